// SPDX-License-Identifier: MIT
// Event times and collision rules of hard disks and spheres (edmd spec sections 2.5 and 2.8):
// collision times against a brute-force root search, grazing and overlapping cases, growing
// spheres, parabolic wall passages; free flight in the engine's rounding order; collision rules
// conserve momentum and total (orbital + spin) angular momentum, lose (m/4)(1 - eps^2) v_n^2,
// and conserve energy for eps = 1, phi = +-1.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "edmd/kinematics.hpp"

using namespace granulab;
using namespace granulab::edmd;

namespace {
/// First time in [0, tmax] at which f changes sign, by fine sampling and bisection; +inf if none.
template <class F>
Real firstRoot(F f, Real tmax) {
    const int n = 200000;
    Real prev = f(0.0);
    for (int k = 1; k <= n; ++k) {
        const Real t = tmax * k / n, cur = f(t);
        if ((prev > 0) != (cur > 0)) {
            Real lo = tmax * (k - 1) / n, hi = t;
            for (int it = 0; it < 200; ++it) {
                const Real mid = 0.5 * (lo + hi);
                ((f(mid) > 0) == (f(lo) > 0) ? lo : hi) = mid;
            }
            return 0.5 * (lo + hi);
        }
        prev = cur;
    }
    return kNoEvent;
}
}  // namespace

TEST(EdmdKinematics, PairCollisionTimeMatchesRootSearch) {
    CounterRng rng(3, 0);
    int hits = 0;
    for (int trial = 0; trial < 300; ++trial) {
        VecD<3> r, v;
        for (int k = 0; k < 3; ++k) r[k] = rng.uniform(-3, 3);
        for (int k = 0; k < 3; ++k) v[k] = -0.3 * r[k] + rng.uniform(-0.5, 0.5);  // mostly approaching
        const Real s = rng.uniform(0.5, 1.5);
        if (dot(r, r) <= s * s) continue;
        const Real t = pairCollisionTime(r, v, s);
        const Real ref = firstRoot(
            [&](Real x) {
                const auto d = r + v * x;
                return dot(d, d) - s * s;
            },
            20.0);
        if (std::isinf(ref)) {
            EXPECT_TRUE(std::isinf(t) || t > 20) << trial;
        } else {
            ++hits;
            EXPECT_NEAR(t, ref, 1e-9 * (1 + ref)) << trial;
        }
    }
    EXPECT_GT(hits, 20);
    // Overlapping by round-off while approaching: now. Separating: never. Grazing miss: never.
    EXPECT_EQ(pairCollisionTime(VecD<2>{{0.999999, 0}}, VecD<2>{{-1, 0}}, 1.0), 0.0);
    EXPECT_TRUE(std::isinf(pairCollisionTime(VecD<2>{{0.999999, 0}}, VecD<2>{{1, 0}}, 1.0)));
    EXPECT_TRUE(std::isinf(pairCollisionTime(VecD<2>{{5, 1.0000001}}, VecD<2>{{-1, 0}}, 1.0)));
    // Far away and slow: no cancellation (c / (-b + sqrt(disc))).
    // (head on, the discriminant cancels to 1e-12 of b^2: the time keeps ~1e-11 relative)
    EXPECT_NEAR(pairCollisionTime(VecD<2>{{1e6, 0}}, VecD<2>{{-1e-3, 0}}, 1.0), (1e6 - 1) / 1e-3,
                1e-10 * 1e9);
}

TEST(EdmdKinematics, GrowingSpheresMeetAtTheSmallestNonNegativeRoot) {
    // Resting spheres 3 apart, contact distance 2 growing at 0.5: touch at t = 2.
    EXPECT_NEAR(growingPairCollisionTime(VecD<3>{{3, 0, 0}}, VecD<3>{{0, 0, 0}}, 2.0, 0.5), 2.0, 1e-14);
    // Receding at 0.25 while growing at 0.5: relative gap closes at 0.25: t = 4.
    EXPECT_NEAR(growingPairCollisionTime(VecD<3>{{3, 0, 0}}, VecD<3>{{0.25, 0, 0}}, 2.0, 0.5), 4.0, 1e-13);
    // Shrinking faster than approaching: never.
    EXPECT_TRUE(std::isinf(growingPairCollisionTime(VecD<3>{{3, 0, 0}}, VecD<3>{{-0.1, 0, 0}}, 2.0, -0.5)));
    CounterRng rng(4, 0);
    for (int trial = 0; trial < 200; ++trial) {
        VecD<2> r{{rng.uniform(-3, 3), rng.uniform(-3, 3)}}, v{{rng.uniform(-1, 1), rng.uniform(-1, 1)}};
        const Real s = 1.0, us = rng.uniform(-0.3, 0.3);
        if (dot(r, r) <= s * s) continue;
        const Real t = growingPairCollisionTime(r, v, s, us);
        const Real ref = firstRoot(
            [&](Real x) {
                const auto d = r + v * x;
                return dot(d, d) - (s + us * x) * (s + us * x);
            },
            3.0);
        if (!std::isinf(ref))
            EXPECT_NEAR(t, ref, 1e-9) << trial;
        else
            EXPECT_TRUE(std::isinf(t) || t > 3 || s + us * t <= 0) << trial;
    }
}

