// SPDX-License-Identifier: MIT
// Contact persistence (gc2d spec 7 item 11): known overlaps of pair sets, unordered and duplicate
// pairs, wall contacts ignored, and the region C restriction in the later frame.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/dem_persistence.hpp"
#include "dem_frames.hpp"

using namespace granulab;
using namespace granulab::analysis;

namespace {

ContactFrame pairs(std::initializer_list<std::pair<int, int>> list) {
    ContactFrame c;
    for (auto [a, b] : list) test::addPair(c, a, b, {1, 0});
    return c;
}

}  // namespace

TEST(DemPersistence, FractionOfKeptPairs) {
    ContactFrame before = pairs({{1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 1}, {1, 5}});  // 1-5 twice
    test::addContact(before, 1, -1, 0, {0, 0}, {0, -1}, {0, 1});                    // wall: ignored
    ContactFrame after = pairs({{2, 1}, {3, 4}, {5, 6}});
    test::addContact(after, 2, -1, 0, {0, 0}, {0, -1}, {0, 1});
    const ContactPersistence p = contactPersistence(before, after, GrainFrame{});
    EXPECT_EQ(p.pairsBefore, 5u);
    EXPECT_EQ(p.pairsKept, 2u);
    EXPECT_EQ(p.pairsAfter, 3u);
    EXPECT_DOUBLE_EQ(p.fraction, 0.4);
    const Table t = toTable(p);
    EXPECT_EQ(t.name, "contact_persistence");
    EXPECT_EQ(t.rows(), 1u);
    EXPECT_DOUBLE_EQ(t.columns[3].values[0], 0.4);
}

TEST(DemPersistence, RegionInTheLaterFrame) {
    const ContactFrame before = pairs({{1, 2}, {2, 3}, {3, 4}, {1, 7}});
    const ContactFrame after = pairs({{1, 2}, {3, 4}});
    GrainFrame g;  // grain 7 has left (not in the frame)
    test::addDisk(g, 1, 0.1, 0.1, 0.05);
    test::addDisk(g, 2, 0.2, 0.1, 0.05);
    test::addDisk(g, 3, 0.3, 0.1, 0.05);
    test::addDisk(g, 4, 0.9, 0.1, 0.05);
    PersistenceParams params;
    params.region = Rect{0, 0.5, 0, 0.5};
    const ContactPersistence p = contactPersistence(before, after, g, params);
    EXPECT_EQ(p.pairsBefore, 2u);  // 1-2 and 2-3
    EXPECT_EQ(p.pairsKept, 1u);
    EXPECT_DOUBLE_EQ(p.fraction, 0.5);
    params.region = Rect{5, 6, 5, 6};
    const ContactPersistence none = contactPersistence(before, after, g, params);
    EXPECT_EQ(none.pairsBefore, 0u);
    EXPECT_TRUE(std::isnan(none.fraction));
    EXPECT_FALSE(none.notes.empty());
    params.region = Rect{0, -1, 0, 1};
    EXPECT_THROW(contactPersistence(before, after, g, params), std::invalid_argument);
}
