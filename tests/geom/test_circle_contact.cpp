// SPDX-License-Identifier: MIT
// Disk-disk and disk-polygon overlap contacts (gc2d spec section 3.1, erratum 6 of section 12).
// References: lens and segment areas by Simpson quadrature of 2 r^2 sin^2 in long double (no
// cancellation at any overlap), the small-overlap asymptote A ~ (4/3) sqrt(2 R) h^(3/2), and
// geom::convexOverlap with an area-preserving 20000-gon for the circle. Lengths in [m].
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/rng.hpp"
#include "geom/circle_contact.hpp"
#include "geom/polygon.hpp"

using namespace granulab;
using namespace granulab::geom;

namespace {
using LD = long double;

/// Circular segment area r^2 (theta - sin theta cos theta) = 2 r^2 int_0^theta sin^2 [m^2].
LD segmentRef(LD r, LD theta) {
    const int n = 4000;  // Simpson; truncation < 1e-13 relative for theta <= pi
    const LD h = theta / n;
    LD s = 0;
    for (int k = 0; k <= n; ++k) {
        const LD v = std::sin(k * h);
        s += (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2)) * v * v;
    }
    return 2 * r * r * s * h / 3;
}

/// Lens area of disks ri, rj at centre distance d (partial overlap), in long double.
LD lensRef(LD ri, LD rj, LD d) {
    const LD a = (d * d + ri * ri - rj * rj) / (2 * d);  // centre i -> chord
    const auto ac = [](LD x) { return std::acos(std::clamp(x, LD(-1), LD(1))); };
    return segmentRef(ri, ac(a / ri)) + segmentRef(rj, ac((d - a) / rj));
}

/// Regular N-gon with the area of the disk (errors of whole edges cancel).
std::vector<Vec2> ngon(Vec2 c, Real r, int n) {
    const Real rn = r * std::sqrt(2 * kPi / (n * std::sin(2 * kPi / n)));
    std::vector<Vec2> p(n);
    for (int k = 0; k < n; ++k)
        p[k] = c + Vec2{rn * std::cos(2 * kPi * k / n), rn * std::sin(2 * kPi * k / n)};
    return p;
}

Vec2 rot(Vec2 v, Real a) {
    return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y};
}

std::vector<Vec2> randomConvex(CounterRng& rng, int n, Real size, Vec2 at) {
    const Real phase = rng.uniform(0, 2 * kPi), sx = rng.uniform(0.4, 1.0), tilt = rng.uniform(0, kPi);
    std::vector<Vec2> p(n);
    for (int k = 0; k < n; ++k) {
        const Real a = phase + 2 * kPi * (k + rng.uniform(-0.4, 0.4)) / n;
        p[k] = at + rot(Vec2{size * sx * std::cos(a), size * std::sin(a)}, tilt);
    }
    return p;
}

Real distanceToBoundary(Vec2 x, const std::vector<Vec2>& poly) {
    Real best = 1e300;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const Vec2 a = poly[k], d = poly[(k + 1) % poly.size()] - a;
        const Real t = std::clamp(dot(x - a, d) / norm2(d), 0.0, 1.0);
        best = std::min(best, norm(x - (a + d * t)));
    }
    return best;
}

AreaContact cp(Vec2 c, Real r, const std::vector<Vec2>& p) {
    return circlePolygonContact(c, r, p.data(), static_cast<int>(p.size()));
}
}  // namespace

TEST(CircleContact, LensAreaMatchesLongDoubleReference) {
    const Real radii[][2] = {{1, 1}, {1, 0.3}, {0.3, 1}, {2.5e-3, 1e-3}};
    const Real depths[] = {1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 0.5, 1, 1.5, 1.9};
    Real worst = 0;
    for (const auto& rr : radii)
        for (Real f : depths) {
            const Real ri = rr[0], rj = rr[1], d = ri + rj - f * std::min(ri, rj);
            const AreaContact c = circleCircleContact({0, 0}, ri, {d, 0}, rj);
            ASSERT_TRUE(c.touching) << ri << " " << rj << " " << f;
            const LD ref = lensRef(ri, rj, d);
            const Real rel = static_cast<Real>(std::abs(c.area - ref) / ref);
            EXPECT_LT(rel, 1e-6) << ri << " " << rj << " " << f;
            worst = std::max(worst, rel);
        }
    std::printf("[ lens ] worst relative area error vs long double: %.2e\n", worst);
}

