// SPDX-License-Identifier: MIT
// Integrators: the error of a damped contact's restitution falls with the time step at each
// scheme's order; every integrator resumes bit for bit from a saved state.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "../support.hpp"
#include "app/dem/dem_engine.hpp"

using namespace granulab;

namespace {

/// Head-on collision of two disks with the linear law (kn = 1e4, e = 0.7); returns |e - 0.7|.
Real restitutionError(const std::string& integrator, Real stepsPerContact, int pcIterations = 50) {
    const Real m = kPi * 0.25, meff = 0.5 * m, kn = 1.0e4, e = 0.7;
    const Real beta = -std::log(e) / std::sqrt(kPi * kPi + std::log(e) * std::log(e));
    const Real tc = kPi / (std::sqrt(kn / meff) * std::sqrt(1 - beta * beta));
    const std::string toml = fmt::format(R"(
[run]
end_time = 1.0
[dem]
dt = {}
integrator = "{}"
pc_iterations = {}
pc_tolerance = 1e-9
[[material]]
name = "a"
density = 1.0
[[contact]]
materials = ["a", "a"]
kn = 1.0e4
damping = "restitution"
e = 0.7
[[particle]]
position = [-0.52, 0.0]
velocity = [1.0, 0.0]
radius = 0.5
material = "a"
[[particle]]
position = [0.52, 0.0]
velocity = [-1.0, 0.0]
radius = 0.5
material = "a"
)",
                                         tc / stepsPerContact, integrator, pcIterations);
    dem::World w = test::makeWorldFromToml(toml);
    const auto steps = static_cast<int>(4 * tc / (tc / stepsPerContact)) + 200;
    for (int k = 0; k < steps; ++k) w.step();
    const auto& s = w.store();
    const Real vrel = std::abs(s.vx[0] - s.vx[1]);
    return std::abs(vrel / 2.0 - e);
}

Real observedOrder(const std::string& integrator, int pcIterations = 50) {
    const Real e1 = restitutionError(integrator, 50, pcIterations);
    const Real e2 = restitutionError(integrator, 100, pcIterations);
    const Real e4 = restitutionError(integrator, 200, pcIterations);
    const Real order = 0.5 * std::log2(e1 / e4);
    std::printf("%-6s iter %2d: |e - 0.7| = %.3g, %.3g, %.3g at 50/100/200 steps per contact -> order %.2f\n",
                integrator.c_str(), pcIterations, e1, e2, e4, order);
    return order;
}

}  // namespace

TEST(Integrators, RestitutionErrorFallsAtTheSchemesOrder) {
    EXPECT_NEAR(observedOrder("euler"), 1.0, 0.25);
    EXPECT_NEAR(observedOrder("pc", 0), 1.0, 0.25);  // modified explicit Euler
    EXPECT_NEAR(observedOrder("verlet"), 2.0, 0.3);
    EXPECT_NEAR(observedOrder("pc", 50), 2.0, 0.3);  // converged: trapezoidal rule
    // Gear is fifth order for smooth forces; the kink of the contact force at touch-down and
    // separation limits the observed order to 2 (with a much smaller constant).
    EXPECT_NEAR(observedOrder("gear"), 2.0, 0.3);
}

TEST(Integrators, EveryIntegratorResumesBitForBit) {
    const std::string scene = std::string(GRANULAB_SOURCE_DIR) + "/examples/disks_in_box.toml";
    for (const char* name : {"verlet", "euler", "pc", "gear"}) {
        SCOPED_TRACE(name);
        const std::vector<io::Override> ov = {io::parseOverride(std::string("dem.integrator=") + name)};
        const model::SceneDef sc = test::readScene(scene, ov);
        const dem::PreparedScene v = app::checkAndPrepareDem(sc);
        dem::World a = dem::makeWorld(sc, v.initial);
        a.initialize();
        for (int k = 0; k < 3000; ++k) a.step();
        std::stringstream state;
        a.saveState(state);
        dem::World b = dem::makeWorld(sc, v.initial);
        b.loadState(state);
        for (int k = 0; k < 2000; ++k) {
            a.step();
            b.step();
        }
        EXPECT_EQ(a.store().x, b.store().x);
        EXPECT_EQ(a.store().vy, b.store().vy);
        EXPECT_EQ(a.store().omega, b.store().omega);
        EXPECT_EQ(a.neighbors().pairs.xi, b.neighbors().pairs.xi);
    }
}
