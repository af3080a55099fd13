// SPDX-License-Identifier: MIT
// cos and sin of a body's angle through an exact split into k/64 rad and a small rest
// (geom/rotation.hpp): accuracy against the library's sin and cos, the exact split at the
// boundaries of a step, and a cache that gives the same bits as the pure function in any order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/rng.hpp"
#include "geom/rotation.hpp"

namespace granulab::geom {
namespace {

// Both the split and the library round each of cos(k h), sin(k h) and the composition once or
// twice: a few units in the last place of 1 (2.2e-16) apart at most.
constexpr Real kTolerance = 4.5e-16;

void expectNearLibrary(Real angle) {
    const CosSin r = rotationOf(angle);
    EXPECT_NEAR(r.c, std::cos(angle), kTolerance) << "angle " << angle;
    EXPECT_NEAR(r.s, std::sin(angle), kTolerance) << "angle " << angle;
}

TEST(Rotation, MatchesTheLibraryOverManyTurnsAndSmallAngles) {
    CounterRng rng(20261205, 0);
    for (int k = 0; k < 20000; ++k) {
        expectNearLibrary(rng.uniform(-20.0, 20.0));
        expectNearLibrary(rng.uniform(-1e4, 1e4));  // a grain in a drum after many turns
        expectNearLibrary(rng.uniform(-1e-3, 1e-3));
    }
    for (const Real a : {0.0, -0.0, 1e-300, 4.9e-324, 1.0, -1.0, 3.141592653589793, 1e6})
        expectNearLibrary(a);
    EXPECT_EQ(rotationOf(0.0).c, 1.0);
    EXPECT_EQ(rotationOf(0.0).s, 0.0);
}

TEST(Rotation, TheRestIsExactAtTheEdgesOfAStep) {
    // Halfway between two steps and just beside: the rest stays within 1/128 rad and is exact.
    for (const Real k : {0.0, 1.0, -1.0, 7.0, 1000.0, -123456.0}) {
        for (const Real off : {0.5, -0.5, 0.4999999999999999, -0.4999999999999999, 1e-17, 0.0}) {
            const Real angle = (k + off) / rotation::kStepsPerRadian;
            Real delta = 0;
            const std::int64_t step = rotation::stepOf(angle, delta);
            EXPECT_LE(std::abs(delta), 0.5 / rotation::kStepsPerRadian);
            EXPECT_EQ(static_cast<Real>(step) / rotation::kStepsPerRadian + delta, angle);
            expectNearLibrary(angle);
        }
    }
}

TEST(Rotation, HugeAndNonFiniteAnglesUseTheLibrary) {
    for (const Real a : {1e20, -3e17, std::numeric_limits<Real>::infinity()}) {
        const CosSin r = rotationOf(a);
        if (std::isfinite(a)) {
            EXPECT_EQ(r.c, std::cos(a));
            EXPECT_EQ(r.s, std::sin(a));
        } else {
            EXPECT_TRUE(std::isnan(r.c) && std::isnan(r.s));
        }
    }
    EXPECT_TRUE(std::isnan(rotationOf(std::numeric_limits<Real>::quiet_NaN()).c));
}

TEST(Rotation, TheCacheGivesThePureFunctionBitForBitWhateverTheSlotHeldBefore) {
    // Slots reused by other bodies (reordering, removal), angles moving by small and large steps.
    CounterRng rng(7, 0);
    RotationCache cache;
    cache.resize(16);
    std::vector<Real> angle(16);
    for (Real& a : angle) a = rng.uniform(-10.0, 10.0);
    for (int step = 0; step < 5000; ++step) {
        for (std::size_t i = 0; i < angle.size(); ++i) {
            angle[i] += rng.uniform(-1e-3, 1e-3);
            if (rng.uniform(0.0, 1.0) < 0.01) angle[i] = rng.uniform(-100.0, 100.0);  // another body
            const CosSin cached = cache(i, angle[i]);
            const CosSin pure = rotationOf(angle[i]);
            ASSERT_EQ(cached.c, pure.c);
            ASSERT_EQ(cached.s, pure.s);
        }
    }
    cache.resize(40);  // grown: the new slots start empty
    const CosSin fresh = cache(39, 2.5);
    EXPECT_EQ(fresh.c, rotationOf(2.5).c);
    EXPECT_EQ(fresh.s, rotationOf(2.5).s);
}

}  // namespace
}  // namespace granulab::geom
