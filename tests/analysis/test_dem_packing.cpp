// SPDX-License-Identifier: MIT
// Local packing fraction on test areas (gc2d spec section 7 item 6, Eq. 2.44/2.45): exact disk and
// polygon clipping, the hexagonal-lattice bulk value, and the free-surface correction.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "analysis/convex_hull.hpp"
#include "analysis/dem_packing.hpp"
#include "analysis/dem_stress.hpp"
#include "dem_lattice.hpp"

namespace granulab {
namespace {

const Real kHexFraction = kPi / (2 * std::sqrt(3.0));

/// Disk n rectangle by midpoint integration of the chord length over x (2e5 strips; the square-root
/// ends of the chord limit it to ~1e-8).
Real diskRectNumeric(Vec2 c, Real r, Vec2 lo, Vec2 hi) {
    const Real a = std::max(lo.x, c.x - r), b = std::min(hi.x, c.x + r);
    if (b <= a) return 0;
    const int n = 200000;
    const Real dx = (b - a) / n;
    Real sum = 0;
    for (int i = 0; i < n; ++i) {
        const Real x = a + (i + 0.5) * dx, s = std::sqrt(std::max<Real>(0, r * r - (x - c.x) * (x - c.x)));
        sum += std::max<Real>(0, std::min(hi.y, c.y + s) - std::max(lo.y, c.y - s));
    }
    return sum * dx;
}

TEST(DemPacking, DiskRectangleIntersectionIsExact) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> u(-1.5, 1.5), len(0.1, 2.5);
    for (int t = 0; t < 200; ++t) {
        const Vec2 lo{u(rng), u(rng)}, hi = lo + Vec2{len(rng), len(rng)};
        const Real exact = analysis::diskInRectangle({0, 0}, 1, lo, hi, 16, nullptr);
        EXPECT_NEAR(exact, diskRectNumeric({0, 0}, 1, lo, hi), 1e-7) << "case " << t;
    }
    EXPECT_NEAR(analysis::diskInRectangle({0, 0}, 1, {-2, -2}, {2, 2}, 16, nullptr), kPi, 1e-14);
    EXPECT_NEAR(analysis::diskInRectangle({0, 0}, 1, {-0.5, -0.5}, {0.5, 0.5}, 16, nullptr), 1, 1e-14);
    EXPECT_NEAR(analysis::diskInRectangle({0, 0}, 1, {0, 0}, {2, 2}, 16, nullptr), kPi / 4, 1e-14);
}

TEST(DemPacking, PolygonClippingAndHull) {
    const std::vector<Vec2> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    std::vector<Vec2> pts;
    EXPECT_NEAR(analysis::polygonInRectangle(square, {1, 1}, {3, 3}, &pts), 1, 1e-15);
    EXPECT_NEAR(analysis::convexHullArea(pts), 1, 1e-15);
    EXPECT_NEAR(analysis::polygonInRectangle(square, {5, 5}, {6, 6}, nullptr), 0, 1e-15);
    std::vector<Vec2> tri{{0, 0}, {1, 0}, {0, 1}, {0.2, 0.2}, {0.1, 0.1}};
    EXPECT_NEAR(analysis::convexHullArea(tri), 0.5, 1e-15);
}

TEST(DemPacking, HexagonalLatticeBulkValue) {
    const Real r = 1e-3;
    const analysis::GrainFrame f = test::hexLattice(60, 70, r);
    // Areas of 8 x 2 lattice periods (16 r by 4 sqrt(3) r), at arbitrary offsets in the bulk.
    analysis::TestAreaGrid g{0.0123, 0.0171, 16 * r, 4 * std::sqrt(3.0) * r, 0.0071, 0.0093, 8, 8};
    const analysis::PackingGrid p = analysis::packingGrid(f, g);
    for (std::size_t k = 0; k < g.count(); ++k) {
        EXPECT_NEAR(p.simple[k], kHexFraction, 1e-3) << "area " << k;
        // A_k misses the void corners of A not covered by a grain (up to ~0.1 %).
        EXPECT_NEAR(p.improved[k], kHexFraction, 2e-3) << "area " << k;
        EXPECT_GT(p.grains[k], 30u);
    }
    const analysis::Table t = analysis::packingTable(p);
    EXPECT_EQ(t.name, "packing_fraction");
    ASSERT_EQ(t.columns.size(), 6u);
    EXPECT_EQ(t.columns[3].name, "rho_improved");
    EXPECT_EQ(t.rows(), g.count());
}

TEST(DemPacking, PolygonLatticeBulkValue) {
    // Regular 12-gons (circumradius r) on the touching-disk hexagonal lattice.
    const Real r = 1e-3;
    analysis::GrainFrame f = test::hexLattice(40, 46, r);
    const int corners = 12;
    f.cornerStart.assign(1, 0);
    for (std::size_t i = 0; i < f.size(); ++i) {
        for (int c = 0; c < corners; ++c) {
            const Real t = 2 * kPi * c / corners + 0.1;
            f.corners.push_back({f.x[i] + r * std::cos(t), f.y[i] + r * std::sin(t)});
        }
        f.cornerStart.push_back(f.corners.size());
    }
    const Real polygonArea = 0.5 * corners * r * r * std::sin(2 * kPi / corners);
    const Real expected = polygonArea / (2 * std::sqrt(3.0) * r * r);
    analysis::TestAreaGrid g{0.0101, 0.0113, 16 * r, 4 * std::sqrt(3.0) * r, 0.0077, 0.0083, 6, 6};
    const analysis::PackingGrid p = analysis::packingGrid(f, g);
    for (std::size_t k = 0; k < g.count(); ++k) {
        EXPECT_NEAR(p.simple[k], expected, 1e-12) << "area " << k;
        EXPECT_NEAR(p.improved[k], expected, 2e-3) << "area " << k;
    }
}

TEST(DemPacking, FreeSurfaceCorrection) {
    // 20 rows: the surface (top of row 19) at y = 19 sqrt(3) r + r; the test areas reach 6 rows
    // above it, so rho' is biased low while A_k ends at the surface.
    const Real r = 1e-3, row = std::sqrt(3.0) * r;
    const analysis::GrainFrame f = test::hexLattice(60, 20, r);
    const Real top = 19 * row + r;
    analysis::TestAreaGrid g{0.02, top - 14 * row, 20 * r, 20 * row, 0.004, 1, 5, 1};
    const analysis::PackingGrid p = analysis::packingGrid(f, g);
    for (std::size_t k = 0; k < g.count(); ++k) {
        EXPECT_LT(p.simple[k], 0.75 * kHexFraction) << "area " << k;
        EXPECT_NEAR(p.improved[k] / kHexFraction, 1, 0.03) << "area " << k;
        EXPECT_LT(p.hullArea[k], 0.75 * g.area());
    }
}

TEST(DemPacking, RejectsBadParameters) {
    const analysis::GrainFrame f = test::hexLattice(3, 3, 1e-3);
    analysis::TestAreaGrid g{0, 0, 0, 1, 1, 1, 1, 1};
    EXPECT_THROW(analysis::packingGrid(f, g), std::invalid_argument);
    g.w = 1;
    EXPECT_THROW(analysis::packingGrid(f, g, {2}), std::invalid_argument);
    EXPECT_THROW(analysis::coveringGrid(0, 0, -1, 1, 1, 1, 1, 1), std::invalid_argument);
    const analysis::TestAreaGrid c = analysis::coveringGrid(0, 0, 1, 0.5, 0.2, 0.1, 0.1, 0.05);
    EXPECT_EQ(c.nx, 9u);
    EXPECT_EQ(c.ny, 9u);
    // Empty area: NaN improved value plus a note.
    const analysis::PackingGrid p =
        analysis::packingGrid(f, analysis::TestAreaGrid{10, 10, 1, 1, 1, 1, 1, 1});
    EXPECT_TRUE(std::isnan(p.improved[0]));
    EXPECT_EQ(p.notes.size(), 1u);
}

TEST(DemAnalysisPerformance, HundredThousandGrainsUnderTwoSeconds) {
    // 1e5 disks on a jittered hexagonal lattice, 3 lattice contacts each; areas of ~150 grains at
    // half-size steps (each grain in ~4 areas). Stress and packing grids together.
    const Real r = 1e-3;
    const std::size_t nx = 316, ny = 317;
    analysis::GrainFrame f = test::hexLattice(nx, ny, r);
    std::mt19937 rng(9);
    std::normal_distribution<Real> jitter(0, 0.01 * r), force(1, 0.3);
    for (std::size_t i = 0; i < f.size(); ++i) {
        f.x[i] += jitter(rng);
        f.y[i] += jitter(rng);
    }
    analysis::ContactFrame c;
    const auto link = [&](std::size_t a, std::size_t b) {
        const Vec2 pa{f.x[a], f.y[a]}, pb{f.x[b], f.y[b]}, n = (pb - pa) / norm(pb - pa);
        test::addContact(c, static_cast<std::int64_t>(a), static_cast<std::int64_t>(b), -1, 0.5 * (pa + pb),
                         n, -force(rng) * n);
    };
    for (std::size_t j = 0; j + 1 < ny; ++j)
        for (std::size_t i = 0; i + 1 < nx; ++i) {
            const std::size_t k = j * nx + i;
            link(k, k + 1);
            link(k, k + nx);
            link(k + 1, k + nx);
        }
    const analysis::TestAreaGrid g =
        analysis::coveringGrid(0, 0, 2 * r * nx, std::sqrt(3.0) * r * ny, 24 * r, 22 * r, 12 * r, 11 * r);
    const auto t0 = std::chrono::steady_clock::now();
    const analysis::StressGrid s = analysis::stressGrid(f, c, g);
    const auto t1 = std::chrono::steady_clock::now();
    const analysis::PackingGrid p = analysis::packingGrid(f, g);
    const auto t2 = std::chrono::steady_clock::now();
    const Real stressSeconds = std::chrono::duration<Real>(t1 - t0).count();
    const Real packingSeconds = std::chrono::duration<Real>(t2 - t1).count();
    RecordProperty("stress_ms", static_cast<int>(1000 * stressSeconds));
    RecordProperty("packing_ms", static_cast<int>(1000 * packingSeconds));
    std::printf("1e5 grains, %zu areas: stress %.3f s, packing %.3f s\n", g.count(), stressSeconds,
                packingSeconds);
    EXPECT_GT(s.grains[g.index(10, 10)], 100u);
    EXPECT_NEAR(p.simple[g.index(10, 10)], kHexFraction, 0.02);
#ifdef NDEBUG
    // Target (issue): well under 2 s on an idle core. The bound here only catches an
    // O(N x areas) regression (that would take minutes) on a shared, loaded machine.
    EXPECT_LT(stressSeconds + packingSeconds, 10.0);
#endif
}

}  // namespace
}  // namespace granulab
