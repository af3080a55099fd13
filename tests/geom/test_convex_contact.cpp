// SPDX-License-Identifier: MIT
// Tracked polygon contact (gc2d spec sections 3.1 and 5.3) against the brute-force clipping
// reference: area, crossings and normal along random trajectories; persistent contacts and near
// misses cost O(1) feature tests whatever the corner count; rod and containment special cases.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/rng.hpp"
#include "geom/convex_contact.hpp"
#include "geom/convex_crossings.hpp"
#include "geom/polygon.hpp"

using namespace granulab;
using namespace granulab::geom;

namespace {
std::vector<Vec2> regular(int n, Real r, Real phase = 0) {
    std::vector<Vec2> p;
    for (int k = 0; k < n; ++k) {
        const Real a = phase + 2 * kPi * k / n;
        p.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return p;
}

/// Random convex polygon inscribed in an ellipse (sorted random angles).
std::vector<Vec2> randomConvex(CounterRng& rng, int n, Real a, Real b) {
    for (;;) {
        std::vector<Real> ang(static_cast<std::size_t>(n));
        for (int k = 0; k < n; ++k)
            ang[static_cast<std::size_t>(k)] = rng.uniform((k - 0.5) * 2 * kPi / n, (k + 0.5) * 2 * kPi / n);
        std::vector<Vec2> p;
        for (Real t : ang) p.push_back({a * std::cos(t), b * std::sin(t)});
        if (checkConvexPolygon(p).ok()) {
            const auto m = polygonMass(p);
            for (auto& q : p) q = q - m.centroid;
            return p;
        }
    }
}

Real inradiusOf(const std::vector<Vec2>& p) {
    Real r = 1e300;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const Vec2 a = p[k], b = p[(k + 1) % p.size()];
        r = std::min(r, cross(b - a, -a) / norm(b - a));
    }
    return r;
}

/// World corners live in a small ring of buffers so that a few frames can coexist.
PolygonFrame frame(const std::vector<Vec2>& body, Vec2 c, Real angle) {
    static std::vector<Vec2> buffers[8];
    static int next = 0;
    auto& w = buffers[next++ % 8];
    w.clear();
    const Real cs = std::cos(angle), sn = std::sin(angle);
    for (const auto& b : body) w.push_back(c + Vec2{cs * b.x - sn * b.y, sn * b.x + cs * b.y});
    PolygonFrame f;
    f.corners = w.data();
    f.n = static_cast<int>(body.size());
    f.centre = c;
    f.inradius = inradiusOf(body);
    return f;
}

std::vector<Vec2> world(const PolygonFrame& f) {
    std::vector<Vec2> w;
    for (int k = 0; k < f.n; ++k) w.push_back(f.corner(k));
    return w;
}

void expectMatchesClipping(const PolygonFrame& A, const PolygonFrame& B, const AreaContact& c, Real scale) {
    const PolygonOverlap ref = convexOverlap(world(A), world(B));
    ASSERT_EQ(c.touching, ref.overlapping);
    if (!ref.overlapping) return;
    EXPECT_NEAR(c.area, ref.area, 1e-12 * scale * scale + 1e-9 * ref.area);
    // The crossing pair is the same set of two points (order may differ).
    const Real d1 = norm(c.c1 - ref.c1) + norm(c.c2 - ref.c2), d2 = norm(c.c1 - ref.c2) + norm(c.c2 - ref.c1);
    EXPECT_LT(std::min(d1, d2), 1e-9 * scale);
    EXPECT_NEAR(dot(c.normal, ref.normal), 1.0, 1e-9);
}

/// A random pair: A starts at x = -3 and moves right past B (at the origin) while it turns, so it
/// approaches, presses in slightly and leaves again. Up to 3 + maxExtra corners each.
struct Approach {
    std::vector<Vec2> pa, pb;
    Vec2 c;          ///< A's centre
    Real ang, angB;  ///< angles of A and B
    Vec2 v;          ///< A's displacement per step
    Real w;          ///< A's turn per step
};
Approach randomApproach(CounterRng& rng, int maxExtra) {
    const int na = 3 + static_cast<int>(rng.uniform() * maxExtra),
              nb = 3 + static_cast<int>(rng.uniform() * maxExtra);
    Approach a;
    a.pa = randomConvex(rng, na, 1.0, rng.uniform(0.3, 1.0));
    a.pb = randomConvex(rng, nb, rng.uniform(0.5, 1.5), rng.uniform(0.3, 1.0));
    a.c = {-3.0, rng.uniform(-0.8, 0.8)};
    a.ang = rng.uniform(0, 2 * kPi);
    a.angB = rng.uniform(0, 2 * kPi);
    a.v = {0.01, rng.uniform(-0.002, 0.002)};
    a.w = rng.uniform(-0.02, 0.02);
    return a;
}
}  // namespace