TEST(CircleContact, TinyLensFollowsAsymptoteAndStaysStable) {
    // A = (4/3) sqrt(2 R) h^(3/2) (1 + O(h/R)), R = ri rj / (ri + rj), h = ri + rj - d.
    for (const auto& rr : {std::pair{1.0, 1.0}, std::pair{1.0, 0.25}, std::pair{3e-3, 1e-3}}) {
        const Real ri = rr.first, rj = rr.second, R = ri * rj / (ri + rj);
        for (Real f : {1e-8, 1e-10, 1e-12}) {
            const Real d = ri + rj - f * ri;
            const LD h = LD(ri) + LD(rj) - LD(d);  // the depth actually represented
            const AreaContact c = circleCircleContact({d, 0}, rj, {0, 0}, ri);
            const LD asym = LD(4) / 3 * std::sqrt(2 * LD(R)) * std::pow(h, LD(1.5));
            const Real rel = static_cast<Real>(std::abs(c.area - asym) / asym);
            EXPECT_LT(rel, 1e-6) << ri << " " << rj << " " << f;
            if (f == 1e-8)
                std::printf("[ lens ] h = 1e-8 r, ri/rj = %g: relative deviation from asymptote %.2e\n",
                            ri / rj, rel);
        }
    }
}

TEST(CircleContact, LensGeometryAndSymmetry) {
    CounterRng rng(3, 1);
    for (int trial = 0; trial < 500; ++trial) {
        const Real ri = rng.uniform(0.1, 2), rj = rng.uniform(0.1, 2);
        const Real lo = std::abs(ri - rj), hi = ri + rj;
        const Real d = lo + (hi - lo) * rng.uniform(0.001, 0.999), a = rng.uniform(0, 2 * kPi);
        const Vec2 ci{rng.uniform(-5, 5), rng.uniform(-5, 5)}, cj = ci + rot({d, 0}, a);
        const AreaContact c = circleCircleContact(ci, ri, cj, rj);
        ASSERT_TRUE(c.touching);
        for (Vec2 x : {c.c1, c.c2}) {
            EXPECT_NEAR(norm(x - ci), ri, 1e-12 * 8);
            EXPECT_NEAR(norm(x - cj), rj, 1e-12 * 8);
        }
        const Vec2 n = (ci - cj) / norm(ci - cj);
        EXPECT_NEAR(norm(c.normal - n), 0, 1e-14);
        EXPECT_NEAR(dot(c.normal, c.c2 - c.c1), 0, 1e-12);
        EXPECT_GT(dot(c.c2 - c.c1, perp(c.normal)), 0);
        EXPECT_NEAR(norm(c.point - (c.c1 + c.c2) * 0.5), 0, 1e-15);
        const AreaContact s = circleCircleContact(cj, rj, ci, ri);
        EXPECT_NEAR(s.area, c.area, 1e-14 * c.area);
        EXPECT_NEAR(norm(s.normal + c.normal), 0, 1e-14);
        EXPECT_NEAR(norm(s.point - c.point), 0, 1e-12);
        // Consistency with the polygon kernel on an area-preserving 20000-gon for disk j.
        if (trial % 10 == 0 && c.area > 1e-6 * kPi * std::min(ri, rj) * std::min(ri, rj)) {
            EXPECT_NEAR(cp(ci, ri, ngon(cj, rj, 20000)).area / c.area, 1, 1e-6);
        }
    }
}

