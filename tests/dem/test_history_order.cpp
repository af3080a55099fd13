// SPDX-License-Identifier: MIT
// Contact history must not depend on slot order: a disk rolling over another with friction,
// while spatial re-sorting swaps which of the two comes first, follows the same trajectory as
// without re-sorting (up to round-off). Catches sign errors when a pair's order flips.
#include <gtest/gtest.h>

#include <cmath>

#include "../support.hpp"

using namespace granulab;

TEST(ContactHistory, IndependentOfSlotOrder) {
    const char* scene = R"(
[run]
end_time = 1.0
[dem]
dt = 2.0e-5
gravity = [0.0, -10.0]
skin = 0.002
[[material]]
name = "g"
density = 1.0
[[contact]]
materials = ["g", "g"]
kn = 1.0e5
damping = "restitution"
e = 0.5
tangential = "cundall_strack"
mu = 0.8
[[particle]]
position = [0.0, 0.0]
radius = 0.5
material = "g"
[[particle]]
position = [-0.9, 0.44]
velocity = [1.5, 0.0]
radius = 0.5
material = "g"
[[wall]]
points = [[-3.0, -0.5], [3.0, -0.5]]
material = "g"
)";
    dem::World sorted = test::makeWorldFromToml(scene, {io::parseOverride("dem.sort_every=1")});
    dem::World unsorted = test::makeWorldFromToml(scene, {io::parseOverride("dem.sort_every=0")});
    Real largestSpring = 0;
    for (int k = 0; k < 30000; ++k) {
        sorted.step();
        unsorted.step();
        for (Real xi : unsorted.neighbors().pairs.xi) largestSpring = std::max(largestSpring, std::abs(xi));
    }
    EXPECT_GT(largestSpring, 1e-6);  // the contact really carried friction
    auto byId = [](const dem::World& w, ParticleId id, int what) {
        const auto& s = w.store();
        for (std::size_t k = 0; k < s.size(); ++k)
            if (s.id[k] == id) return what == 0 ? s.x[k] : (what == 1 ? s.y[k] : s.omega[k]);
        return 0.0;
    };
    for (ParticleId id : {0u, 1u})
        for (int what = 0; what < 3; ++what)
            EXPECT_NEAR(byId(sorted, id, what), byId(unsorted, id, what), 1e-9)
                << "id " << id << " field " << what;
}

TEST(ContactHistory, SlotPermutationKeepsTheSpringAndTheForces) {
    // Two touching disks sliding past each other with a stretched tangential spring.
    model::ParticleStore s;
    s.add(0, {0.0, 0.0}, {0.0, 0.3}, 0, 1.0, 0.5, 1.0, 0.125, 0);
    s.add(1, {0.99, 0.0}, {0.0, -0.2}, 0, -2.0, 0.5, 1.0, 0.125, 0);
    dem::LawTable laws(1);
    dem::ContactLaw law;
    law.normal = dem::HookeNormal{1e4};
    law.tangential = dem::CundallStrack{3e3, 1.0, 0.0, 0.9};
    laws.set(0, 0, law);
    laws.finalize();
    model::WallSet walls;
    dem::BruteForce broad;
    dem::NeighborList list;
    list.rebuild(s, walls, 0.1, 0, broad, laws, {}, false);
    ASSERT_EQ(list.pairs.size(), 1u);
    list.pairs.xi[0] = 1e-3;
    std::vector<Vec2> wallForce;
    dem::ShapeContext shapes;
    dem::ForceStats stats;
    const std::vector<Real> noVel(2, 0.0);
    const dem::DriftVelocities still{noVel.data(), noVel.data(), noVel.data()};
    dem::computeForces(s, walls, list, laws, {}, still, 1e-4, false, stats, wallForce, shapes);
    const Real fy1 = s.fy[1], tq1 = s.torque[1], xiBefore = list.pairs.xi[0];
    // Swap the slots: the pair (0, 1) becomes (1, 0) and is stored as (0, 1) with the ids swapped.
    s.permute({1, 0});
    list.rebuild(s, walls, 0.1, 0, broad, laws, {1, 0}, false);
    ASSERT_EQ(list.pairs.size(), 1u);
    EXPECT_EQ(list.pairs.xi[0], xiBefore);  // the spring is symmetric under exchange of the bodies
    dem::computeForces(s, walls, list, laws, {}, still, 1e-4, false, stats, wallForce, shapes);
    EXPECT_NEAR(s.fy[0], fy1, 1e-12);  // slot 0 now holds id 1
    EXPECT_NEAR(s.torque[0], tq1, 1e-12);
}
