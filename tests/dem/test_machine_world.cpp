// SPDX-License-Identifier: MIT
// Scene machines inside a running world: the global size scaling s(t) (gc2d 2.4) sets radii and
// polygon corners at every step, mass kept and inertia times s^2; a [[change]] switches friction
// off at its time without a restart (gc2d 6.7); a gravity schedule reaches the particles.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support.hpp"

namespace granulab {
namespace {

const char* kSquareOnFloor = R"(
[run]
end_time = 1.0
[dem]
dt = 1e-5
gravity = [0.0, -9.81]
[[material]]
name = "grain"
density = 1000.0
[[material]]
name = "floor"
[[contact]]
materials = ["grain", "*"]
normal = "area"
E = 1.0e5
damping = "gamma"
gamma = 0.5
tangential = "gc2d"
mu = 0.5
[[shape]]
name = "square"
kind = "regular"
corner_count = 4
radius = 0.005
rotation = 0.7853981633974483
[[particle]]
shape = "square"
position = [0.0, 0.0036]
velocity = [0.3, 0.0]
material = "grain"
[[wall]]
points = [[-1, -0.02], [1, -0.02], [1, 0], [-1, 0]]
kind = "polygon"
material = "floor"
)";

TEST(Machines, SizeScalingSetsRadiiAndCornersEveryStep) {
    const std::string toml = std::string(kSquareOnFloor) + R"(
[size_scaling]
amplitude = 0.02
frequency = 5.0
slope = 3.0
window = [0.0, 1.0]
)";
    dem::World w = test::makeWorldFromToml(toml);
    const Real r0 = 0.005, m0 = w.store().mass[0],
               i0 = 1 / w.store().invInertia[0] / w.sizeScale() / w.sizeScale();
    for (int k = 1; k <= 2000; ++k) {
        ASSERT_EQ(w.step(), dem::kStepOk);
        if (k % 20 != 0) continue;
        const Real t = k * 1e-5;
        const Real s = 1 + 0.02 * (0.5 - 0.5 * std::tanh(3 * std::cos(2 * kPi * 5 * t)));
        EXPECT_NEAR(w.sizeScale(), s, 1e-15);
        EXPECT_NEAR(w.store().radius[0], r0 * s, 1e-14 * r0);
        EXPECT_EQ(w.store().mass[0], m0);
        EXPECT_NEAR(1 / w.store().invInertia[0], i0 * s * s, 1e-12 * i0);
    }
}

TEST(Machines, ChangeSwitchesFrictionOffAtItsTime) {
    const std::string toml = std::string(kSquareOnFloor) + R"(
[[change]]
at = 0.03
contact = 0
set = { mu = 0.0 }
)";
    dem::World w = test::makeWorldFromToml(toml);
    for (int k = 0; k < 3000; ++k) ASSERT_EQ(w.step(), dem::kStepOk);  // 0.03 s of sliding friction
    const Real slowed = w.store().vx[0];
    EXPECT_LT(slowed, 0.3 - 0.5 * 9.81 * 0.02);  // mu g decelerates it
    for (int k = 0; k < 2000; ++k) ASSERT_EQ(w.step(), dem::kStepOk);
    const Real early = w.store().vx[0];
    for (int k = 0; k < 3000; ++k) ASSERT_EQ(w.step(), dem::kStepOk);
    EXPECT_NEAR(w.store().vx[0], early, 1e-3 * early);  // no friction: it glides on
    EXPECT_GT(early, 0.05);
}

TEST(Machines, GravityScheduleReachesTheParticles) {
    std::string toml = std::string(kSquareOnFloor);
    toml.replace(toml.find("gravity = [0.0, -9.81]"), 22, "");
    toml += R"(
[gravity]
type = "linear"
magnitude = [9.81, 0.0]
window = [0.0, 0.01]
)";
    dem::World w = test::makeWorldFromToml(toml);
    for (int k = 0; k < 1000; ++k) ASSERT_EQ(w.step(), dem::kStepOk);
    EXPECT_NEAR(w.gravity().y, 0.0, 1e-12);
    EXPECT_NEAR(w.gravity().x, 0.0, 1e-12);
}

}  // namespace
}  // namespace granulab
