// SPDX-License-Identifier: MIT
// Wall and floor pressure (gc2d spec 7 items 1-2, Eqs. 2.36-2.40): exact sums of hand-built
// contacts, a uniform load, inclusive window edges, the moving average, the thesis normalisation
// and the pile scale measured from grains.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/dem_pressure.hpp"
#include "dem_frames.hpp"

using namespace granulab;
using namespace granulab::analysis;

namespace {

bool hasNote(const std::vector<std::string>& notes, const std::string& part) {
    return std::any_of(notes.begin(), notes.end(),
                       [&](const std::string& n) { return n.find(part) != std::string::npos; });
}

const Column& column(const Table& t, const std::string& name) {
    for (const Column& c : t.columns)
        if (c.name == name) return c;
    throw std::out_of_range("no column " + name);
}

}  // namespace

TEST(DemPressure, FloorWithThreeContactsHasExactPressure) {
    WallSegments walls;
    test::addSegment(walls, 0, {0, 0}, {2, 0});  // floor, l = 2 m
    test::addSegment(walls, 1, {2, 0}, {2, 5});  // side wall, not selected
    ContactFrame c;
    // Forces on the grains [N]; n points from the grain down into the floor.
    test::addContact(c, 1, -1, 0, {0.3, 0}, {0, -1}, {1, 5});
    test::addContact(c, 2, -1, 0, {0.9, 0}, {0, -1}, {-0.5, 3});
    test::addContact(c, 3, -1, 0, {1.7, 0}, {0, -1}, {0, 2});
    test::addContact(c, 3, -1, 1, {2, 0.2}, {1, 0}, {-7, 0});    // side wall
    test::addContact(c, 3, 4, -1, {1.7, 0.4}, {0, 1}, {0, -9});  // grain pair
    const WallPressure p = wallPressure(c, walls, {{0}});
    EXPECT_EQ(p.contacts, 3u);
    EXPECT_DOUBLE_EQ(p.length, 2);
    EXPECT_DOUBLE_EQ(p.force.x, -0.5);
    EXPECT_DOUBLE_EQ(p.force.y, -10);
    EXPECT_DOUBLE_EQ(p.forcePerLength.y, -5);
    EXPECT_TRUE(p.straight);
    EXPECT_DOUBLE_EQ(p.normal.x, 0);
    EXPECT_DOUBLE_EQ(p.normal.y, 1);
    EXPECT_DOUBLE_EQ(p.pressure, 5);        // gc2d Eq. 2.36: (5 + 3 + 2) N / 2 m
    EXPECT_DOUBLE_EQ(p.normalPressure, 5);  // fn = fy here
    const Table t = toTable(p);
    EXPECT_EQ(t.name, "wall_mean_pressure");
    EXPECT_EQ(t.rows(), 1u);
    EXPECT_DOUBLE_EQ(column(t, "p").values[0], 5);
    EXPECT_EQ(column(t, "p").unit, "N/m");
    EXPECT_DOUBLE_EQ(column(t, "Fy").values[0], -10);
}

TEST(DemPressure, SideWallNormalPointsTowardTheGrains) {
    WallSegments walls;
    test::addSegment(walls, 2, {1, 0}, {1, 1});
    test::addSegment(walls, 2, {1, 1}, {1, 4});  // collinear second segment: l = 4 m
    ContactFrame c;
    test::addContact(c, 1, -1, 2, {1, 0.5}, {1, 0}, {-2, 0.5});
    test::addContact(c, 2, -1, 2, {1, 3.0}, {1, 0}, {-6, -0.5});
    const WallPressure p = wallPressure(c, walls, {{2}});
    EXPECT_DOUBLE_EQ(p.length, 4);
    EXPECT_DOUBLE_EQ(p.normal.x, -1);
    EXPECT_DOUBLE_EQ(p.pressure, 2);  // gc2d Eq. 2.37: (2 + 6)/4
    EXPECT_DOUBLE_EQ(p.force.x, 8);
    EXPECT_DOUBLE_EQ(p.force.y, 0);
}

TEST(DemPressure, BentWallReportsComponentsOnly) {
    WallSegments walls;
    test::addSegment(walls, 0, {-1, 1}, {0, 0});
    test::addSegment(walls, 0, {0, 0}, {1, 1});  // a V of length 2 sqrt 2
    ContactFrame c;
    const Real s = std::sqrt(0.5);
    test::addContact(c, 1, -1, 0, {-0.5, 0.5}, {-s, -s}, {3 * s, 3 * s});  // fn = 3
    test::addContact(c, 2, -1, 0, {0.5, 0.5}, {s, -s}, {-s, s});           // fn = 1
    const WallPressure p = wallPressure(c, walls, {{0}});
    EXPECT_FALSE(p.straight);
    EXPECT_TRUE(std::isnan(p.pressure));
    EXPECT_NEAR(p.normalPressure, 4 / (2 * std::sqrt(2.0)), 1e-14);
    EXPECT_NEAR(p.forcePerLength.y, -4 * s / (2 * std::sqrt(2.0)), 1e-14);
    EXPECT_TRUE(hasNote(toTable(p).notes, "bent"));
}

