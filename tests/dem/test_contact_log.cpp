// SPDX-License-Identifier: MIT
// The contact records of a force evaluation (dem/contact_log.hpp; gc2d spec section 7): together
// with gravity they are every force on a grain (the sum equals the World's f exactly, up to the
// order of summation), wall contacts add up to the World's wall forces, and normals, points and
// components follow the documented conventions. Disks under the depth laws and polygons under the
// area law, while grains fall, collide and settle.
#include <gtest/gtest.h>

#include <cmath>
#include <unordered_map>

#include "../support.hpp"
#include "dem/world.hpp"

using namespace granulab;

namespace {

const char* kDiskBed = R"(
[run]
seed = 3
end_time = 1.0
[dem]
dt = 1.0e-4
gravity = [0.0, -10.0]
[[material]]
name = "grain"
density = 1.0
youngs_modulus = 1.0e6
poisson = 0.3
[[contact]]
materials = ["*", "*"]
normal = "hertz"
damping = "restitution"
e = 0.3
tangential = "cundall_strack"
mu = 0.5
[[block]]
lattice = "hexagonal"
spacing = 1.1
region = [0.6, 0.6, 9.4, 6.0]
radius = { distribution = "uniform", min = 0.4, max = 0.5 }
velocity = [0.3, -0.5]
material = "grain"
[[wall]]
name = "box"
points = [[0.0, 12.0], [0.0, 0.0], [10.0, 0.0], [10.0, 12.0]]
material = "grain"
)";

const char* kPolygonPile = R"(
[run]
seed = 7
end_time = 1
[dem]
dt = 2e-6
gravity = [0, -9.81]
[[material]]
name = "grain"
density = 5000
[[contact]]
materials = ["*", "*"]
normal = "area"
E = 1e7
damping = "gamma"
gamma = 0.75
tangential = "gc2d"
mu = 0.6
[[shape]]
name = "sand"
kind = "grain"
size = [0.0015, 0.0015]
corner_count = 7
corner_angles = "rand1"
rotation_mode = "equal"
[[block]]
shape = "sand"
lattice = "square"
region = [0.0, 0.0, 0.02, 0.02]
spacing = 0.0032
material = "grain"
[[wall]]
name = "floor"
points = [[0, 0], [0.02, 0]]
material = "grain"
[[wall]]
name = "body"
kind = "polygon"
points = [[0.008, -0.002], [0.012, -0.002], [0.01, 0.0005]]
material = "grain"
)";

/// Runs `steps` steps recording the last one and checks the records against the World's forces.
void checkRecords(dem::World& w, int steps) {
    for (int k = 0; k < steps; ++k) {
        w.recordContacts(k == steps - 1);
        ASSERT_EQ(w.step(), dem::kStepOk);
    }
    const auto& s = w.store();
    const auto& log = w.contactLog();
    ASSERT_EQ(log.step, w.stepIndex());
    ASSERT_EQ(log.records.size(), w.forceStats().contacts + w.forceStats().wallContacts);
    ASSERT_GT(log.records.size(), 10u);
    std::unordered_map<ParticleId, std::size_t> slot;
    for (std::size_t i = 0; i < s.size(); ++i) slot[s.id[i]] = i;
    const Vec2 g = w.gravity();
    std::vector<Vec2> sum(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) sum[i] = g * s.mass[i];
    std::vector<Vec2> wallSum(w.walls().walls.size());
    Real fMax = 0;
    for (const dem::ContactRecord& r : log.records) {
        EXPECT_NEAR(norm(r.normal), 1.0, 1e-12);
        EXPECT_GE(r.depth, 0.0);
        EXPECT_GE(r.area, 0.0);
        EXPECT_GE(r.length, 0.0);
        fMax = std::max(fMax, norm(r.force));
        const std::size_t a = slot.at(r.a);
        sum[a] += r.force;
        // The contact point lies between the bodies: within reach of a's centre.
        EXPECT_LE(norm(r.point - Vec2{s.x[a], s.y[a]}), s.radius[a] * (1 + 1e-9));
        if (r.wall >= 0) {
            wallSum[static_cast<std::size_t>(r.wall)] -= r.force;
        } else {
            const std::size_t b = slot.at(r.b);
            sum[b] -= r.force;
            // n points from a toward b.
            EXPECT_GT(dot(r.normal, Vec2{s.x[b] - s.x[a], s.y[b] - s.y[a]}), 0.0);
        }
    }
    ASSERT_GT(fMax, 0.0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const Real scale = fMax + s.mass[i] * norm(g);
        EXPECT_NEAR(s.fx[i], sum[i].x, 1e-12 * scale) << "grain " << s.id[i];
        EXPECT_NEAR(s.fy[i], sum[i].y, 1e-12 * scale) << "grain " << s.id[i];
    }
    for (std::size_t k = 0; k < wallSum.size(); ++k) {
        EXPECT_NEAR(w.wallForce()[k].x, wallSum[k].x, 1e-12 * fMax * s.size());
        EXPECT_NEAR(w.wallForce()[k].y, wallSum[k].y, 1e-12 * fMax * s.size());
    }
}

}  // namespace

TEST(ContactLog, DiskRecordsAreEveryForceOnTheGrains) {
    dem::World w = test::makeWorldFromToml(kDiskBed);
    checkRecords(w, 20000);  // falling, colliding, settling on the floor and the side walls
}

TEST(ContactLog, PolygonRecordsAreEveryForceOnTheGrains) {
    dem::World w = test::makeWorldFromToml(kPolygonPile);
    checkRecords(w, 50000);  // 0.1 s: the rows fall onto each other and the floor
}

TEST(ContactLog, OnlyRequestedStepsRecord) {
    dem::World w = test::makeWorldFromToml(kDiskBed);
    for (int k = 0; k < 50; ++k) ASSERT_EQ(w.step(), dem::kStepOk);
    EXPECT_EQ(w.contactLog().step, -1);
    EXPECT_TRUE(w.contactLog().records.empty());
}
