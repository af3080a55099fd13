// SPDX-License-Identifier: MIT
// Disk-segment contacts: interiors, free end points, and a shared corner claimed exactly once.
#include <gtest/gtest.h>

#include "geom/segment.hpp"
#include "model/walls.hpp"

using namespace granulab;

namespace {
int countContacts(const model::WallSet& w, Vec2 c, Real r) {
    int n = 0;
    for (const auto& s : w.segments)
        n += geom::diskSegmentContact(c, r, s.a, s.b, s.startShared, s.endShared, s.prevDirection).touching;
    return n;
}
}  // namespace

TEST(Segment, InteriorAndFreeEndContacts) {
    auto g = geom::diskSegmentContact({0.5, 0.3}, 0.5, {0, 0}, {1, 0}, false, false, {});
    EXPECT_TRUE(g.touching);
    EXPECT_DOUBLE_EQ(g.overlap, 0.2);
    EXPECT_DOUBLE_EQ(g.normal.y, 1.0);
    g = geom::diskSegmentContact({1.3, 0.4}, 0.6, {0, 0}, {1, 0}, false, false, {});
    EXPECT_TRUE(g.touching);  // end point at distance 0.5
    EXPECT_NEAR(g.overlap, 0.1, 1e-15);
    EXPECT_NEAR(g.normal.x, 0.6, 1e-15);
}

TEST(Segment, ConvexCornerGivesOneContact) {
    model::WallSet w;  // a step: floor then a drop, disk above the corner's Voronoi region
    w.addPolyline("step", {{-5, 0}, {0, 0}, {0, -5}}, false, 0, {});
    EXPECT_EQ(countContacts(w, {0.3, 0.2}, 0.5), 1);
    // In the face region of the vertical segment only that face touches.
    EXPECT_EQ(countContacts(w, {0.3, -0.2}, 0.5), 1);
    EXPECT_EQ(countContacts(w, {-0.2, 0.3}, 0.5), 1);
}

TEST(Segment, ConcaveCornerGivesOneContactPerFace) {
    model::WallSet w;  // box corner
    w.addPolyline("corner", {{0, 5}, {0, 0}, {5, 0}}, false, 0, {});
    EXPECT_EQ(countContacts(w, {0.4, 0.4}, 0.5), 2);
    EXPECT_EQ(countContacts(w, {2.0, 0.4}, 0.5), 1);
}

TEST(Segment, ClosedPolygonCornersClaimedOnce) {
    model::WallSet w;
    w.addPolyline("square", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, true, 0, {});
    // Outside each corner, diagonal direction: exactly one (corner) contact.
    EXPECT_EQ(countContacts(w, {1.2, 1.2}, 0.5), 1);
    EXPECT_EQ(countContacts(w, {-0.2, -0.2}, 0.5), 1);
    EXPECT_EQ(countContacts(w, {1.2, -0.2}, 0.5), 1);
    EXPECT_EQ(countContacts(w, {-0.2, 1.2}, 0.5), 1);
}