TEST(CircleContact, LensContainmentAndSeparation) {
    const AreaContact in = circleCircleContact({0.2, 0.1}, 0.5, {0, 0}, 2);
    ASSERT_TRUE(in.touching);
    EXPECT_DOUBLE_EQ(in.area, kPi * 0.25);
    const Vec2 u = Vec2{0.2, 0.1} / norm(Vec2{0.2, 0.1});
    EXPECT_NEAR(norm(in.normal - u), 0, 1e-15);
    EXPECT_NEAR(norm(in.point - (Vec2{0.2, 0.1} + u * 0.5)), 0, 1e-15);
    EXPECT_EQ(in.c1, in.c2);
    const AreaContact big = circleCircleContact({0, 0}, 2, {0.2, 0.1}, 0.5);  // i is the big one
    EXPECT_DOUBLE_EQ(big.area, kPi * 0.25);
    EXPECT_NEAR(norm(big.normal + u), 0, 1e-15);
    EXPECT_NEAR(norm(big.point - in.point), 0, 1e-15);
    const AreaContact con = circleCircleContact({1, 1}, 1, {1, 1}, 1);  // concentric: +x
    EXPECT_DOUBLE_EQ(con.area, kPi);
    EXPECT_EQ(con.normal, (Vec2{1, 0}));
    EXPECT_FALSE(circleCircleContact({0, 0}, 1, {2, 0}, 1).touching);  // tangent
    EXPECT_FALSE(circleCircleContact({0, 0}, 1, {3, 0}, 1).touching);
    EXPECT_FALSE(circleCircleContact({0, 0}, 0, {0.5, 0}, 1).touching);
    // Continuity at the onset of containment.
    const AreaContact almost = circleCircleContact({1.5 + 1e-9, 0}, 0.5, {0, 0}, 2);
    EXPECT_NEAR(almost.area / (kPi * 0.25), 1, 1e-4);
    EXPECT_NEAR(norm(almost.point - Vec2{2, 0}), 0, 1e-4);
}

TEST(CircleContact, PolygonAreaMatchesPolygonizedCircle) {
    CounterRng rng(11, 2);
    Real worst = 0;
    int compared = 0, multi = 0;
    for (int trial = 0; trial < 600; ++trial) {
        std::vector<Vec2> poly;
        const Real size = 1;
        if (trial % 3 == 0)
            poly = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        else if (trial % 3 == 1)
            poly = {{-1, -0.6}, {1.2, -0.8}, {0.1, 1.1}};
        else
            poly = randomConvex(rng, 3 + trial % 10, size, {0, 0});
        ASSERT_TRUE(checkConvexPolygon(poly).ok());
        // Every fourth placement: disk and polygon of similar size and centre (> 2 crossings).
        const bool alike = trial % 4 == 3;
        const Real r =
            alike ? rng.uniform(0.8, 1.4) : size * std::exp(rng.uniform(std::log(0.05), std::log(3.0)));
        const Real reach = alike ? 0.3 : 1.5 + r;
        const Vec2 c{rng.uniform(-reach, reach), rng.uniform(-reach, reach)};
        const AreaContact got = cp(c, r, poly);
        const PolygonOverlap ref = convexOverlap(ngon(c, r, 20000), poly);
        const Real disk = kPi * r * r;
        EXPECT_NEAR(got.area, ref.area, 1e-9 * disk);
        EXPECT_EQ(got.touching, got.area > 0);
        if (ref.area > 1e-6 * disk) {
            ASSERT_TRUE(got.touching);
            const Real rel = std::abs(got.area - ref.area) / ref.area;
            EXPECT_LT(rel, 1e-6) << trial;
            worst = std::max(worst, rel);
            ++compared;
            multi += ref.crossings > 2;
        }
    }
    EXPECT_GT(compared, 300);
    EXPECT_GT(multi, 50);
    std::printf("[ poly ] %d overlaps (%d with > 2 crossings): worst relative area error %.2e\n", compared,
                multi, worst);
}

