// SPDX-License-Identifier: MIT
// Validation of the gc2d friction law on polygons (gc2d spec sections 3.4, 3.8 and 8.2 items 1
// and 2): a block on an incline starts to slide at arctan(mu), and a block pulled by a slowly
// moving spring starts to move when the spring force reaches mu m g.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../support.hpp"

using namespace granulab;

namespace {

constexpr Real kG = 9.81;

/// A 2 cm x 1 cm block (areal density 5000 kg/m^2: m = 1 kg) resting on a floor, gravity tilted
/// by theta (equivalent to tilting the plane; +x is downhill).
std::string inclineScene(Real mu, Real theta) {
    return fmt::format(R"(
[run]
end_time = 1
[dem]
dt = 1e-5
gravity = [{}, {}]
[[material]]
name = "block"
density = 5000
[[contact]]
materials = ["*", "*"]
normal = "area"
E = 1e7
damping = "gamma"
gamma = 0.5
tangential = "gc2d"
mu = {}
[[shape]]
name = "block"
kind = "rectangle"
size = [0.02, 0.01]
chamfer = 0.0
[[particle]]
shape = "block"
position = [0.0, 0.005]
material = "block"
[[wall]]
points = [[-1.0, 0.0], [1.0, 0.0]]
material = "block"
)",
                       kG * std::sin(theta), -kG * std::cos(theta), mu);
}

struct InclineRun {
    Real displacement = 0;  ///< [m] along x over the measuring window
    Real acceleration = 0;  ///< [m/s^2] (v(end) - v(start)) / window
    Real speed = 0;         ///< [m/s] |v| at the end
};

InclineRun runIncline(Real mu, Real theta) {
    dem::World w = test::makeWorldFromToml(inclineScene(mu, theta));
    const auto& s = w.store();
    // Settle: the normal contact forms within ~0.3 ms and its oscillation (period ~1 ms for
    // k = E L / l = 4e7 N/m, m = 1 kg) is damped by gamma = 0.5 within a few periods.
    const Real settle = 0.05, window = 0.2;
    while (w.time() < settle - 1e-12) EXPECT_EQ(w.step(), dem::kStepOk);
    const Real x0 = s.x[0], v0 = s.vx[0];
    while (w.time() < settle + window - 1e-12) EXPECT_EQ(w.step(), dem::kStepOk);
    return {s.x[0] - x0, (s.vx[0] - v0) / window, std::hypot(s.vx[0], s.vy[0])};
}

}  // namespace

TEST(PolygonFriction, InclineOnsetAtArctanMu) {
    const Real deg = std::acos(-1.0) / 180;
    for (Real mu : {0.3, 0.6}) {
        const Real onset = std::atan(mu);
        // 1 degree below arctan(mu): static friction holds. The gc2d spring (k_t = 2/7 E) carries
        // the downhill weight component m g sin(theta) ~ 3-5 N with an elastic displacement of
        // F / k_t ~ 2 um, built up during the settling; afterwards nothing may move. A block that
        // slid at even 1 % of the resolved acceleration g (cos theta + mu sin theta) * 1 degree
        // (~0.2 m/s^2) would cover 1/2 * 0.002 m/s^2 * (0.2 s)^2 = 40 um in the window, so the
        // threshold of 0.1 um separates sticking from sliding by orders of magnitude.
        const auto stick = runIncline(mu, onset - deg);
        std::printf(
            "mu = %.1f, theta = arctan(mu) - 1 deg = %.2f deg: displacement over 0.2 s = %.3e m, speed %.2e "
            "m/s\n",
            mu, (onset - deg) / deg, stick.displacement, stick.speed);
        EXPECT_LT(std::abs(stick.displacement), 1e-7) << "mu " << mu;
        EXPECT_LT(stick.speed, 1e-6) << "mu " << mu;

        // 1 degree above: the block slides with a = g (sin theta - mu cos theta). The Coulomb cap
        // of the gc2d law is exactly mu times the elastic normal force, which equals m g cos theta
        // once the normal oscillation has decayed (the damping term averages to zero in steady
        // sliding), so the only deviations are integration errors. The tolerance of 2 % of a
        // (~0.004 m/s^2) is 1/40 of the change of a between neighbouring 1-degree tilts
        // (g (cos theta + mu sin theta) * 1 degree ~ 0.18 m/s^2), so the test still resolves the
        // onset angle to well below the 1-degree steps of the thesis (spec 8.2 item 1).
        const Real theta = onset + deg;
        const auto slide = runIncline(mu, theta);
        const Real expected = kG * (std::sin(theta) - mu * std::cos(theta));
        std::printf(
            "mu = %.1f, theta = arctan(mu) + 1 deg = %.2f deg: displacement over 0.2 s = %.3e m, a = %.5f "
            "m/s^2, "
            "expected g (sin - mu cos) = %.5f m/s^2 (%+.3f %%)\n",
            mu, theta / deg, slide.displacement, slide.acceleration, expected,
            100 * (slide.acceleration / expected - 1));
        EXPECT_GT(slide.displacement, 1e-3) << "mu " << mu;
        EXPECT_NEAR(slide.acceleration, expected, 0.02 * expected) << "mu " << mu;
    }
}

