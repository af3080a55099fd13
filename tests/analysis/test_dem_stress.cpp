// SPDX-License-Identifier: MIT
// Coarse-grained stress on test areas (gc2d spec section 7 items 7-8, Eq. 2.52) on a static
// configuration in exact force balance built by hand: a square stack of disks under gravity
// between two side walls on a floor, with known vertical and horizontal contact forces.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "analysis/dem_stress.hpp"
#include "dem_lattice.hpp"

namespace granulab {
namespace {

constexpr Real kR = 1e-3;  // [m] disk radius
constexpr Real kW = 2e-3;  // [N] weight m g of one disk (per metre of depth)
constexpr std::size_t kNx = 20, kNy = 30;

/// Horizontal contact force [N] in row j: a depth-dependent lateral push 0.4 x the vertical load
/// carried by a grain of the row, plus 1e-3 N, so the wall load varies with height.
Real lateral(std::size_t j) {
    return 0.4 * kW * static_cast<Real>(kNy - j) + 1e-3;
}

/// Square stack: grain (i, j) at ((2i + 1) r, (2j + 1) r). Force balance of every grain: vertical
/// contact (i, j)-(i, j+1) at y = 2(j+1) r pushes the lower grain down with the weight of the
/// column above; floor (wall 0) pushes each bottom grain up with the column's weight; horizontal
/// contacts and the side walls (1 left at x = 0, 2 right at x = 2 nx r) carry lateral(j).
/// `rotate` turns the whole configuration by `angle` about `pivot`.
void squareStack(analysis::GrainFrame& f, analysis::ContactFrame& c, Real angle = 0, Vec2 pivot = {}) {
    const Real cs = std::cos(angle), sn = std::sin(angle);
    const auto rot = [&](Vec2 v) { return Vec2{cs * v.x - sn * v.y, sn * v.x + cs * v.y}; };
    const auto at = [&](Vec2 p) { return pivot + rot(p - pivot); };
    const auto id = [](std::size_t i, std::size_t j) { return static_cast<std::int64_t>(j * kNx + i); };
    for (std::size_t j = 0; j < kNy; ++j)
        for (std::size_t i = 0; i < kNx; ++i) {
            const Vec2 p = at({(2 * static_cast<Real>(i) + 1) * kR, (2 * static_cast<Real>(j) + 1) * kR});
            test::addDisk(f, p.x, p.y, kR, kW / 9.81);
        }
    for (std::size_t j = 0; j < kNy; ++j)
        for (std::size_t i = 0; i < kNx; ++i) {
            const Real x = (2 * static_cast<Real>(i) + 1) * kR, y = (2 * static_cast<Real>(j) + 1) * kR;
            const Real above = kW * static_cast<Real>(kNy - 1 - j);  // weight of the grains above
            if (j + 1 < kNy)
                test::addContact(c, id(i, j), id(i, j + 1), -1, at({x, y + kR}), rot({0, 1}),
                                 rot({0, -above}));
            if (j == 0) test::addContact(c, id(i, j), -1, 0, at({x, 0}), rot({0, -1}), rot({0, above + kW}));
            if (i + 1 < kNx)
                test::addContact(c, id(i, j), id(i + 1, j), -1, at({x + kR, y}), rot({1, 0}),
                                 rot({-lateral(j), 0}));
            if (i == 0) test::addContact(c, id(i, j), -1, 1, at({0, y}), rot({-1, 0}), rot({lateral(j), 0}));
            if (i + 1 == kNx)
                test::addContact(c, id(i, j), -1, 2, at({x + kR, y}), rot({1, 0}), rot({-lateral(j), 0}));
        }
}

TEST(DemStress, HorizontalCutCarriesTheWeightAbove) {
    analysis::GrainFrame f;
    analysis::ContactFrame c;
    squareStack(f, c);
    // Areas of 10 columns x 12 rows (120 grains), edges on contact lines; rows overlap by half.
    const analysis::TestAreaGrid g{0, 0, 20 * kR, 24 * kR, 20 * kR, 12 * kR, 2, 4};
    const analysis::StressGrid s = analysis::stressGrid(f, c, g);
    // The top row of areas holds the free surface, where no contact closes the force hull: skipped.
    for (std::size_t j = 0; j + 1 < g.ny; ++j) {
        Real integral = 0;  // int sigma_zz dx over the cut through the areas' centre line [N]
        for (std::size_t i = 0; i < g.nx; ++i) integral += s.sigmaZz[g.index(i, j)] * g.w;
        const Real cut = g.centre(g.index(0, j)).y;
        const auto rowsAbove = static_cast<Real>(kNy - static_cast<std::size_t>(std::lround(cut / (2 * kR))));
        const Real weight = kW * static_cast<Real>(kNx) * rowsAbove;
        EXPECT_NEAR(integral / weight, 1, 0.01) << "row " << j;
        for (std::size_t i = 0; i < g.nx; ++i) {
            EXPECT_EQ(s.grains[g.index(i, j)], 120u);
            EXPECT_NEAR(s.sigmaXz[g.index(i, j)], 0, 1e-12);
        }
    }
    EXPECT_TRUE(s.notes.empty());  // 120 grains per area: no sparse-area note
}

TEST(DemStress, StressAtTheWallIsTheWallLoad) {
    analysis::GrainFrame f;
    analysis::ContactFrame c;
    squareStack(f, c);
    const analysis::TestAreaGrid g{0, 0, 20 * kR, 24 * kR, 20 * kR, 12 * kR, 2, 4};
    const analysis::StressGrid s = analysis::stressGrid(f, c, g);
    for (std::size_t j = 0; j + 1 < g.ny; ++j) {  // below the free-surface row
        // Wall force per length over the area's rows: sum lateral(row) / h [N/m].
        const auto firstRow = static_cast<std::size_t>(std::lround(g.bottom(j) / (2 * kR)));
        Real load = 0;
        for (std::size_t row = firstRow; row < firstRow + 12; ++row) load += lateral(row);
        load /= g.h;
        EXPECT_NEAR(s.sigmaXx[g.index(0, j)] / load, 1, 0.01) << "left, row " << j;
        EXPECT_NEAR(s.sigmaXx[g.index(g.nx - 1, j)] / load, 1, 0.01) << "right, row " << j;
        // The force hull misses a triangle r^2/2 at each corner (wall contacts sit at row centres,
        // vertical ones at column centres): V = w h - 2 r^2, a 0.4 % effect at 120 grains.
        EXPECT_NEAR(s.hullArea[g.index(0, j)], g.area() - 2 * kR * kR, 1e-12 * g.area());
    }
    const analysis::Table t = analysis::stressTable(s);
    EXPECT_EQ(t.name, "stress");
    ASSERT_EQ(t.columns.size(), 11u);
    EXPECT_EQ(t.columns[2].name, "sigma_xx");
    EXPECT_EQ(t.columns[2].unit, "N/m");
    EXPECT_EQ(t.columns[7].name, "psi");
    EXPECT_EQ(t.rows(), g.count());
}

TEST(DemStress, PrincipalAxesRotateWithTheConfiguration) {
    const Vec2 centre{kNx * kR, kNy * kR};
    const analysis::TestAreaGrid big{centre.x - 0.1, centre.y - 0.1, 0.2, 0.2, 0.2, 0.2, 1, 1};
    analysis::GrainFrame f0, f1;
    analysis::ContactFrame c0, c1;
    squareStack(f0, c0);
    const Real angle = kPi / 6;
    squareStack(f1, c1, angle, centre);
    const analysis::StressGrid s0 = analysis::stressGrid(f0, c0, big), s1 = analysis::stressGrid(f1, c1, big);
    ASSERT_GT(s0.sigmaZz[0], s0.sigmaXx[0]);
    EXPECT_NEAR(s0.psi[0], 0, 1e-9);
    EXPECT_NEAR(s1.major[0] / s0.major[0], 1, 1e-12);
    EXPECT_NEAR(s1.minor[0] / s0.minor[0], 1, 1e-12);
    EXPECT_NEAR(s1.psi[0], -30, 1e-9);  // the vertical major axis turned 30 deg counter-clockwise
    EXPECT_EQ(s0.grains[0], kNx * kNy);
}

TEST(DemStress, PrincipalStressConventions) {
    EXPECT_NEAR(analysis::principalStress(1, 3, 0).psi, 0, 1e-12);
    EXPECT_NEAR(analysis::principalStress(3, 1, 0).psi, 90, 1e-12);
    const analysis::PrincipalStress p = analysis::principalStress(2, 2, 1);
    EXPECT_NEAR(p.major, 3, 1e-12);
    EXPECT_NEAR(p.minor, 1, 1e-12);
    EXPECT_NEAR(p.psi, 45, 1e-12);
    EXPECT_NEAR(analysis::principalStress(2, 2, -1).psi, -45, 1e-12);
}

TEST(DemStress, RejectsBadInput) {
    analysis::GrainFrame f;
    analysis::ContactFrame c;
    squareStack(f, c);
    EXPECT_THROW(analysis::stressGrid(f, c, analysis::TestAreaGrid{0, 0, -1, 1, 1, 1, 1, 1}),
                 std::invalid_argument);
    c.b[0] = 999999;
    EXPECT_THROW(analysis::stressGrid(f, c, analysis::TestAreaGrid{}), std::invalid_argument);
    // An area without forces: NaN and a note.
    analysis::ContactFrame none;
    const analysis::StressGrid s =
        analysis::stressGrid(f, none, analysis::TestAreaGrid{0, 0, 0.01, 0.01, 1, 1, 1, 1});
    EXPECT_TRUE(std::isnan(s.sigmaXx[0]));
    EXPECT_FALSE(s.notes.empty());
}

}  // namespace
}  // namespace granulab