TEST(CircleContact, PolygonTinyOverlapIsStable) {
    const std::vector<Vec2> sq{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    const Real r = 0.25;
    for (Real f : {1e-6, 1e-8, 1e-10}) {
        const Real y = 1 + r - f * r;
        const LD h = LD(1) + LD(r) - LD(y);
        const AreaContact c = cp({0.3, y}, r, sq);
        const LD ref = segmentRef(r, std::acos((LD(r) - h) / r));
        const Real rel = static_cast<Real>(std::abs(c.area - ref) / ref);
        EXPECT_LT(rel, 1e-6) << f;
        EXPECT_NEAR(norm(c.normal - Vec2{0, 1}), 0, 1e-12);
        if (f == 1e-8) std::printf("[ poly ] h = 1e-8 r on a face: relative area error %.2e\n", rel);
    }
}

TEST(CircleContact, PolygonCrossingsAndNormal) {
    CounterRng rng(5, 3);
    int checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const auto poly = randomConvex(rng, 3 + trial % 12, 1, {rng.uniform(-3, 3), rng.uniform(-3, 3)});
        const Real r = std::exp(rng.uniform(std::log(0.05), std::log(3.0)));
        const Vec2 c = poly[0] + rot({rng.uniform(0, 1.2 + r), 0}, rng.uniform(0, 2 * kPi));
        const AreaContact got = cp(c, r, poly);
        if (!got.touching || got.c1 == got.c2) continue;
        ++checked;
        const Real scale = 1e-12 * (r + 4);
        for (Vec2 x : {got.c1, got.c2}) {
            EXPECT_NEAR(norm(x - c), r, scale);
            EXPECT_LT(distanceToBoundary(x, poly), scale);
        }
        EXPECT_NEAR(norm(got.normal), 1, 1e-14);
        EXPECT_NEAR(dot(got.normal, got.c2 - got.c1), 0, 1e-12 * norm(got.c2 - got.c1));
        EXPECT_NEAR(norm(got.point - (got.c1 + got.c2) * 0.5), 0, 1e-15 * (r + 4));
        // The normal pushes the disk away: moving the disk along it does not grow the overlap.
        const Real eta = 1e-6 * r;
        EXPECT_LE(cp(c + got.normal * eta, r, poly).area,
                  cp(c - got.normal * eta, r, poly).area + 1e-13 * r * r)
            << trial;
        bool inside = true;  // centre outside the polygon: the normal points at the centre too
        for (std::size_t k = 0; k < poly.size(); ++k)
            inside = inside && cross(poly[(k + 1) % poly.size()] - poly[k], c - poly[k]) > 0;
        if (!inside) {
            EXPECT_GT(dot(got.normal, c - got.point), 0) << trial;
        }
    }
    EXPECT_GT(checked, 800);
}

TEST(CircleContact, PolygonFarthestPairWithManyCrossings) {
    // Square of half-side 0.8 around a unit disk: 8 crossings; a 40-gon just outside the disk:
    // 80 crossings (more than the kernel stores, the re-walking path).
    std::vector<Vec2> gon(40);
    for (int k = 0; k < 40; ++k) gon[k] = rot({1.002, 0}, 2 * kPi * k / 40);  // inradius 0.9989
    for (const auto& poly : {std::vector<Vec2>{{-0.8, -0.8}, {0.8, -0.8}, {0.8, 0.8}, {-0.8, 0.8}}, gon}) {
        const Vec2 c{1e-4, -2e-4};
        const AreaContact got = cp(c, 1, poly);
        std::vector<Vec2> xs;  // crossings by brute force: line-circle roots on each edge
        for (std::size_t k = 0; k < poly.size(); ++k) {
            const Vec2 a = poly[k] - c, d = poly[(k + 1) % poly.size()] - poly[k];
            const Real A = norm2(d), B = dot(a, d), C = norm2(a) - 1, disc = B * B - A * C;
            if (disc <= 0) continue;
            for (Real t : {(-B - std::sqrt(disc)) / A, (-B + std::sqrt(disc)) / A})
                if (t > 0 && t < 1) xs.push_back(c + a + d * t);
        }
        ASSERT_GE(xs.size(), poly.size() == 4 ? 8u : 40u);
        Real far = 0;
        for (Vec2 p : xs)
            for (Vec2 q : xs) far = std::max(far, norm(p - q));
        EXPECT_NEAR(norm(got.c2 - got.c1), far, 1e-12);
        EXPECT_NEAR(got.area, convexOverlap(ngon(c, 1, 20000), poly).area, 1e-9);
    }
}