TEST(EdmdKinematics, FreeFlightIsTheLineOrTheParabolaInTheEnginesRoundingOrder) {
    // Thrown up at 3 m/s under g = -9.81 from 0.5 m: apex at t = 3/9.81, height 0.5 + 9/19.62.
    const Real tApex = 3 / 9.81;
    EXPECT_NEAR(flightPosition(0.5, 3.0, -9.81, tApex), 0.5 + 9 / 19.62, 1e-14);
    EXPECT_NEAR(flightVelocity(3.0, -9.81, tApex), 0.0, 1e-14);
    EXPECT_EQ(flightPosition(0.5, 3.0, 0.0, 2.0), flightPosition(0.5, 3.0, 2.0));
    EXPECT_EQ(flightPosition(0.5, 3.0, 2.0), 6.5);
    EXPECT_EQ(flightVelocity(3.0, -9.81, 0.0), 3.0);
    // The order is part of the contract (bit-identical runs): (x + v dt) + ((g/2) dt) dt.
    CounterRng rng(8, 0);
    for (int trial = 0; trial < 1000; ++trial) {
        const Real x = rng.uniform(-10, 10), v = rng.uniform(-5, 5), g = rng.uniform(-20, 20),
                   dt = rng.uniform(0, 3);
        const Real line = x + v * dt;
        EXPECT_EQ(flightPosition(x, v, dt), line);
        EXPECT_EQ(flightPosition(x, v, g, dt), line + 0.5 * g * dt * dt);
        EXPECT_EQ(flightVelocity(v, g, dt), v + g * dt);
    }
    // Whole particles: componentwise; two flights make one up to round-off.
    VecD<3> x{{1, 2, 3}}, v{{0.5, -1, 2}};
    const VecD<3> g{{0, 0, -9.81}};
    VecD<3> xl = x, vl = v;
    freeFlight<false>(xl, vl, g, 0.25);  // g ignored
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(xl[k], flightPosition(x[k], v[k], 0.25));
        EXPECT_EQ(vl[k], v[k]);
    }
    VecD<3> xp = x, vp = v;
    freeFlight<true>(xp, vp, g, 0.25);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(xp[k], flightPosition(x[k], v[k], g[k], 0.25));
        EXPECT_EQ(vp[k], flightVelocity(v[k], g[k], 0.25));
    }
    freeFlight<true>(xp, vp, g, 0.5);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(xp[k], x[k] + v[k] * 0.75 + 0.5 * g[k] * 0.75 * 0.75, 1e-14);
        EXPECT_NEAR(vp[k], v[k] + g[k] * 0.75, 1e-14);
    }
    VecD<2> x2{{1, 2}}, v2{{3, 4}};
    freeFlight<true>(x2, v2, VecD<2>{{0, -1}}, 2.0);
    EXPECT_EQ(x2[0], 7.0);
    EXPECT_EQ(x2[1], 8.0);
    EXPECT_EQ(v2[1], 2.0);
}

TEST(EdmdKinematics, FirstPassageUnderGravity) {
    EXPECT_NEAR(firstPassage(0, 2, 0, 1), 0.5, 1e-15);
    EXPECT_TRUE(std::isinf(firstPassage(0, -2, 0, 1)));
    // Thrown up at 2 m/s under g = -9.81: reaches 0.1 m on the way up.
    const Real t = firstPassage(0, 2, -9.81, 0.1);
    EXPECT_NEAR(2 * t - 0.5 * 9.81 * t * t, 0.1, 1e-14);
    EXPECT_LT(t, 2 / 9.81);
    // Too high: turns back before the plane.
    EXPECT_TRUE(std::isinf(firstPassage(0, 2, -9.81, 1.0)));
    // Falling away but pulled up (g > 0 along the normal): passes later.
    const Real u = firstPassage(0, -1, 2, 0.5);
    EXPECT_NEAR(-u + u * u, 0.5, 1e-14);
}

