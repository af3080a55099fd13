// SPDX-License-Identifier: MIT
// Convex polygon geometry (issue 4 groundwork, gc2d spec sections 2.2 and 3.1): mass
// properties, shape checks, overlap area against analytic cases, symmetry, invariance under
// rigid motions, crossing points and a robust normal for rods touching end to end.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "geom/polygon.hpp"

using namespace granulab;
using namespace granulab::geom;

namespace {
std::vector<Vec2> rect(Real x0, Real y0, Real x1, Real y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::vector<Vec2> regular(int n, Real r, Vec2 c, Real phase) {
    std::vector<Vec2> p;
    for (int k = 0; k < n; ++k) {
        const Real a = phase + 2 * kPi * k / n;
        p.push_back(c + Vec2{r * std::cos(a), r * std::sin(a)});
    }
    return p;
}

std::vector<Vec2> moved(const std::vector<Vec2>& p, Real angle, Vec2 shift) {
    std::vector<Vec2> q;
    const Real c = std::cos(angle), s = std::sin(angle);
    for (const auto& v : p) q.push_back(Vec2{c * v.x - s * v.y, s * v.x + c * v.y} + shift);
    return q;
}
}  // namespace

TEST(Polygon, MassProperties) {
    const auto sq = polygonMass(rect(0, 0, 2, 1));
    EXPECT_DOUBLE_EQ(sq.area, 2.0);
    EXPECT_DOUBLE_EQ(sq.centroid.x, 1.0);
    EXPECT_DOUBLE_EQ(sq.centroid.y, 0.5);
    EXPECT_NEAR(sq.secondMoment, 2.0 * (4.0 + 1.0) / 12.0, 1e-15);    // A (a^2 + b^2) / 12
    const auto disk = polygonMass(regular(4096, 1.0, {3, -2}, 0.1));  // tends to pi r^4 / 2
    EXPECT_NEAR(disk.area, kPi, 1e-5);
    EXPECT_NEAR(disk.secondMoment, kPi / 2, 1e-5);
    EXPECT_NEAR(disk.centroid.x, 3.0, 1e-12);
}

TEST(Polygon, ShapeChecksNameTheCorner) {
    EXPECT_TRUE(checkConvexPolygon(regular(7, 1, {}, 0)).ok());
    EXPECT_EQ(checkConvexPolygon({{0, 0}, {1, 0}}).what, "fewer than 3 corners");
    EXPECT_EQ(checkConvexPolygon({{0, 0}, {0, 1}, {1, 1}, {1, 0}}).what, "clockwise");
    const auto collinear = checkConvexPolygon({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}});
    EXPECT_EQ(collinear.what, "collinear");
    EXPECT_EQ(collinear.corner, 1);
    const auto dent = checkConvexPolygon({{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}});
    EXPECT_EQ(dent.what, "non-convex");
    EXPECT_EQ(dent.corner, 3);
    std::vector<Vec2> star;  // pentagram: every turn is left, but it winds twice
    for (int k = 0; k < 5; ++k) star.push_back({std::cos(4 * kPi * k / 5), std::sin(4 * kPi * k / 5)});
    EXPECT_EQ(checkConvexPolygon(star).what, "self-intersecting");
    EXPECT_EQ(checkConvexPolygon({{0, 0}, {1, 0}, {1, 0}, {0, 1}}).what, "duplicate");
}

TEST(Polygon, OverlapOfTwoSquaresIsExact) {
    const auto o = convexOverlap(rect(0, 0, 2, 2), rect(1, 0.5, 3, 2.5));
    ASSERT_TRUE(o.overlapping);
    EXPECT_NEAR(o.area / 1.5, 1.0, 1e-12);
    EXPECT_EQ(o.crossings, 2);
    const Vec2 a{2, 0.5}, b{1, 2};
    const bool order = norm(o.c1 - a) < norm(o.c1 - b);
    EXPECT_NEAR(norm((order ? o.c1 : o.c2) - a), 0, 1e-12);
    EXPECT_NEAR(norm((order ? o.c2 : o.c1) - b), 0, 1e-12);
    EXPECT_NEAR(dot(o.normal, b - a), 0, 1e-12);               // perpendicular to the contact line
    EXPECT_GT(dot(o.normal, Vec2{1, 1} - Vec2{2, 1.5}), 0.0);  // pushes i away from j
    EXPECT_FALSE(convexOverlap(rect(0, 0, 1, 1), rect(2, 0, 3, 1)).overlapping);
}

TEST(Polygon, OverlapIsSymmetricAndInvariantUnderRigidMotions) {
    CounterRng rng(17, 0);
    for (int trial = 0; trial < 200; ++trial) {
        const int ni = 3 + trial % 9, nj = 3 + (trial / 3) % 9;
        const auto pi = regular(ni, rng.uniform(0.5, 1.5), {0, 0}, rng.uniform(0, 6.3));
        const auto pj = regular(nj, rng.uniform(0.5, 1.5), {rng.uniform(0.5, 2.0), rng.uniform(-0.5, 0.5)},
                                rng.uniform(0, 6.3));
        const auto o = convexOverlap(pi, pj);
        if (!o.overlapping) continue;
        const auto swapped = convexOverlap(pj, pi);
        EXPECT_NEAR(swapped.area / o.area, 1.0, 1e-12);
        EXPECT_NEAR(norm(swapped.point - o.point), 0, 1e-9)
            << "crossings " << o.crossings << " / " << swapped.crossings << " n " << ni << " " << nj
            << " area " << o.area;
        EXPECT_NEAR(dot(swapped.normal, o.normal), -1.0, 1e-9);  // opposite bodies, opposite push
        const Real angle = rng.uniform(0, 6.3);
        const Vec2 shift{rng.uniform(-100, 100), rng.uniform(-100, 100)};
        const auto m = convexOverlap(moved(pi, angle, shift), moved(pj, angle, shift));
        EXPECT_NEAR(m.area / o.area, 1.0, 1e-9);
        const auto expectedPoint = moved({o.point}, angle, shift)[0];
        EXPECT_NEAR(norm(m.point - expectedPoint), 0, 1e-9);
        const auto expectedNormal = moved({o.normal}, angle, {})[0];
        EXPECT_NEAR(dot(m.normal, expectedNormal), 1.0, 1e-9);
    }
}

TEST(Polygon, RodsTouchingEndToEndGetTheNormalAlongTheRods) {
    // Two long thin rods overlapping at their ends: the contact line is across the rods and the
    // normal along them, although the centroids' line would also work here; rotate j slightly
    // so that the centroid line is not a normal.
    const auto i = rect(-10, -0.1, 0.05, 0.1);
    const auto j = moved(rect(-0.05, -0.05, 10, 0.05), 0.01, {0, 0});  // thinner: its end pokes into i
    const auto o = convexOverlap(i, j);
    ASSERT_TRUE(o.overlapping);
    EXPECT_EQ(o.crossings, 2);
    EXPECT_LT(o.normal.x, -0.99);  // pushes i (on the left) to the left
}