TEST(DemPressure, RejectsMissingWalls) {
    WallSegments walls;
    test::addSegment(walls, 0, {0, 0}, {1, 0});
    ContactFrame c;
    EXPECT_THROW(wallPressure(c, walls, {}), std::invalid_argument);
    EXPECT_THROW(wallPressure(c, walls, {{3}}), std::invalid_argument);
    WallSegments degenerate;
    test::addSegment(degenerate, 0, {1, 1}, {1, 1});
    EXPECT_THROW(wallPressure(c, degenerate, {{0}}), std::invalid_argument);
}

namespace {

/// Floor [0, 10] m with 100 contacts at x = 0.05 + 0.1 k carrying q * 0.1 m each (load q [N/m]).
void uniformFloor(Real q, WallSegments& walls, ContactFrame& c) {
    test::addSegment(walls, 0, {0, 0}, {10, 0});
    for (int k = 0; k < 100; ++k)
        test::addContact(c, k, -1, 0, {0.05 + 0.1 * k, 0}, {0, -1}, {0.01 * k, q * 0.1});
}

}  // namespace

TEST(DemPressure, UniformLoadGivesLoadPerLength) {
    WallSegments walls;
    ContactFrame c;
    uniformFloor(3, walls, c);
    PressureProfileParams params;
    params.walls = {0};
    params.halfWidth = 0.5;
    params.step = 0.1;
    params.from = 1;
    params.to = 9;
    const PressureProfile p = pressureProfile(c, walls, params);
    ASSERT_EQ(p.x.size(), 81u);
    for (std::size_t w = 0; w < p.x.size(); ++w) {
        EXPECT_EQ(p.contacts[w], 10u) << "x " << p.x[w];
        EXPECT_NEAR(p.p[w], 3, 1e-12);
        EXPECT_NEAR(p.pAverage[w], 3, 1e-12);
    }
    EXPECT_EQ(p.sparseWindows, 0u);
    EXPECT_TRUE(p.notes.empty());
    params.minContacts = 11;
    const PressureProfile sparse = pressureProfile(c, walls, params);
    EXPECT_EQ(sparse.sparseWindows, 81u);
    const Table t = toTable(sparse);
    EXPECT_EQ(t.name, "floor_pressure");
    EXPECT_TRUE(hasNote(t.notes, "81 of 81 windows hold fewer than 11 contacts"));
    EXPECT_EQ(t.columns.size(), 4u);
    EXPECT_EQ(column(t, "p_avg").unit, "N/m");
}

TEST(DemPressure, WindowEdgesAreInclusiveAndTheAverageIsCentred) {
    WallSegments walls;
    test::addSegment(walls, 0, {0, 0}, {8, 0});
    ContactFrame c;
    // Non-overlapping windows of width 1 centred at 0.5 + w; loads 1, 2, 4, 8 N, one at each edge.
    test::addContact(c, 0, -1, 0, {0.0, 0}, {0, -1}, {0, 1});
    test::addContact(c, 1, -1, 0, {2.0, 0}, {0, -1}, {0, 2});
    test::addContact(c, 2, -1, 0, {2.25, 0}, {0, -1}, {0, 4});
    test::addContact(c, 3, -1, 0, {3.5, 0}, {0, -1}, {0, 8});
    PressureProfileParams params;
    params.walls = {0};
    params.halfWidth = 0.5;
    params.step = 1;
    params.from = 0.5;
    params.to = 3.5;
    params.movingAverage = 3;
    const PressureProfile p = pressureProfile(c, walls, params);
    ASSERT_EQ(p.p.size(), 4u);
    // x = 2 is on the edge of windows 1 and 2 (x - b <= x_i <= x + b): counted in both.
    EXPECT_EQ(p.contacts[0], 1u);
    EXPECT_EQ(p.contacts[1], 1u);
    EXPECT_EQ(p.contacts[2], 2u);
    EXPECT_EQ(p.contacts[3], 1u);
    EXPECT_DOUBLE_EQ(p.p[0], 1);
    EXPECT_DOUBLE_EQ(p.p[1], 2);
    EXPECT_DOUBLE_EQ(p.p[2], 6);
    EXPECT_DOUBLE_EQ(p.p[3], 8);
    EXPECT_DOUBLE_EQ(p.pAverage[0], 1.5);  // ends: the windows that exist
    EXPECT_DOUBLE_EQ(p.pAverage[1], 3);
    EXPECT_DOUBLE_EQ(p.pAverage[2], 16.0 / 3);
    EXPECT_DOUBLE_EQ(p.pAverage[3], 7);
    EXPECT_EQ(p.sparseWindows, 4u);
}

