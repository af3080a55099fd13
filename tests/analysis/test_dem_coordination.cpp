// SPDX-License-Identifier: MIT
// Coordination number and rattlers (gc2d spec 7 item 4): a chain with known counts, rattler
// removal that cascades along a dangling chain, a region selection and undefined selections.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/dem_coordination.hpp"
#include "dem_frames.hpp"

using namespace granulab;
using namespace granulab::analysis;

namespace {

/// Grains 1..n on a line at x = id, radius 0.5.
GrainFrame line(int n) {
    GrainFrame g;
    for (int i = 1; i <= n; ++i) test::addDisk(g, i, i, 0, 0.5);
    return g;
}

}  // namespace

TEST(DemCoordination, ChainBetweenTwoWalls) {
    const GrainFrame g = line(5);
    ContactFrame c;
    for (int i = 1; i < 5; ++i) test::addPair(c, i, i + 1, {-1, 0});
    test::addContact(c, 1, -1, 0, {0.5, 0}, {-1, 0}, {1, 0});
    test::addContact(c, 5, -1, 1, {5.5, 0}, {1, 0}, {-1, 0});
    const Coordination k = coordination(g, c);
    const std::vector<std::uint32_t> expected{1, 2, 2, 2, 1};
    EXPECT_EQ(k.contactsPerGrain, expected);
    EXPECT_DOUBLE_EQ(k.meanK, 1.6);
    ASSERT_EQ(k.probability.size(), 3u);
    EXPECT_DOUBLE_EQ(k.probability[0], 0);
    EXPECT_DOUBLE_EQ(k.probability[1], 0.4);
    EXPECT_DOUBLE_EQ(k.probability[2], 0.6);
    EXPECT_EQ(k.rattlers, 0u);  // walls hold the chain ends
    EXPECT_DOUBLE_EQ(k.meanKNonRattler, 1.6);
    CoordinationParams walls;
    walls.countWalls = true;
    const Coordination kw = coordination(g, c, walls);
    EXPECT_DOUBLE_EQ(kw.meanK, 2);
    EXPECT_DOUBLE_EQ(kw.meanKNonRattler, 2);
    const Table t = toTable(k);
    EXPECT_EQ(t.name, "coordination");
    EXPECT_EQ(t.columns[0].name, "K");
    EXPECT_DOUBLE_EQ(t.columns[0].values[2], 2);
    EXPECT_DOUBLE_EQ(t.columns[2].values[1], 2);  // two grains with K = 1
    EXPECT_EQ(t.notes[0], "mean_K = 1.6");
}

TEST(DemCoordination, RattlerRemovalCascades) {
    // Triangle 1-2-3 (stable), a tail 3-4-5-6 that unravels from its free end, and grain 7 held by
    // one force-bearing contact (to 2) and one contact without force (to 1).
    const GrainFrame g = line(7);
    ContactFrame c;
    test::addPair(c, 1, 2, {-1, 0});
    test::addPair(c, 1, 3, {-1, 0.5});
    test::addPair(c, 2, 3, {-1, 0});
    test::addPair(c, 3, 4, {-1, 0});
    test::addPair(c, 4, 5, {-1, 0});
    test::addPair(c, 5, 6, {-1, 0});
    test::addPair(c, 7, 1, {0, 0});
    test::addPair(c, 7, 2, {0.5, 0});
    const Coordination k = coordination(g, c);
    const std::vector<std::uint32_t> contacts{3, 3, 3, 2, 2, 1, 2};
    EXPECT_EQ(k.contactsPerGrain, contacts);
    const std::vector<char> rattler{0, 0, 0, 1, 1, 1, 1};  // 4 and 5 start with 2 each: the cascade
    EXPECT_EQ(k.rattler, rattler);
    EXPECT_EQ(k.rattlers, 4u);
    EXPECT_DOUBLE_EQ(k.rattlerFraction, 4.0 / 7);
    EXPECT_DOUBLE_EQ(k.meanK, 16.0 / 7);
    EXPECT_DOUBLE_EQ(k.meanKNonRattler, 2);
}

TEST(DemCoordination, RegionSelectsGrainsButNotTheirCages) {
    const GrainFrame g = line(7);
    ContactFrame c;
    test::addPair(c, 1, 2, {-1, 0});
    test::addPair(c, 1, 3, {-1, 0.5});
    test::addPair(c, 2, 3, {-1, 0});
    test::addPair(c, 3, 4, {-1, 0});
    test::addPair(c, 4, 5, {-1, 0});
    test::addPair(c, 5, 6, {-1, 0});
    test::addPair(c, 7, 1, {0, 0});
    test::addPair(c, 7, 2, {0.5, 0});
    test::addPair(c, 8, 2, {0.5, 0});  // id 8 is not in the frame
    CoordinationParams params;
    params.region = Rect{2.5, 4.5, -1, 1};  // grains 3 and 4
    const Coordination k = coordination(g, c, params);
    EXPECT_EQ(k.grains, 2u);
    EXPECT_EQ(k.rattlers, 1u);
    EXPECT_DOUBLE_EQ(k.meanK, 2.5);
    EXPECT_DOUBLE_EQ(k.meanKNonRattler, 2);  // grain 3: to 1 and 2, not to the rattler 4
    EXPECT_EQ(k.unknownIds, 1u);
    EXPECT_FALSE(k.notes.empty());
    params.region = Rect{100, 101, 0, 1};
    const Coordination none = coordination(g, c, params);
    EXPECT_TRUE(std::isnan(none.meanK));
    EXPECT_TRUE(std::isnan(none.rattlerFraction));
    params.region = Rect{1, 0, 0, 1};
    EXPECT_THROW(coordination(g, c, params), std::invalid_argument);
    CoordinationParams negative;
    negative.forceThreshold = -1;
    EXPECT_THROW(coordination(g, c, negative), std::invalid_argument);
}
