// SPDX-License-Identifier: MIT
// Validation: an elastic, frictionless gas of 1000 disks in a box conserves total energy
// (kinetic + rotational + elastic): drift (mean over the last 10 % of the run minus mean over the
// first 10 %) < 1e-4 relative over 1e5 steps. Velocity Verlet conserves a shadow energy, so the
// instantaneous energy also fluctuates during contacts, by ~(omega dt)^2/8 of the energy held in
// springs; that bound is checked separately. Momentum is conserved to round-off without walls.
#include <gtest/gtest.h>

#include <cmath>

#include "../support.hpp"

using namespace granulab;

namespace {
const char* kGas = R"(
[run]
seed = 3
end_time = 100.0
[dem]
dt = 1.2e-4              # contact time 6.2e-3 s -> ~50 steps per contact
[[material]]
name = "grain"
density = 1.0
[[contact]]
materials = ["*", "*"]
normal = "hooke"
kn = 1.0e5
[[block]]
lattice = "random"
count = 1000
region = [0.0, 0.0, 50.0, 50.0]     # area fraction ~0.31
radius = { distribution = "uniform", min = 0.4, max = 0.6 }
material = "grain"
temperature = 1.0
)";
const char* kBox = R"(
[[wall]]
points = [[0.0, 0.0], [50.0, 0.0], [50.0, 50.0], [0.0, 50.0]]
closed = true
material = "grain"
)";
}  // namespace

TEST(Conservation, ElasticGasEnergyDriftBelow1e4Over1e5Steps) {
    dem::World w = test::makeWorldFromToml(std::string(kGas) + kBox);
    const Real e0 = w.energies().total();
    Real worst = 0, early = 0, late = 0;
    int nEarly = 0, nLate = 0;
    std::uint64_t contactsSeen = 0;
    constexpr int kSteps = 100000;
    for (int k = 0; k < kSteps; ++k) {
        ASSERT_EQ(w.step(), dem::kStepOk);
        contactsSeen += w.forceStats().contacts + w.forceStats().wallContacts;
        if (k % 50 != 49) continue;
        const Real e = w.energies().total();
        worst = std::max(worst, std::abs(e - e0) / e0);
        if (k < kSteps / 10) early += e, ++nEarly;
        if (k >= kSteps - kSteps / 10) late += e, ++nLate;
    }
    EXPECT_GT(contactsSeen, 100000u);  // the gas really collides
    const Real drift = std::abs(late / nLate - early / nEarly) / e0;
    EXPECT_LT(drift, 1e-4) << "relative energy drift " << drift;
    // (pi/50)^2/8 = 4.9e-4 if all energy sat in springs; a gas holds only a few per cent there.
    EXPECT_LT(worst, 4.9e-4) << "largest relative energy deviation " << worst;
    std::printf("energy drift %.3g, largest deviation %.3g over %d steps\n", drift, worst, kSteps);
}

TEST(Conservation, MomentumConservedToRoundOffWithoutWalls) {
    dem::World w = test::makeWorldFromToml(kGas);
    const Vec2 p0 = w.momentum();
    Real scale = 0;
    for (std::size_t i = 0; i < w.store().size(); ++i)
        scale += w.store().mass[i] * std::hypot(w.store().vx[i], w.store().vy[i]);
    std::uint64_t contactsSeen = 0;
    for (int k = 0; k < 20000; ++k) {
        w.step();
        contactsSeen += w.forceStats().contacts;
    }
    EXPECT_GT(contactsSeen, 10000u);
    const Vec2 p1 = w.momentum();
    EXPECT_LT(std::hypot(p1.x - p0.x, p1.y - p0.y), 1e-12 * scale);
}
