// SPDX-License-Identifier: MIT
// A piston on a granular column (gc2d spec 6.3; docs/physics/walls.md): the velocity controller
// lands at v_max, then settles at the target force within 1 % without overshoot larger than 1 %
// when v_max sqrt(k M) is well below the target; the overshoot is reported.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "../support.hpp"

namespace granulab {
namespace {

TEST(Machines, PistonSettlesOnAColumnWithoutOvershoot) {
    // 5 x 6 disks (r = 2 mm, m = 1.6e-4 kg) in a 2.2 cm box; a lid pushed down with 1 N, about
    // 20 times the column's weight. Column: k_eff ~ 1e4 N/m, M ~ 5e-3 kg: sqrt(k M) ~ 7 N s/m,
    // so v_max = 0.01 m/s lands with ~0.07 N, 7 % of the target.
    const std::string toml = R"(
[run]
end_time = 1.0
[dem]
dt = 1e-5
gravity = [0.0, -9.81]
[[material]]
name = "glass"
density = 12.5
[[material]]
name = "steel"
[[contact]]
materials = ["glass", "*"]
normal = "hooke"
kn = 1.0e4
damping = "restitution"
e = 0.3
tangential = "cundall_strack"
mu = 0.3
[[block]]
lattice = "square"
region = [0.0005, 0.0, 0.0205, 0.0245]
spacing = 0.0041
radius = 0.002
material = "glass"
[[wall]]
name = "box"
points = [[0.0, 0.06], [0.0, 0.0], [0.0215, 0.0], [0.0215, 0.06]]
material = "steel"
[[wall]]
name = "piston"
points = [[0.0002, 0.0255], [0.0213, 0.0255], [0.0213, 0.0305], [0.0002, 0.0305]]
closed = true
kind = "polygon"
piston_force = 1.0
piston_v_max = 0.01
piston_from = 0.05
material = "steel"
)";
    dem::World w = test::makeWorldFromToml(toml);
    const Real target = 1.0;
    Real peak = 0;
    std::vector<Real> last;
    const int steps = 40000;  // 0.4 s
    for (int k = 0; k < steps; ++k) {
        ASSERT_EQ(w.step(), dem::kStepOk);
        const Real f = w.wallForce()[1].y;  // grains push the piston up
        peak = std::max(peak, f);
        if (k >= steps - 5000) last.push_back(f);
    }
    Real mean = 0;
    for (const Real f : last) mean += f;
    mean /= static_cast<Real>(last.size());
    const Real overshoot = peak / target - 1;
    RecordProperty("settled_force", std::to_string(mean));
    RecordProperty("overshoot", std::to_string(overshoot));
    std::printf("piston: settled force %.5f N (target %.3f N), overshoot %.3f %%\n", mean, target,
                100 * overshoot);
    EXPECT_NEAR(mean, target, 0.01 * target);
    EXPECT_LT(overshoot, 0.01);
    EXPECT_LT(w.walls().walls[1].displacement.y, 0.0);  // it moved down onto the column
}

}  // namespace
}  // namespace granulab