TEST(EdmdKinematics, SmoothCollisionConservesMomentumAndLosesTheRightEnergy) {
    CounterRng rng(5, 0);
    for (int trial = 0; trial < 100; ++trial) {
        VecD<3> v1{{rng.normal(), rng.normal(), rng.normal()}},
            v2{{rng.normal(), rng.normal(), rng.normal()}};
        VecD<3> k{{rng.normal(), rng.normal(), rng.normal()}};
        k = k * (1 / std::sqrt(dot(k, k)));
        if (dot(v1 - v2, k) >= 0) k = k * -1.0;  // approaching
        const Real m1 = rng.uniform(0.5, 2), m2 = rng.uniform(0.5, 2), eps = rng.uniform(0, 1);
        const Real vn = dot(v1 - v2, k);
        const auto p0 = v1 * m1 + v2 * m2;
        const Real e0 = 0.5 * m1 * dot(v1, v1) + 0.5 * m2 * dot(v2, v2);
        smoothCollision(v1, v2, m1, m2, k, eps);
        const auto dp = v1 * m1 + v2 * m2 - p0;
        EXPECT_LT(std::sqrt(dot(dp, dp)), 1e-14);
        EXPECT_NEAR(dot(v1 - v2, k), -eps * vn, 1e-14);
        const Real e1 = 0.5 * m1 * dot(v1, v1) + 0.5 * m2 * dot(v2, v2);
        EXPECT_NEAR(e0 - e1, 0.5 * (m1 * m2 / (m1 + m2)) * (1 - eps * eps) * vn * vn, 1e-13);
    }
}

TEST(EdmdKinematics, RoughCollisionConservesAngularMomentumAndEnergyAtTheLimits) {
    CounterRng rng(6, 0);
    const Real m = 1.3, a = 0.7;
    for (const Real z : {0.4, 0.5}) {
        for (int trial = 0; trial < 100; ++trial) {
            Vec3 k{{rng.normal(), rng.normal(), z == 0.5 ? 0.0 : rng.normal()}};
            k = k * (1 / std::sqrt(dot(k, k)));
            Vec3 v1{{rng.normal(), rng.normal(), z == 0.5 ? 0.0 : rng.normal()}},
                v2{{rng.normal(), rng.normal(), z == 0.5 ? 0.0 : rng.normal()}};
            Vec3 w1{{z == 0.5 ? 0.0 : rng.normal(), z == 0.5 ? 0.0 : rng.normal(), rng.normal()}};
            Vec3 w2{{z == 0.5 ? 0.0 : rng.normal(), z == 0.5 ? 0.0 : rng.normal(), rng.normal()}};
            if (dot(v1 - v2, k) >= 0) k = k * -1.0;
            const Vec3 r2{{0.3, -0.2, 0.1}}, r1 = r2 + k * (2 * a);  // k points from 2 to 1
            const Real I = z * m * a * a;
            const auto angular = [&] {
                return crossProduct(r1, v1) * m + crossProduct(r2, v2) * m + (w1 + w2) * I;
            };
            const auto energy = [&] {
                return 0.5 * m * (dot(v1, v1) + dot(v2, v2)) + 0.5 * I * (dot(w1, w1) + dot(w2, w2));
            };
            const Real eps = trial % 3 == 0 ? 1.0 : rng.uniform(0, 1);
            const Real phi = trial % 2 == 0 ? (trial % 4 == 0 ? 1.0 : -1.0) : rng.uniform(-1, 1);
            const Vec3 L0 = angular();
            const Real E0 = energy();
            roughCollision(v1, v2, w1, w2, k, a, eps, phi, z);
            const Vec3 dL = angular() - L0;
            EXPECT_LT(std::sqrt(dot(dL, dL)), 1e-13) << "z " << z << " trial " << trial;
            if (eps == 1.0 && (phi == 1.0 || phi == -1.0))
                EXPECT_NEAR(energy(), E0, 1e-13 * E0) << trial;
            else
                EXPECT_LE(energy(), E0 * (1 + 1e-14)) << trial;
        }
    }
}

