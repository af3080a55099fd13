// SPDX-License-Identifier: MIT
// The seed's mutual attraction (cfddem spec 5.6, Eq. 3.72): F = G m1 m2 / d^2 along the centre
// line, equal and opposite; the cutoff grid gives exactly the pairs within the cutoff; the contact
// switches (cfddem #FP, #FB) leave overlapping particles and walls without force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support.hpp"
#include "dem/fluid_forces.hpp"

namespace granulab {
namespace {

model::ParticleStore randomStore(std::size_t n, Real side, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> u(0, side), m(0.5, 2.0);
    model::ParticleStore s;
    for (std::size_t k = 0; k < n; ++k)
        s.add(static_cast<ParticleId>(k), {u(rng), u(rng)}, {}, 0, 0, 0.01, m(rng), 1e-4, 0);
    for (std::size_t k = 0; k < n; ++k) s.fx[k] = s.fy[k] = 0;
    return s;
}

TEST(Attraction, TwoBodiesFeelNewtonsLaw) {
    model::ParticleStore s;
    s.add(0, {0, 0}, {}, 0, 0, 0.1, 2.0, 1, 0);
    s.add(1, {3, 4}, {}, 0, 0, 0.1, 5.0, 1, 0);
    s.fx = {0, 0};
    s.fy = {0, 0};
    dem::CellBins scratch;
    dem::addAttraction(s, 6.674e-11, 0, scratch);
    const Real f = 6.674e-11 * 2 * 5 / 25;  // d = 5 m
    EXPECT_NEAR(s.fx[0], f * 0.6, 1e-25);
    EXPECT_NEAR(s.fy[0], f * 0.8, 1e-25);
    EXPECT_EQ(s.fx[1], -s.fx[0]);
    EXPECT_EQ(s.fy[1], -s.fy[0]);
}

TEST(Attraction, CutoffGridSumsExactlyThePairsWithinTheCutoff) {
    const Real cutoff = 0.7;
    model::ParticleStore grid = randomStore(400, 10, 3);
    model::ParticleStore brute = grid;
    dem::CellBins scratch;
    dem::addAttraction(grid, 1.0, cutoff, scratch);
    for (std::size_t i = 0; i < brute.size(); ++i)
        for (std::size_t j = i + 1; j < brute.size(); ++j) {
            const Real dx = brute.x[j] - brute.x[i], dy = brute.y[j] - brute.y[i], d2 = dx * dx + dy * dy;
            if (d2 > cutoff * cutoff) continue;
            const Real f = brute.mass[i] * brute.mass[j] / d2, d = std::sqrt(d2);
            brute.fx[i] += f * dx / d;
            brute.fy[i] += f * dy / d;
            brute.fx[j] -= f * dx / d;
            brute.fy[j] -= f * dy / d;
        }
    Real total = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        EXPECT_NEAR(grid.fx[i], brute.fx[i], 1e-9 * (1 + std::abs(brute.fx[i])));
        EXPECT_NEAR(grid.fy[i], brute.fy[i], 1e-9 * (1 + std::abs(brute.fy[i])));
        total += std::abs(brute.fx[i]);
    }
    EXPECT_GT(total, 1.0);  // pairs within the cutoff exist
}

TEST(Attraction, FarOutlierUsesSparseCellsNotAllPairs) {
    // One particle 1e9 m away: a dense grid of cutoff cells would not fit in memory; the sparse
    // cells give the same forces as the pairs within the cutoff (the outlier feels none).
    model::ParticleStore grid = randomStore(300, 5, 9);
    grid.add(300, {1e9, 1e9}, {}, 0, 0, 0.01, 1.0, 1e-4, 0);
    grid.fx.back() = grid.fy.back() = 0;
    model::ParticleStore dense = grid;
    dense.keep([] {
        std::vector<std::uint32_t> k(300);
        for (std::uint32_t i = 0; i < 300; ++i) k[i] = i;
        return k;
    }());
    dem::CellBins a, b;
    dem::addAttraction(grid, 1.0, 0.5, a);
    dem::addAttraction(dense, 1.0, 0.5, b);
    for (std::size_t i = 0; i < 300; ++i) {
        EXPECT_NEAR(grid.fx[i], dense.fx[i], 1e-9 * (1 + std::abs(dense.fx[i])));
        EXPECT_NEAR(grid.fy[i], dense.fy[i], 1e-9 * (1 + std::abs(dense.fy[i])));
    }
    EXPECT_EQ(grid.fx[300], 0);
}

TEST(Attraction, ContactSwitchesRemoveContactForces) {
    // Two disks flying into each other and into the floor: with particle_contacts and wall_contacts
    // off they pass through, feeling gravity only; with them on they bounce.
    const std::string scene = R"(
[run]
end_time = 0.02
[dem]
dt = 1.0e-5
gravity = [0.0, -9.81]
particle_contacts = false
wall_contacts = false
[[material]]
name = "m"
density = 1.0
[[contact]]
materials = ["*", "*"]
normal = "hooke"
kn = 1000.0
[[particle]]
position = [0.0, 0.011]
velocity = [1.0, -1.0]
radius = 0.01
material = "m"
[[particle]]
position = [0.025, 0.011]
velocity = [-1.0, -1.0]
radius = 0.01
material = "m"
[[wall]]
points = [[-1.0, 0.0], [1.0, 0.0]]
material = "m"
)";
    const auto run = [](const std::string& text) {
        dem::World w = test::makeWorldFromToml(text);
        for (int k = 0; k < 2000; ++k) w.step();
        return w;
    };
    const dem::World off = run(scene);
    for (std::size_t i = 0; i < 2; ++i) {
        const std::size_t id = off.store().id[i];
        EXPECT_EQ(off.store().vx[i], id == 0 ? 1.0 : -1.0);
        EXPECT_NEAR(off.store().vy[i], -1.0 - 9.81 * 0.02, 1e-9);
    }
    const dem::World on = run(test::replaceAll(test::replaceAll(scene, "particle_contacts = false", ""),
                                               "wall_contacts = false", ""));
    for (std::size_t i = 0; i < 2; ++i) EXPECT_GT(on.store().vy[i], 0);  // bounced off the floor
}

}  // namespace
}  // namespace granulab
