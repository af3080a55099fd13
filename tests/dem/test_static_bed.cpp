// SPDX-License-Identifier: MIT
// Validation: a settled bed on a frictional floor between frictionless side walls; the force on
// the floor equals the total weight within 0.5 %, and the wall forces balance gravity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support.hpp"

using namespace granulab;

TEST(StaticBed, FloorCarriesTheWeight) {
    const char* scene = R"(
[run]
seed = 11
end_time = 10.0
[dem]
dt = 2.0e-4
gravity = [0.0, -10.0]
[[dem.damping]]
gamma = 0.5
[[material]]
name = "grain"
density = 1.0
[[material]]
name = "floor"
[[material]]
name = "side"
[[contact]]
materials = ["grain", "*"]
normal = "hooke"
kn = 1.0e5
damping = "restitution"
e = 0.5
tangential = "cundall_strack"
mu = 0.5
[[contact]]
materials = ["grain", "side"]
normal = "hooke"
kn = 1.0e5
damping = "restitution"
e = 0.5
[[block]]
lattice = "hexagonal"
spacing = 1.15
region = [0.6, 0.6, 19.4, 12.0]
radius = { distribution = "uniform", min = 0.45, max = 0.55 }
material = "grain"
[[wall]]
name = "floor"
points = [[0.0, 0.0], [20.0, 0.0]]
material = "floor"
[[wall]]
name = "left"
points = [[0.0, 0.0], [0.0, 30.0]]
material = "side"
[[wall]]
name = "right"
points = [[20.0, 0.0], [20.0, 30.0]]
material = "side"
)";
    dem::World w = test::makeWorldFromToml(scene);
    Real weight = 0;
    for (std::size_t i = 0; i < w.store().size(); ++i) weight += 10.0 * w.store().mass[i];
    const std::int64_t steps = static_cast<std::int64_t>(10.0 / 2.0e-4);
    for (std::int64_t k = 0; k < steps; ++k) ASSERT_EQ(w.step(), dem::kStepOk);
    const auto e = w.energies();
    EXPECT_LT(e.kinetic, 1e-6 * weight);     // static
    const Real floor = -w.wallForce()[0].y;  // particles push the floor down
    std::printf("floor force / weight = %.6f, kinetic energy / weight = %.2e\n", floor / weight,
                e.kinetic / weight);
    EXPECT_NEAR(floor / weight, 1.0, 0.005) << "floor " << floor << " weight " << weight;
    // Side walls are frictionless: they carry no vertical load.
    EXPECT_NEAR(w.wallForce()[1].y, 0.0, 1e-9 * weight);
    EXPECT_NEAR(w.wallForce()[2].y, 0.0, 1e-9 * weight);
    // Horizontal wall forces balance.
    EXPECT_NEAR(w.wallForce()[1].x + w.wallForce()[2].x + w.wallForce()[0].x, 0.0, 1e-3 * weight);
}