TEST(EdmdKinematics, ClosingTimeIsTheSmallestPositiveRoot) {
    CounterRng rng(21, 0);
    for (int k = 0; k < 20000; ++k) {
        const Real s = rng.uniform(0, 1), u = rng.uniform(-2, 2), gw = k % 3 == 0 ? 0 : rng.uniform(-3, 3);
        const Real t = closingTime(s, u, gw);
        // Brute force: first sign change of s - u t - gw t^2/2 on a fine grid up to 10 s.
        Real reference = kNoEvent;
        const int steps = 200000;
        for (int n = 1; n <= steps; ++n) {
            const Real tt = 10.0 * n / steps;
            if (s - u * tt - 0.5 * gw * tt * tt <= 0) {
                reference = tt;
                break;
            }
        }
        if (k > 300) break;  // the grid search is slow; a few hundred cases suffice
        if (reference == kNoEvent)
            EXPECT_TRUE(t == kNoEvent || t > 10 - 1e-4) << s << " " << u << " " << gw;
        else
            EXPECT_NEAR(t, reference, 10.0 / steps) << s << " " << u << " " << gw;
    }
    EXPECT_EQ(closingTime(0, 1, 0), 0);                   // touching and closing: now
    EXPECT_EQ(closingTime(0, -1, 0), kNoEvent);           // touching and opening: never
    EXPECT_EQ(closingTime(0, 0, 0), kNoEvent);            // at rest on the plane without gravity: never
    EXPECT_NEAR(closingTime(-1e-15, -1, 2), 1.0, 1e-12);  // opening, gravity brings it back
}

TEST(EdmdKinematics, GeneralRoughRuleMatchesTheEqualSphereRuleAndConservesAngularMomentum) {
    CounterRng rng(22, 0);
    auto randomVec = [&] { return Vec3{{rng.normal(), rng.normal(), rng.normal()}}; };
    for (int k = 0; k < 1000; ++k) {
        Vec3 n = randomVec();
        n = n * (1 / std::sqrt(dot(n, n)));
        const Real eps = rng.uniform(0, 1), phi = rng.uniform(-1, 1), z = 0.4;
        // Equal spheres: the thesis rule (2.6-2.8) and the general one agree.
        const Real a = 0.3, m = 2.0;
        Vec3 v1 = randomVec(), v2 = randomVec(), w1 = randomVec(), w2 = randomVec();
        if (dot(v1 - v2, n) > 0) std::swap(v1, v2);
        Vec3 u1 = v1, u2 = v2, o1 = w1, o2 = w2;
        roughCollision(v1, v2, w1, w2, n, a, eps, phi, z);
        const Real jn = (1 + eps) * (-dot(u1 - u2, n)) * m / 2;
        roughCollisionGeneral(u1, u2, o1, o2, n, a, a, m, m, z, jn, phi);
        for (int d = 0; d < 3; ++d) {
            EXPECT_NEAR(u1[d], v1[d], 1e-12);
            EXPECT_NEAR(o2[d], w2[d], 1e-12);
        }
        // Unequal spheres: angular momentum about the contact point and momentum conserved;
        // eps = 1, phi = 1 conserves energy.
        const Real a1 = rng.uniform(0.1, 1), a2 = rng.uniform(0.1, 1), m1 = rng.uniform(0.5, 3),
                   m2 = rng.uniform(0.5, 3);
        const Vec3 r1 = n * a1, r2 = n * (-a2);  // centres relative to the contact point
        Vec3 p1 = randomVec(), p2 = randomVec(), s1 = randomVec(), s2 = randomVec();
        if (dot(p1 - p2, n) > 0) std::swap(p1, p2);
        auto angular = [&] {
            return crossProduct(r1, p1) * m1 + crossProduct(r2, p2) * m2 + s1 * (z * m1 * a1 * a1) +
                   s2 * (z * m2 * a2 * a2);
        };
        auto energy = [&] {
            return 0.5 * (m1 * dot(p1, p1) + m2 * dot(p2, p2) + z * m1 * a1 * a1 * dot(s1, s1) +
                          z * m2 * a2 * a2 * dot(s2, s2));
        };
        const Vec3 L0 = angular();
        const Real E0 = energy();
        const bool conservative = k % 2 == 0;
        const Real e = conservative ? 1 : eps, f = conservative ? 1 : phi;
        const Real j = (1 + e) * (-dot(p1 - p2, n)) * m1 * m2 / (m1 + m2);
        roughCollisionGeneral(p1, p2, s1, s2, n, a1, a2, m1, m2, z, j, f);
        const Vec3 L1 = angular();
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(L1[d], L0[d], 1e-12 * (1 + std::abs(L0[d])));
        if (conservative)
            EXPECT_NEAR(energy(), E0, 1e-12 * E0);
        else
            EXPECT_LE(energy(), E0 * (1 + 1e-12));
    }
}
