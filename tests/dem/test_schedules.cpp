// SPDX-License-Identifier: MIT
// Gravity schedules (gc2d spec 6.6, the recommended phase) against their formulas at sample
// times, and the direction turning over the tilt window.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/schedules.hpp"

namespace granulab::dem {
namespace {

GravitySchedule figB1(
    GravitySchedule::Type type) {  // gc2d Fig. B.1: G 9.81 9.0, G_TIME 0.1 1.1, G_PARAMETER 5 0.2
    GravitySchedule g;
    g.type = type;
    g.g1 = 9.81;
    g.g2 = 9.0;
    g.t1 = 0.1;
    g.t2 = 1.1;
    g.steps = 5;
    g.ramp = 0.2;
    return g;
}

TEST(GravitySchedule, MatchesTheFormulasAt101Times) {
    for (const auto type : {GravitySchedule::Type::Constant, GravitySchedule::Type::Linear,
                            GravitySchedule::Type::Step, GravitySchedule::Type::SmoothStep}) {
        const GravitySchedule g = figB1(type);
        for (int k = 0; k <= 100; ++k) {
            const Real t = 1.3 * k / 100.0;
            const Real tau = std::clamp((t - 0.1) / 1.0, 0.0, 1.0);
            const Real kk = std::min(std::floor(5 * tau), 5.0), u = 5 * tau - kk;
            Real expected = 9.81;
            if (type == GravitySchedule::Type::Linear) expected = 9.81 + (9.0 - 9.81) * tau;
            if (type == GravitySchedule::Type::Step) expected = 9.81 + (9.0 - 9.81) * kk / 5;
            if (type == GravitySchedule::Type::SmoothStep)
                expected =
                    9.81 + (9.0 - 9.81) * (kk + (kk < 5 ? std::clamp((u - 0.8) / 0.2, 0.0, 1.0) : 0.0)) / 5;
            EXPECT_NEAR(gravityMagnitude(g, t), expected, 1e-12) << "type " << int(type) << " t = " << t;
        }
    }
}

TEST(GravitySchedule, EndpointsAndLimits) {
    GravitySchedule g = figB1(GravitySchedule::Type::SmoothStep);
    EXPECT_DOUBLE_EQ(gravityMagnitude(g, 0.0), 9.81);
    EXPECT_DOUBLE_EQ(gravityMagnitude(g, 2.0), 9.0);
    g.ramp = 1;  // p2 = 1 is LINEAR
    GravitySchedule lin = figB1(GravitySchedule::Type::Linear);
    for (int k = 0; k <= 50; ++k)
        EXPECT_NEAR(gravityMagnitude(g, 0.1 + k / 50.0), gravityMagnitude(lin, 0.1 + k / 50.0), 1e-12);
    g.ramp = 0;  // p2 = 0 is STEP
    GravitySchedule step = figB1(GravitySchedule::Type::Step);
    for (int k = 0; k <= 50; ++k)
        EXPECT_NEAR(gravityMagnitude(g, 0.1 + k / 50.0 + 1e-9), gravityMagnitude(step, 0.1 + k / 50.0 + 1e-9),
                    1e-12);
}

TEST(GravitySchedule, DirectionTiltsLinearly) {
    GravitySchedule g;
    g.g1 = g.g2 = 10;
    g.direction1 = -kPi / 2;
    g.direction2 = -kPi / 2 + 0.3;  // tilt by 0.3 rad
    g.tilt1 = 1;
    g.tilt2 = 2;
    for (int k = 0; k <= 30; ++k) {
        const Real t = 3.0 * k / 30;
        const Real a = -kPi / 2 + 0.3 * std::clamp(t - 1, 0.0, 1.0);
        const Vec2 v = gravityAt(g, t);
        EXPECT_NEAR(v.x, 10 * std::cos(a), 1e-12);
        EXPECT_NEAR(v.y, 10 * std::sin(a), 1e-12);
    }
}

}  // namespace
}  // namespace granulab::dem

namespace granulab::dem {
namespace {

TEST(SizeScaling, MatchesEqB2AtSampleTimes) {
    SizeCycle c;
    c.amplitude = 0.05;
    c.frequency = 2;
    c.slope = 4;
    c.t1 = 0.1;
    c.t2 = 2.0;
    for (int k = 0; k <= 100; ++k) {
        const Real t = 2.5 * k / 100.0;
        const Real tc = std::clamp(t, 0.1, 2.0);
        const Real expected = 1 + 0.05 * (0.5 - 0.5 * std::tanh(4 * std::cos(2 * kPi * 2 * tc)));
        EXPECT_NEAR(sizeScale(c, t), expected, 1e-15) << "t = " << t;
    }
}

}  // namespace
}  // namespace granulab::dem
