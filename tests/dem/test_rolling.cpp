// SPDX-License-Identifier: MIT
// Rolling resistance (cfddem Eq. 3.56-3.59): a disk rolling on a floor keeps rolling without it,
// is braked by the rolling damper, and the rolling spring holds a disk on a gentle slope where
// it would otherwise roll away with a = 2/3 g sin(theta).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support.hpp"

using namespace granulab;

namespace {
dem::World rollingDisk(const std::string& rolling, Real slope) {
    const Real g = 9.81;
    return test::makeWorldFromToml(
        fmt::format(R"(
[run]
end_time = 10.0
[dem]
dt = 1.0e-5
gravity = [{gx}, {gy}]
[[material]]
name = "g"
density = 1.0
[[contact]]
materials = ["g", "g"]
kn = 1.0e4
damping = "restitution"
e = 0.3
tangential = "cundall_strack"
mu = 1.0
{rolling}
[[particle]]
position = [0.0, 0.1]
velocity = [{v}, 0.0]
omega = {w}
radius = 0.1
material = "g"
[[wall]]
points = [[-100.0, 0.0], [100.0, 0.0]]
material = "g"
)",
                    fmt::arg("gx", g * std::sin(slope)), fmt::arg("gy", -g * std::cos(slope)),
                    fmt::arg("rolling", rolling), fmt::arg("v", slope == 0 ? 0.5 : 0.0),
                    fmt::arg("w", slope == 0 ? -5.0 : 0.0)));
}
}  // namespace

TEST(Rolling, DamperBrakesARollingDisk) {
    dem::World free = rollingDisk("", 0.0);
    dem::World braked = rollingDisk("rolling = \"spring_dashpot\"\nD_r = 0.5", 0.0);
    for (int k = 0; k < 100000; ++k) {
        free.step();
        braked.step();
    }
    std::printf("rolling disk after 1 s: %.4f m/s free, %.4f m/s with the rolling damper\n",
                free.store().vx[0], braked.store().vx[0]);
    EXPECT_NEAR(free.store().vx[0], 0.5, 0.005);     // pure rolling: no dissipation
    EXPECT_NEAR(free.store().omega[0], -5.0, 0.05);  // still rolling without slip
    EXPECT_LT(std::abs(braked.store().vx[0]), 0.25);
}

TEST(Rolling, SpringHoldsADiskOnAGentleSlope) {
    const Real slope = 0.02;  // rad
    dem::World free = rollingDisk("", slope);
    dem::World held = rollingDisk("rolling = \"spring_dashpot\"\nk_r = 500.0\nD_r = 0.3", slope);
    for (int k = 0; k < 100000; ++k) {
        free.step();
        held.step();
    }
    const Real expected = 0.5 * (2.0 / 3.0) * 9.81 * std::sin(slope);  // x = a t^2 / 2 at t = 1 s
    std::printf("slope: free disk rolled %.4f m (2/3 g sin: %.4f), held disk %.2e m\n", free.store().x[0],
                expected, held.store().x[0]);
    EXPECT_NEAR(free.store().x[0] / expected, 1.0, 0.03);
    EXPECT_LT(std::abs(held.store().x[0]), 1e-3);
}