TEST(ConvexContact, TwoSquaresExact) {
    const std::vector<Vec2> sq = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    const auto A = frame(sq, {0, 1.9}, 0), B = frame(sq, {0.5, 0}, 0);
    const auto c = polygonContact(A, B);
    ASSERT_TRUE(c.touching);
    EXPECT_NEAR(c.area, 0.1 * 1.5, 1e-15);
    // Crossings (-0.5, 0.9) and (1, 1): the contact line is the diagonal of the overlap
    // rectangle, so n = perp(1.5, 0.1)/|.| pushes A (above) up and slightly left.
    EXPECT_NEAR(norm(c.c2 - c.c1), std::sqrt(1.5 * 1.5 + 0.01), 1e-14);
    EXPECT_NEAR(c.normal.y, 1.5 / std::sqrt(1.5 * 1.5 + 0.01), 1e-14);
    EXPECT_NEAR(c.normal.x, -0.1 / std::sqrt(1.5 * 1.5 + 0.01), 1e-14);
}

TEST(ConvexContact, TrackedEqualsClippingAlongRandomTrajectories) {
    CounterRng rng(7, 1);
    FeatureStats stats;
    std::uint64_t touchingSteps = 0;
    for (int trial = 0; trial < 60; ++trial) {
        Approach a = randomApproach(rng, 20);
        FeatureCache cache;
        for (int step = 0; step < 600; ++step) {
            a.c += a.v;
            a.ang += a.w;
            const auto A = frame(a.pa, a.c, a.ang), B = frame(a.pb, {0, 0}, a.angB);
            const auto got = trackPolygonContact(A, B, cache, stats);
            // Beyond a quarter of the inscribed radius the tracker itself clips (deep overlaps).
            expectMatchesClipping(A, B, got, 1.0);
            touchingSteps += got.touching;
            if (::testing::Test::HasFailure()) return;
        }
    }
    EXPECT_GT(touchingSteps, 1000u);
    std::printf(
        "feature tests per evaluation %.3f, cold starts %llu, full clips %llu over %llu evaluations\n",
        double(stats.iterations) / double(stats.evaluations), (unsigned long long)stats.coldStarts,
        (unsigned long long)stats.fullClips, (unsigned long long)stats.evaluations);
}

TEST(ConvexContact, ThePairKernelsInlinePathsEqualTheTrackedContact) {
    // What the pair kernel does (dem/forces_area.hpp): the refresh of both cached crossings with
    // the normal completed afterwards, else the separation certificate of the cached closest
    // features, else the tracked contact. Along random trajectories the refresh gives the tracked
    // contact's numbers bit for bit, and a pair certified apart is apart (clipping reference).
    // (Both polygons turn here; where they turn by 0.02 rad per step relative to each other, a
    // shallow overlap was seen to cross more than twice, and the tracked contact, inline or not, takes it
    // for two crossings: bounded by erratum 6's depth guard, not exact. DEM steps turn grains by
    // about 1e-5 rad.)
    CounterRng rng(11, 3);
    FeatureStats stats, spare;
    std::uint64_t refreshed = 0, certified = 0, tracked = 0;
    for (int trial = 0; trial < 60; ++trial) {
        Approach a = randomApproach(rng, 12);
        const Real wB = rng.uniform(-0.01, 0.01);  // B turns too
        FeatureCache cache;
        for (int step = 0; step < 600; ++step) {
            a.c += a.v;
            a.ang += a.w;
            a.angB += wB;
            const auto A = frame(a.pa, a.c, a.ang), B = frame(a.pb, {0, 0}, a.angB);
            FeatureCache copy = cache;
            const AreaContact reference = trackPolygonContact(A, B, copy, spare);
            AreaContact got;
            if (crossings::refreshCrossings<false>(A, B, cache, stats, got)) {
                crossings::chainNormal(got, A.centre, B.centre);
                ++refreshed;
                ASSERT_TRUE(got.touching);
                EXPECT_EQ(got.area, reference.area);
                EXPECT_EQ(got.normal.x, reference.normal.x);
                EXPECT_EQ(got.normal.y, reference.normal.y);
                EXPECT_EQ(got.point.x, reference.point.x);
                EXPECT_EQ(got.pull.y, reference.pull.y);
            } else if (crossings::stillApart(A, B, cache, stats)) {
                ++certified;
                ASSERT_FALSE(reference.touching);
                ASSERT_FALSE(convexOverlap(world(A), world(B)).overlapping)
                    << "trial " << trial << " step " << step;
            } else {
                got = trackPolygonContact(A, B, cache, stats);
                ++tracked;
            }
            if (::testing::Test::HasFailure()) return;
        }
    }
    std::printf("refreshed %llu, certified apart %llu, tracked %llu\n", (unsigned long long)refreshed,
                (unsigned long long)certified, (unsigned long long)tracked);
    EXPECT_GT(refreshed, 1000u);
    EXPECT_GT(certified, 10000u);  // most apart steps need no walk
}

