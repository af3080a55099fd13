// SPDX-License-Identifier: MIT
// Contact-force direction and magnitude distributions (gc2d spec 7 item 3): isotropic forces give
// a flat P(alpha) = 1/(2 pi), pair forces count twice and wall forces once, and P(F/<F>) of known
// magnitudes.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/dem_force_stats.hpp"
#include "dem_frames.hpp"

using namespace granulab;
using namespace granulab::analysis;

TEST(DemForceStats, IsotropicForcesGiveFlatDirections) {
    ContactFrame c;
    const int n = 720;
    for (int k = 0; k < n; ++k) {
        const Real angle = (k + 0.25) * 2 * kPi / n;  // never on a bin edge
        test::addPair(c, k, k + 1, {2 * std::cos(angle), 2 * std::sin(angle)});
    }
    const ForceDirections d = forceDirections(c, {72, true});
    EXPECT_EQ(d.forces, 2u * n);
    Real integral = 0;
    for (std::size_t b = 0; b < 72; ++b) {
        EXPECT_EQ(d.count[b], 20u) << "bin " << b;
        EXPECT_NEAR(d.density[b], 1 / (2 * kPi), 1e-12);
        integral += d.density[b] * 2 * kPi / 72;
    }
    EXPECT_NEAR(integral, 1, 1e-12);
    EXPECT_NEAR(d.alpha.front(), -kPi + kPi / 72, 1e-15);
    const Table t = toTable(d);
    EXPECT_EQ(t.name, "force_directions");
    EXPECT_EQ(t.columns[0].name, "alpha");
    EXPECT_EQ(t.columns[0].unit, "rad");
    EXPECT_EQ(t.columns[1].unit, "1/rad");
}

TEST(DemForceStats, PairsCountTwiceWallsOnce) {
    ContactFrame c;
    test::addPair(c, 1, 2, {0, 3});                          // alpha = pi/2 and -pi/2
    test::addContact(c, 1, -1, 0, {0, 0}, {0, -1}, {0, 5});  // wall: +pi/2 once
    test::addContact(c, 2, -1, 1, {0, 0}, {1, 0}, {-1, 0});  // wall: alpha = pi -> first bin
    test::addPair(c, 3, 4, {0, 0});                          // no direction: skipped
    const ForceDirections d = forceDirections(c, {4, true});
    // bins [-pi, -pi/2), [-pi/2, 0), [0, pi/2), [pi/2, pi)
    EXPECT_EQ(d.forces, 4u);
    EXPECT_EQ(d.zeroForces, 1u);
    EXPECT_EQ(d.count[0], 1u);
    EXPECT_EQ(d.count[1], 1u);
    EXPECT_EQ(d.count[2], 0u);
    EXPECT_EQ(d.count[3], 2u);
    const ForceDirections noWalls = forceDirections(c, {4, false});
    EXPECT_EQ(noWalls.forces, 2u);
    EXPECT_EQ(noWalls.count[1], noWalls.count[3]);  // P(alpha) = P(alpha + pi)
    EXPECT_THROW(forceDirections(c, {0, true}), std::invalid_argument);
    const ForceDirections empty = forceDirections(ContactFrame{});
    EXPECT_TRUE(std::isnan(empty.density[0]));
    EXPECT_FALSE(empty.notes.empty());
}

TEST(DemForceStats, MagnitudeDistributionOfKnownForces) {
    ContactFrame c;
    test::addPair(c, 1, 2, {1, 0});
    test::addPair(c, 2, 3, {0, -2});
    test::addPair(c, 3, 4, {1.8, 2.4});                        // |F| = 3
    test::addContact(c, 4, -1, 0, {0, 0}, {0, -1}, {0, 100});  // wall, excluded by default
    ForceMagnitudeParams params;
    params.bins = 10;
    params.maxRatio = 5;  // bins of width 0.5
    const ForceMagnitudes m = forceMagnitudes(c, params);
    EXPECT_DOUBLE_EQ(m.meanForce, 2);
    EXPECT_EQ(m.contacts, 3u);
    for (std::size_t b = 0; b < 10; ++b) {
        const Real expected = (b >= 1 && b <= 3) ? 1 / (3 * 0.5) : 0;  // ratios 0.5, 1, 1.5
        EXPECT_DOUBLE_EQ(m.density[b], expected) << "bin " << b;
    }
    EXPECT_DOUBLE_EQ(m.overflowFraction, 0);
    params.includeWalls = true;
    params.maxRatio = 2;
    const ForceMagnitudes withWalls = forceMagnitudes(c, params);
    EXPECT_DOUBLE_EQ(withWalls.meanForce, 26.5);
    EXPECT_DOUBLE_EQ(withWalls.overflowFraction, 0.25);  // 100/26.5 > 2
    const Table t = toTable(m);
    EXPECT_EQ(t.name, "force_magnitudes");
    EXPECT_EQ(t.columns[0].name, "F/<F>");
    EXPECT_EQ(t.notes[0], "mean_force = 2 N");
    params.maxRatio = 0;
    EXPECT_THROW(forceMagnitudes(c, params), std::invalid_argument);
}
