// SPDX-License-Identifier: MIT
// T4 of the cfddem seed, made quantitative (spec/cfddem.md section 7, T4 as corrected there): a
// steel sphere resting on a steel wall under gravity (normal overlap held by its weight) starts
// with a horizontal velocity; the Mindlin spring makes the contact oscillate with the period
// 2 pi sqrt(m_t/k_t), m_t = 2m/7 (translation + rolling of a sphere). With D_t = 0 the amplitude
// is conserved within 1 % over 10 periods at >= 200 steps per period (trapezoidal spring
// increment of the iterating predictor-corrector); with D_t > 0 it decays.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support.hpp"

using namespace granulab;

namespace {
constexpr Real kR = 0.5, kRho = 7700, kE = 1.962e11, kNu = 0.3, kG = 9.81;

struct Oscillation {
    Real period = 0;          ///< [s] from zero crossings of the spring
    Real firstAmplitude = 0;  ///< [m] largest |xi| in the first measured period
    Real lastAmplitude = 0;   ///< [m] the same 10 periods later
};

Oscillation run(const std::string& integrator, Real dampingRatioT, Real dt, Real expectedPeriod) {
    const std::string toml = fmt::format(R"(
[run]
end_time = 1.0
[dem]
dt = {dt}
integrator = "{integ}"
pc_iterations = 100
pc_tolerance = 1e-10
mass_model = "sphere"
gravity = [0.0, -{g}]
[[material]]
name = "steel"
density = {rho}
youngs_modulus = {e}
poisson = {nu}
[[contact]]
materials = ["steel", "steel"]
normal = "hertz"
damping = "lehr"
D_n = 1.0
tangential = "mindlin"
mu = 10.0
D_t = {dtr}
[[particle]]
position = [0.0, {r}]
velocity = [0.01, 0.0]
radius = {r}
material = "steel"
[[wall]]
points = [[-5.0, 0.0], [5.0, 0.0]]
material = "steel"
)",
                                         fmt::arg("dt", dt), fmt::arg("integ", integrator), fmt::arg("g", kG),
                                         fmt::arg("rho", kRho), fmt::arg("e", kE), fmt::arg("nu", kNu),
                                         fmt::arg("dtr", dampingRatioT), fmt::arg("r", kR));
    dem::World w = test::makeWorldFromToml(toml);
    Oscillation o;
    const Real settle = 12 * expectedPeriod;  // the normal overlap settles (D_n = 1) first
    Real prev = 0, firstCrossing = -1, lastCrossing = -1;
    int crossings = 0;
    while (w.time() < settle + 12 * expectedPeriod) {
        w.step();
        const auto& xiList = w.neighbors().wallPairs.xi;
        const Real xi = xiList.empty() ? 0.0 : xiList[0];
        const Real t = w.time();
        if (t < settle) {
            prev = xi;
            continue;
        }
        if (t < settle + expectedPeriod) o.firstAmplitude = std::max(o.firstAmplitude, std::abs(xi));
        if (t >= settle + 10 * expectedPeriod && t < settle + 11 * expectedPeriod)
            o.lastAmplitude = std::max(o.lastAmplitude, std::abs(xi));
        if (prev < 0 && xi >= 0) {  // upward zero crossing, interpolated
            const Real tc = t - w.config().dt * xi / (xi - prev);
            if (firstCrossing < 0) firstCrossing = tc;
            lastCrossing = tc;
            ++crossings;
        }
        prev = xi;
    }
    o.period = crossings > 1 ? (lastCrossing - firstCrossing) / (crossings - 1) : 0;
    return o;
}

/// Period 2 pi sqrt(m_t / k_t) at the static overlap of the sphere's weight.
Real expectedPeriod() {
    const Real m = kRho * 4.0 / 3.0 * kPi * kR * kR * kR;
    const Real eStar = 1.0 / (2 * (1 - kNu * kNu) / kE);
    const Real kHz = 4.0 / 3.0 * eStar * std::sqrt(kR);
    const Real overlap = std::pow(m * kG / kHz, 2.0 / 3.0);
    const Real nuStar = 1.0 / (2.0 / kNu);
    const Real kt = 8 * eStar / (2 * (1 + nuStar)) * std::sqrt(kR * overlap);
    const Real mt = 2.0 * m / 7.0;
    return 2 * kPi * std::sqrt(mt / kt);
}
}  // namespace

TEST(TangentialOscillation, T4PeriodAndConservedAmplitude) {
    const Real period = expectedPeriod();
    const Oscillation pc = run("pc", 0.0, period / 200, period);
    std::printf("T4 pc: period %.5g s (expected %.5g), amplitude %.4g -> %.4g m over 10 periods (%.3f %%)\n",
                pc.period, period, pc.firstAmplitude, pc.lastAmplitude,
                100 * (pc.lastAmplitude / pc.firstAmplitude - 1));
    EXPECT_NEAR(pc.period / period, 1.0, 0.01);
    EXPECT_NEAR(pc.lastAmplitude / pc.firstAmplitude, 1.0, 0.01);
    const Oscillation verlet = run("verlet", 0.0, period / 200, period);
    std::printf("T4 verlet: period %.5g s, amplitude ratio %.4f\n", verlet.period,
                verlet.lastAmplitude / verlet.firstAmplitude);
    EXPECT_NEAR(verlet.lastAmplitude / verlet.firstAmplitude, 1.0, 0.01);
    const Oscillation damped = run("pc", 0.1, period / 200, period);
    std::printf("T4 pc, D_t = 0.1: amplitude ratio %.4f over 10 periods\n",
                damped.lastAmplitude / damped.firstAmplitude);
    EXPECT_LT(damped.lastAmplitude / damped.firstAmplitude, 0.5);
}