TEST(ConvexContact, TheSeparationCertificateRefusesTouchingCorners) {
    // Two squares corner to corner, then touching along a face: never certified apart.
    const std::vector<Vec2> sq = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    FeatureStats stats;
    FeatureCache cache;
    cache.state = FeatureCache::Apart;
    cache.f[0] = 4;  // A's corner 2 (1, 1) + centre
    cache.f[1] = 0;  // B's corner 0 (-1, -1) + centre
    const auto A = frame(sq, {0, 0}, 0), far = frame(sq, {2.5, 2.5}, 0), touching = frame(sq, {2, 2}, 0);
    EXPECT_TRUE(crossings::stillApart(A, far, cache, stats));
    EXPECT_FALSE(crossings::stillApart(A, touching, cache, stats));  // the corners coincide
    cache.f[0] = 3;                                                  // A's edge 1: x = 1
    cache.f[1] = 0;
    const auto flush = frame(sq, {2, 0.5}, 0), beyond = frame(sq, {2.001, 0.5}, 0);
    EXPECT_FALSE(crossings::stillApart(A, flush, cache, stats));  // on the line: not strictly outside
    EXPECT_TRUE(crossings::stillApart(A, beyond, cache, stats));
    const auto tilted = frame(sq, {2.3, 0.5}, 0.5);  // B's corner 0 is not its extreme toward A
    EXPECT_FALSE(crossings::stillApart(A, tilted, cache, stats));
}

TEST(ConvexContact, PersistentContactCostIndependentOfCornerCount) {
    // A 64-gon and a 7-gon rolling slowly on a floor: feature tests per step stay ~constant.
    for (int n : {8, 64, 512}) {
        const auto disk = regular(n, 1.0);
        const std::vector<Vec2> floor = {{-50, -5}, {50, -5}, {50, 5}, {-50, 5}};
        FeatureCache cache;
        FeatureStats stats;
        const int steps = 5000;
        for (int s = 0; s < steps; ++s) {
            const Real ang = -0.002 * s;  // rolling to the right
            const auto A = frame(disk, {0.002 * s, std::cos(kPi / n) - 1e-3}, ang),
                       B = frame(floor, {0, -5}, 0);
            const auto got = trackPolygonContact(A, B, cache, stats);
            ASSERT_TRUE(got.touching) << n << " step " << s;
        }
        const double perStep = double(stats.iterations) / steps;
        std::printf("%d-gon rolling: %.3f feature tests per step, %llu cold starts\n", n, perStep,
                    (unsigned long long)stats.coldStarts);
        EXPECT_EQ(stats.coldStarts, 1u);
        EXPECT_LT(perStep, 4.0);
    }
}

TEST(ConvexContact, NearMissIsConstantTime) {
    const auto a = regular(256, 1.0), b = regular(256, 1.0, 0.01);
    FeatureCache cache;
    FeatureStats stats;
    for (int s = 0; s < 1000; ++s) {
        const auto A = frame(a, {2.001 + 1e-4 * std::sin(0.01 * s), 0}, 0.001 * s), B = frame(b, {0, 0}, 0);
        ASSERT_FALSE(trackPolygonContact(A, B, cache, stats).touching);
    }
    EXPECT_EQ(stats.coldStarts, 1u);
    EXPECT_LT(double(stats.iterations - 256 * 256) / 1000.0, 4.0);
}

TEST(ConvexContact, RodsEndToEndAndContainment) {
    const std::vector<Vec2> rod = {{-5, -0.1}, {5, -0.1}, {5, 0.1}, {-5, 0.1}};
    const std::vector<Vec2> thin = {{-5, -0.05}, {5, -0.05}, {5, 0.05}, {-5, 0.05}};
    const auto A = frame(thin, {9.95, 0.01}, 0), B = frame(rod, {0, 0}, 0);
    const auto c = polygonContact(A, B);
    ASSERT_TRUE(c.touching);
    EXPECT_GT(c.normal.x, 0.99);  // along the rods, not across them
    const std::vector<Vec2> small = {{-0.05, -0.05}, {0.05, -0.05}, {0.05, 0.05}, {-0.05, 0.05}};
    const auto in = polygonContact(frame(small, {1, 0}, 0.3), frame(rod, {0, 0}, 0));
    ASSERT_TRUE(in.touching);
    EXPECT_NEAR(in.area, 0.01, 1e-15);
}