TEST(DemPressure, ThesisNormalisation) {
    WallSegments walls;
    ContactFrame c;
    uniformFloor(3, walls, c);
    PressureProfileParams params;
    params.walls = {0};
    params.halfWidth = 0.5;
    params.step = 1;
    params.from = 2;
    params.to = 6;
    params.scale = PileScale{2, 1.5, 0.5, 2, 6};  // rho g h = 1.5 N/m, d = 4 m
    const PressureProfile p = pressureProfile(c, walls, params);
    ASSERT_EQ(p.xOverD.size(), 5u);
    for (std::size_t w = 0; w < 5; ++w) {
        EXPECT_DOUBLE_EQ(p.xOverD[w], 0.25 * static_cast<Real>(w));
        EXPECT_NEAR(p.pOverRhoGH[w], 2, 1e-12);
    }
    const Table t = toTable(p, "wall_pressure");
    EXPECT_EQ(t.name, "wall_pressure");
    EXPECT_EQ(column(t, "x/d").unit, "1");
    EXPECT_NEAR(column(t, "p/(rho g h)").values[1], 2, 1e-12);
    params.scale = PileScale{2, 1.5, 0.5, 6, 2};
    EXPECT_THROW(pressureProfile(c, walls, params), std::invalid_argument);
}

TEST(DemPressure, ProfileRejectsNonsense) {
    WallSegments walls;
    ContactFrame c;
    uniformFloor(1, walls, c);
    test::addSegment(walls, 1, {0, 0}, {0, 1});
    PressureProfileParams params;
    params.walls = {0};
    params.halfWidth = 0.5;
    params.step = 0.5;
    EXPECT_NO_THROW(pressureProfile(c, walls, params));
    for (auto bad : {std::pair{-0.5, 0.5}, std::pair{0.5, 0.0}}) {
        PressureProfileParams q = params;
        q.halfWidth = bad.first;
        q.step = bad.second;
        EXPECT_THROW(pressureProfile(c, walls, q), std::invalid_argument);
    }
    PressureProfileParams even = params;
    even.movingAverage = 4;
    EXPECT_THROW(pressureProfile(c, walls, even), std::invalid_argument);
    PressureProfileParams bent = params;
    bent.walls = {0, 1};
    EXPECT_THROW(pressureProfile(c, walls, bent), std::invalid_argument);
    PressureProfileParams reversed = params;
    reversed.from = 5;
    reversed.to = 4;
    EXPECT_THROW(pressureProfile(c, walls, reversed), std::invalid_argument);
}

TEST(DemPressure, PileScaleFromGrains) {
    WallSegments walls;
    test::addSegment(walls, 0, {-5, 0.1}, {5, 0.1});  // floor at y = 0.1 m
    GrainFrame g;
    test::addDisk(g, 10, -1.0, 0.2, 0.1);  // on the floor
    test::addDisk(g, 11, 1.5, 0.3, 0.2);   // on the floor
    test::addDisk(g, 12, 0.2, 1.4, 0.1);   // top at 1.5 m
    test::addDisk(g, 13, 3.0, 0.9, 0.1);   // not touching the floor, farthest right
    ContactFrame c;
    test::addContact(c, 10, -1, 0, {-1.0, 0.1}, {0, -1}, {0, 1});
    test::addContact(c, 11, -1, 0, {1.5, 0.1}, {0, -1}, {0, 1});
    test::addContact(c, 99, -1, 0, {0.0, 0.1}, {0, -1}, {0, 1});  // unknown id: skipped
    const PileScale s = measurePileScale(g, c, walls, {0}, 1800, 9.81);
    EXPECT_DOUBLE_EQ(s.h, 1.4);
    EXPECT_DOUBLE_EQ(s.x0, -1.1);
    EXPECT_DOUBLE_EQ(s.x1, 1.7);
    EXPECT_DOUBLE_EQ(s.rho, 1800);
    const PileScale all = measurePileScale(g, c, walls, {0}, 1800, 9.81, true);
    EXPECT_DOUBLE_EQ(all.x1, 3.1);
    ContactFrame none;
    EXPECT_TRUE(std::isnan(measurePileScale(g, none, walls, {0}, 1, 1).x0));
    EXPECT_THROW(measurePileScale(g, c, walls, {0}, 0, 9.81), std::invalid_argument);
}