namespace {

/// A flat 1 cm x 2 mm block (m = 5000 kg/m^2 * 2e-5 m^2 = 0.1 kg) on a floor, pulled along +x by
/// a DRAG spring (k = 100 N/m, the gc2d default) attached at the leading edge at centroid height
/// (1 mm above the floor), its free end moving at `speed` from zero force.
std::string pulledBlockScene(Real mu, Real speed) {
    return fmt::format(R"(
[run]
end_time = 100
[dem]
dt = 4e-6
gravity = [0, -9.81]
[[material]]
name = "block"
density = 5000
[[contact]]
materials = ["*", "*"]
normal = "area"
E = 1e7
damping = "gamma"
gamma = 0.5
tangential = "gc2d"
mu = {}
[[shape]]
name = "block"
kind = "rectangle"
size = [0.01, 0.002]
[[particle]]
shape = "block"
position = [0.0, 0.001]
material = "block"
[[wall]]
points = [[-1.0, 0.0], [1.0, 0.0]]
material = "block"
[[spring]]
particle = 0
k = 100
attach = [0.005, 0.0]
pull_start = [0.005, 0.001]
speed = {}
direction = 0.0
from = 0.0
)",
                       mu, speed);
}

}  // namespace

TEST(PolygonFriction, PulledBlockStartsAtMuMg) {
    // Slow pulling: the spring force grows at R = k v = 0.2 N/s, so the block (stuck on the
    // static gc2d spring, k_t = 2/7 E) waits mu m g / R = 1-4 s before it moves.
    const Real k = 100, v = 2e-3;
    // Onset is detected when the block has moved delta = 10 um from where it settled: 37 times
    // the elastic stretch of the friction spring at the largest load (mu m g / k_t = 0.78 N /
    // 2.9e6 N/m = 0.27 um), so sticking is never mistaken for sliding.
    const Real delta = 1e-5;
    // Once the block slips (static = kinetic friction in gc2d: the cap is mu F_n both ways), it
    // moves as x(tau) = v (tau - sin(w tau) / w), w = sqrt(k / m), so the spring force when the
    // displacement reaches delta exceeds the onset force by k v sin(w tau) / w. Solve for tau
    // and subtract that overshoot (5 mN, 2.7 % of mu m g at mu = 0.2) instead of hiding it in
    // the tolerance.
    auto overshoot = [&](Real m) {
        const Real omega = std::sqrt(k / m);
        Real lo = 0, hi = 1;
        for (int it = 0; it < 200; ++it) {
            const Real tau = 0.5 * (lo + hi);
            (v * (tau - std::sin(omega * tau) / omega) < delta ? lo : hi) = tau;
        }
        return k * v * std::sin(omega * lo) / omega;
    };
    for (Real mu : {0.2, 0.5, 0.8}) {
        dem::World w = test::makeWorldFromToml(pulledBlockScene(mu, v));
        const auto& s = w.store();
        const Real m = s.mass[0];
        ASSERT_NEAR(m, 0.1, 1e-12);
        auto springForce = [&]() {
            const auto& sp = w.springs()[0];
            const Real c = std::cos(s.angle[0]), sn = std::sin(s.angle[0]);
            const Vec2 attach{s.x[0] + c * sp.attach.x - sn * sp.attach.y,
                              s.y[0] + sn * sp.attach.x + c * sp.attach.y};
            return (sp.freeEnd(w.time()) - attach) * sp.stiffness;
        };
        // Reference position once the block has settled on the floor (the normal contact
        // oscillation, period ~0.2 ms, is gone after 20 ms; the spring force is 4 mN by then).
        while (w.time() < 0.02) ASSERT_EQ(w.step(), dem::kStepOk);
        const Real x0 = s.x[0];
        const Real limit = 2 * mu * m * kG / (k * v);  // twice the expected onset time
        Vec2 fOnset{0, 0};
        Real tOnset = -1;
        while (w.time() < limit) {
            ASSERT_EQ(w.step(), dem::kStepOk);
            if (s.x[0] - x0 > delta) {
                fOnset = springForce();
                tOnset = w.time();
                break;
            }
        }
        ASSERT_GT(tOnset, 0) << "mu " << mu << ": the block never moved";
        const Real expected = mu * m * kG;
        const Real corrected = fOnset.x - overshoot(m);
        std::printf(
            "mu = %.1f: spring force at %.0f um displacement %.6f N (t = %.4f s), minus slip overshoot %.6f "
            "N = "
            "%.6f N; mu m g = %.6f N (%+.3f %%); vertical spring force %.2e N\n",
            mu, delta * 1e6, fOnset.x, tOnset, overshoot(m), corrected, expected,
            100 * (corrected / expected - 1), fOnset.y);
        // Tolerance 1 % of mu m g (2 mN at mu = 0.2). In the gc2d law the static limit is mu times
        // the elastic normal force, which equals m g at rest; the spring acts at centroid height,
        // so its line passes through the centroid and the friction couple (mu m g * 1 mm) only
        // shifts the normal force by mu h / 2 <= 0.8 mm, well inside the 10 mm base (no tipping,
        // no change of the normal force). What remains: the vertical spring component from the
        // block's tilt (printed, ~1e-7 N), the time resolution k v dt = 1e-6 N, and the
        // approximation in the overshoot (the viscous term of the tangential law during the first
        // microseconds of slip), each far below 1 %.
        EXPECT_NEAR(corrected, expected, 0.01 * expected) << "mu " << mu;
    }
}
