// SPDX-License-Identifier: MIT
// Wall drivers follow their closed forms (gc2d spec 6.4, 6.3; docs/physics/walls.md): vibration
// profiles (COSINUS, SAWTOOTH, TAPPING, TRIANGLE with the erratum fixed) sampled at 100 times,
// their velocity against a central difference, constant velocity and rotation; the state
// checkpoint re-anchors a changed driver without a jump.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "model/walls.hpp"

namespace granulab::model {
namespace {

/// The profiles written out again, independently of walls.cpp (spec 6.4).
Real expectedDisplacement(VibrationType type, Real W, Real f, Real t) {
    const Real u = t * f - std::floor(t * f);
    switch (type) {
        case VibrationType::Cosine:
            return W * 0.5 * (1 - std::cos(2 * kPi * f * t));
        case VibrationType::Sawtooth:
            return W * u;
        case VibrationType::Tapping:
            return W * std::pow(std::sin(2 * kPi * f * t), 30);
        case VibrationType::Triangle:
            return u < 0.5 ? 2 * W * u : 2 * W * (1 - u);
    }
    return 0;
}

WallSet floorWith(const WallDriver& d) {
    WallSet w;
    w.addPolyline("floor", {{0, 0}, {1, 0}}, false, 0, {});
    w.setDriver(0, d);
    return w;
}

class VibrationProfile : public ::testing::TestWithParam<VibrationType> {};

TEST_P(VibrationProfile, FollowsClosedFormAt100Times) {
    WallDriver d;
    d.kind = WallDriver::Kind::Vibration;
    d.vibration = GetParam();
    d.width = 1e-4;  // [m] 0.1 mm, 20 Hz: the tapping of gc2d 4.3.1
    d.frequency = 20;
    d.direction = {0, 1};
    d.from = 0.01;
    d.to = 0.4;
    WallSet w = floorWith(d);
    for (int k = 0; k < 100; ++k) {
        const Real t = 0.5 * k / 99.0 + 1e-4;  // before, inside and after the window
        w.place(t);
        const Real tc = std::clamp(t, d.from, d.to);
        const Real expected = expectedDisplacement(d.vibration, d.width, d.frequency, tc);
        EXPECT_NEAR(w.walls[0].displacement.y, expected, 1e-12 * d.width + 1e-18) << "t = " << t;
        EXPECT_EQ(w.walls[0].displacement.x, 0.0);
        EXPECT_NEAR(w.segments[0].a.y, expected, 1e-15);
        // Velocity: the analytic dA/dt inside the window (central difference away from kinks), 0 outside.
        const Real v = w.walls[0].velocity.y;
        if (t <= d.from || t >= d.to) {
            EXPECT_EQ(v, 0.0);
            continue;
        }
        const Real h = 1e-7;
        const Real phase = (t * d.frequency) - std::floor(t * d.frequency);
        const bool nearKink = phase < 1e-4 || phase > 1 - 1e-4 || std::abs(phase - 0.5) < 1e-4;
        if (nearKink) continue;
        const Real fd = (expectedDisplacement(d.vibration, d.width, d.frequency, t + h) -
                         expectedDisplacement(d.vibration, d.width, d.frequency, t - h)) /
                        (2 * h);
        EXPECT_NEAR(v, fd, 1e-6 * vibrationMaxSpeed(d) + 1e-12) << "t = " << t;
        EXPECT_LE(std::abs(v), vibrationMaxSpeed(d) * (1 + 1e-12));
    }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, VibrationProfile,
                         ::testing::Values(VibrationType::Cosine, VibrationType::Sawtooth,
                                           VibrationType::Tapping, VibrationType::Triangle));

TEST(WallDriver, TappingMaxSpeedIsTheMaximum) {
    WallDriver d;
    d.kind = WallDriver::Kind::Vibration;
    d.vibration = VibrationType::Tapping;
    d.width = 2;
    d.frequency = 3;
    Real best = 0;
    for (int k = 0; k < 200000; ++k) best = std::max(best, std::abs(vibrationAt(d, k * 1e-6).velocity));
    EXPECT_NEAR(best, vibrationMaxSpeed(d), 1e-6 * best);
}

TEST(WallDriver, ConstantVelocityAndRotation) {
    WallDriver v;
    v.kind = WallDriver::Kind::Velocity;
    v.velocity = {0.3, -0.1};
    WallSet w = floorWith(v);
    for (int k = 0; k < 100; ++k) {
        const Real t = 0.01 * k;
        w.place(t);
        EXPECT_DOUBLE_EQ(w.segments[0].b.x, 1 + 0.3 * t);
        EXPECT_DOUBLE_EQ(w.segments[0].b.y, -0.1 * t);
    }
    WallDriver r;
    r.kind = WallDriver::Kind::Rotation;
    r.pivot = {0, 0};
    r.omega = 2.0;
    WallSet rot = floorWith(r);
    for (int k = 0; k < 100; ++k) {
        const Real t = 0.01 * k;
        rot.place(t);
        EXPECT_NEAR(rot.segments[0].b.x, std::cos(2 * t), 1e-15);
        EXPECT_NEAR(rot.segments[0].b.y, std::sin(2 * t), 1e-15);
        const Vec2 vb = rot.velocityAt(0, rot.segments[0].b);  // omega z x r
        EXPECT_NEAR(vb.x, -2 * std::sin(2 * t), 1e-14);
        EXPECT_NEAR(vb.y, 2 * std::cos(2 * t), 1e-14);
    }
}

TEST(WallDriver, PistonMovesAtMaxSpeedUntilItFeelsForceAndStopsAtTarget) {
    WallDriver p;
    p.kind = WallDriver::Kind::Piston;
    p.direction = {0, -1};
    p.targetForce = 10;
    p.maxSpeed = 0.5;
    p.gain = 0.5 / 1.0;
    WallSet w = floorWith(p);
    const Real dt = 1e-3;
    w.advance(dt, dt, {Vec2{0, 0}});  // no resistance: full speed down
    EXPECT_DOUBLE_EQ(w.walls[0].velocity.y, -0.5);
    EXPECT_DOUBLE_EQ(w.walls[0].displacement.y, -0.5 * dt);
    w.advance(2 * dt, dt, {Vec2{0, 10}});  // grains push up with the target force: rest
    EXPECT_DOUBLE_EQ(w.walls[0].velocity.y, 0.0);
    w.advance(3 * dt, dt, {Vec2{0, 10.4}});  // too much force: back off, v = gain (F_t - F)
    EXPECT_NEAR(w.walls[0].velocity.y, 0.5 * 0.4, 1e-12);
}

TEST(WallDriver, ResumeWithAChangedVelocityContinuesWhereTheWallIs) {
    WallDriver v;
    v.kind = WallDriver::Kind::Velocity;
    v.velocity = {0.5, 0};
    WallSet before = floorWith(v);
    before.place(2.0);
    std::stringstream state;
    before.save(state);
    // Same driver: bit-for-bit continuation.
    WallSet same = floorWith(v);
    same.load(state, 2.0);
    same.place(3.0);
    before.place(3.0);
    EXPECT_EQ(same.segments[0].a.x, before.segments[0].a.x);
    // Changed velocity: no jump at the resume time, then the new velocity.
    state.clear();
    state.seekg(0);
    WallDriver faster = v;
    faster.velocity = {2.0, 0};
    WallSet changed = floorWith(faster);
    changed.load(state, 2.0);
    EXPECT_DOUBLE_EQ(changed.segments[0].a.x, 1.0);  // 0.5 m/s x 2 s
    changed.place(3.0);
    EXPECT_DOUBLE_EQ(changed.segments[0].a.x, 3.0);  // + 2 m/s x 1 s
}

TEST(WallDriver, PolygonBodyKeepsCentroidAndInradius) {
    WallSet w;
    w.addPolygon("block", {{0, 0}, {2, 0}, {2, 1}, {0, 1}}, 0);
    ASSERT_TRUE(w.walls[0].body);
    EXPECT_DOUBLE_EQ(w.bodyCentroid[0].x, 1.0);
    EXPECT_DOUBLE_EQ(w.bodyCentroid[0].y, 0.5);
    EXPECT_DOUBLE_EQ(w.bodyInradius[0], 0.5);
    WallDriver v;
    v.kind = WallDriver::Kind::Velocity;
    v.velocity = {1, 0};
    w.setDriver(0, v);
    w.place(0.25);
    EXPECT_DOUBLE_EQ(w.bodyCentroid[0].x, 1.25);
    EXPECT_DOUBLE_EQ(w.corners[2].x, 2.25);
}

}  // namespace
}  // namespace granulab::model