TEST(CircleContact, PolygonInvariantUnderRigidMotion) {
    CounterRng rng(9, 4);
    for (int trial = 0; trial < 300; ++trial) {
        const auto poly = randomConvex(rng, 3 + trial % 9, 1, {0, 0});
        const Real r = rng.uniform(0.1, 2);
        const Vec2 c{rng.uniform(-1.5 - r, 1.5 + r), rng.uniform(-1.5 - r, 1.5 + r)};
        const AreaContact a = cp(c, r, poly);
        if (!(a.area > 1e-6 * kPi * r * r)) continue;
        const Real ang = rng.uniform(0, 2 * kPi);
        const Vec2 shift{rng.uniform(-10, 10), rng.uniform(-10, 10)};
        std::vector<Vec2> moved;
        for (Vec2 v : poly) moved.push_back(rot(v, ang) + shift);
        const AreaContact b = cp(rot(c, ang) + shift, r, moved);
        EXPECT_NEAR(b.area / a.area, 1, 1e-10) << trial;
        EXPECT_NEAR(norm(b.point - (rot(a.point, ang) + shift)), 0, 1e-10) << trial;
        EXPECT_NEAR(norm(b.normal - rot(a.normal, ang)), 0, 1e-9) << trial;
    }
}

TEST(CircleContact, PolygonContainmentCases) {
    const std::vector<Vec2> sq{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    // Disk inside, nearest edge x = 4: touching point on it, outward normal +x.
    const AreaContact in = cp({3, 1.8}, 0.5, sq);
    ASSERT_TRUE(in.touching);
    EXPECT_DOUBLE_EQ(in.area, kPi * 0.25);
    EXPECT_EQ(in.c1, in.c2);
    EXPECT_NEAR(norm(in.point - Vec2{4, 1.8}), 0, 1e-15);
    EXPECT_NEAR(norm(in.normal - Vec2{1, 0}), 0, 1e-15);
    // Centre inside, cap cut off by the bottom edge: pushed out through it (-y), not deeper in.
    const AreaContact deep = cp({2, 0.3}, 0.5, sq);
    EXPECT_NEAR(norm(deep.normal - Vec2{0, -1}), 0, 1e-12);
    EXPECT_GT(deep.area, 0.5 * kPi * 0.25);
    // Polygon inside the disk: its area, point at its centroid, normal centroid -> centre.
    const AreaContact all = cp({2.5, 2}, 10, sq);
    EXPECT_NEAR(all.area, 16, 1e-13);
    EXPECT_NEAR(norm(all.point - Vec2{2, 2}), 0, 1e-14);
    EXPECT_NEAR(norm(all.normal - Vec2{1, 0}), 0, 1e-14);
    // Disjoint, tangent to a face, tangent at a corner.
    EXPECT_FALSE(cp({6, 2}, 1, sq).touching);
    EXPECT_FALSE(cp({5, 2}, 1, sq).touching);
    EXPECT_FALSE(cp({7, 8}, 5, sq).touching);  // through the corner (4, 4) only
    EXPECT_FALSE(cp({2, 2}, 1, std::vector<Vec2>{{0, 0}, {1, 0}}).touching);  // not a polygon
}

TEST(CircleContact, PolygonSymmetricStripFallsBackSafely) {
    // A strip through the centre: the two arcs cancel in dA/d(centre), four crossings.
    const std::vector<Vec2> strip{{-3, -0.3}, {3, -0.3}, {3, 0.3}, {-3, 0.3}};
    const AreaContact s = cp({0, 0}, 1, strip);
    ASSERT_TRUE(s.touching);
    EXPECT_NEAR(s.area, 2 * (0.3 * std::sqrt(1 - 0.09) + std::asin(0.3)), 1e-14);
    EXPECT_NEAR(norm(s.normal), 1, 1e-15);
    EXPECT_NEAR(dot(s.normal, s.c2 - s.c1), 0, 1e-14);
    EXPECT_NEAR(norm(s.c2 - s.c1), 2, 1e-14);  // farthest pair: a diagonal of the four crossings
}
