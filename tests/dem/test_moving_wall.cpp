// SPDX-License-Identifier: MIT
// A wall with prescribed velocity hits a disk at rest: the wall has infinite mass, so the disk
// leaves with (1 + e) times the wall speed (frictionless, restitution convention).
#include <gtest/gtest.h>

#include <cstdio>

#include "../support.hpp"

using namespace granulab;

TEST(MovingWall, PistonKicksDiskWithOnePlusE) {
    const char* scene = R"(
[run]
end_time = 1.0
[dem]
dt = 5.0e-5
[[material]]
name = "g"
density = 1.0
[[contact]]
materials = ["g", "g"]
kn = 1.0e4
damping = "restitution"
e = 0.6
[[particle]]
position = [1.0, 0.0]
radius = 0.5
material = "g"
[[wall]]
points = [[0.0, -1.0], [0.0, 1.0]]
velocity = [2.0, 0.0]
material = "g"
)";
    dem::World w = test::makeWorldFromToml(scene);
    for (int k = 0; k < 20000; ++k) w.step();
    const Real v = w.store().vx[0];
    std::printf("disk speed after the piston kick %.6f (expected %.6f)\n", v, 1.6 * 2.0);
    EXPECT_NEAR(v / (1.6 * 2.0), 1.0, 2e-3);
    EXPECT_NEAR(w.store().vy[0], 0.0, 1e-12);
}
