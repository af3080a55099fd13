// SPDX-License-Identifier: MIT
// Oracle test: the cell grid finds exactly the brute-force pair sets (particle pairs and
// particle-wall pairs) on random polydisperse scenes, including radius ratios of 20 and
// far-away stragglers.
#include <gtest/gtest.h>

#include "core/rng.hpp"
#include "dem/broad_phase.hpp"

using namespace granulab;

namespace {
model::ParticleStore randomScene(std::uint64_t seed, std::size_t n, Real rmin, Real rmax, Real box) {
    CounterRng rng(seed, 0);
    model::ParticleStore s;
    for (std::size_t k = 0; k < n; ++k) {
        const Real r = rng.uniform(rmin, rmax);
        s.add(static_cast<ParticleId>(k), {rng.uniform(0, box), rng.uniform(0, box)}, {}, 0, 0, r, 1, 1, 0);
    }
    return s;
}
}  // namespace

TEST(BroadPhase, CellGridMatchesBruteForceOnPolydisperseScenes) {
    struct Case {
        std::size_t n;
        Real rmin, rmax, box, margin;
    };
    const Case cases[] = {{500, 0.5, 0.5, 30, 0.1},
                          {800, 0.05, 1.0, 40, 0.05},
                          {300, 0.1, 2.0, 20, 0.0},
                          {1000, 0.2, 0.3, 15, 0.2}};
    std::uint64_t seed = 1;
    for (const auto& c : cases) {
        model::ParticleStore s = randomScene(seed++, c.n, c.rmin, c.rmax, c.box);
        s.add(static_cast<ParticleId>(s.size()), {1e4, -3e3}, {}, 0, 0, 0.3, 1, 1, 0);  // straggler
        model::WallSet walls;
        walls.addPolyline("box", {{0, 0}, {c.box, 0}, {c.box, c.box}, {0, c.box}}, true, 0, {});
        walls.addPolyline("diag", {{-1, 2}, {c.box * 0.7, c.box * 0.4}}, false, 0, {});
        std::vector<std::uint64_t> ref, got, refW, gotW;
        dem::BruteForce brute;
        dem::CellGrid grid;
        brute.findPairs(s, c.margin, ref);
        grid.findPairs(s, c.margin, got);
        brute.findWallPairs(s, walls, c.margin, refW);
        grid.findWallPairs(s, walls, c.margin, gotW);
        EXPECT_FALSE(ref.empty());
        EXPECT_EQ(ref, got) << "n " << c.n;
        EXPECT_FALSE(refW.empty());
        EXPECT_EQ(refW, gotW) << "n " << c.n;
    }
}

TEST(BroadPhase, SortAndSweepMatchesBruteForceWhileParticlesMoveAndArrive) {
    model::ParticleStore s = randomScene(7, 600, 0.05, 0.8, 30);
    dem::SortAndSweep sap;
    dem::BruteForce brute;
    CounterRng rng(99, 1);
    std::vector<std::uint64_t> ref, got;
    for (int round = 0; round < 30; ++round) {
        const Real margin = 0.1;
        sap.findPairs(s, margin, got);
        brute.findPairs(s, margin, ref);
        ASSERT_EQ(ref, got) << "round " << round;
        // Move every particle a little (some far), and now and then add new particles.
        for (std::size_t i = 0; i < s.size(); ++i) {
            const Real step = (i % 50 == 0) ? 3.0 : 0.15;
            s.x[i] += rng.uniform(-step, step);
            s.y[i] += rng.uniform(-step, step);
        }
        if (round % 5 == 4)
            for (int k = 0; k < 20; ++k)
                s.add(static_cast<ParticleId>(s.size()), {rng.uniform(0, 30), rng.uniform(0, 30)}, {}, 0, 0,
                      rng.uniform(0.05, 0.8), 1, 1, 0);
    }
    EXPECT_GT(ref.size(), 100u);
}

TEST(BroadPhase, SortAndSweepHandlesExactlyTouchingBoxes) {
    // Square lattice whose boxes touch exactly (spacing = 2 r + margin): ties in both lists.
    model::ParticleStore s;
    const Real r = 0.5, margin = 0.25, a = 2 * r + margin;
    for (int iy = 0; iy < 12; ++iy)
        for (int ix = 0; ix < 12; ++ix)
            s.add(static_cast<ParticleId>(s.size()), {ix * a, iy * a}, {}, 0, 0, r, 1, 1, 0);
    dem::SortAndSweep sap;
    dem::BruteForce brute;
    CounterRng rng(5, 2);
    std::vector<std::uint64_t> ref, got;
    for (int round = 0; round < 40; ++round) {
        sap.findPairs(s, margin, got);
        brute.findPairs(s, margin, ref);
        ASSERT_EQ(ref, got) << "round " << round;
        // Nudge a few particles along one axis only, by amounts that keep some ties exact.
        for (int k = 0; k < 10; ++k) {
            const auto i = static_cast<std::size_t>(rng.uniform(0, static_cast<Real>(s.size())));
            (round % 2 ? s.x : s.y)[i] += (rng.uniform() < 0.5 ? -1 : 1) * 0.0625;
        }
    }
}

// Issue 11, case 1: a particle far out, where its box is narrower than the coordinate step of
// double precision (begin == end), sorts its end before its begin; the first sweep ended it
// without having begun it and crashed. It overlaps nothing; the others are still found.
TEST(BroadPhase, SortAndSweepToleratesBoxesBelowTheCoordinateResolution) {
    model::ParticleStore s;
    s.add(0, {1e14, 0.05}, {}, 0, 0, 0.002, 1, 1, 0);
    s.add(1, {0.0, 0.0}, {}, 0, 0, 0.01, 1, 1, 0);
    s.add(2, {0.015, 0.0}, {}, 0, 0, 0.01, 1, 1, 0);
    dem::SortAndSweep sweep;
    std::vector<std::uint64_t> pairs;
    sweep.findPairs(s, 0.0, pairs);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0], dem::pairKey(1, 2));
    s.x[0] += 1e-3;  // the incremental update too
    sweep.findPairs(s, 0.0, pairs);
    EXPECT_EQ(pairs.size(), 1u);
}
