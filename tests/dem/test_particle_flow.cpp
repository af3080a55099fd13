// SPDX-License-Identifier: MIT
// Particles in and out (gc2d spec 6.5, cfddem spec 4.2-4.3, T8): a drop source pours exactly its
// count (minus the skipped), inlets emit exactly n pps T, an outlet removes every particle that
// crosses it and no other, removal keeps every array consistent, mass in - out = change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "../support.hpp"

namespace granulab {
namespace {

const char* kMaterials = R"(
[[material]]
name = "grain"
density = 1000.0
[[material]]
name = "wall"
[[contact]]
materials = ["grain", "*"]
normal = "hooke"
kn = 1.0e4
damping = "restitution"
e = 0.5
tangential = "cundall_strack"
mu = 0.5
)";

TEST(ParticleFlow, DropSourcePoursItsCountMinusTheSkipped) {
    const std::string toml = std::string(R"(
[run]
end_time = 0.6
[dem]
dt = 2e-5
gravity = [0.0, -9.81]
)") + kMaterials + R"(
[[source]]
position = [0.0, 0.05]
placement = "rel"
width = 0.01
interval = 0.01
from = 0.0
to = 0.5
radius = 0.002
material = "grain"
[[wall]]
points = [[-0.1, 0.0], [0.1, 0.0], [0.1, -0.01], [-0.1, -0.01]]
closed = true
kind = "polygon"
material = "wall"
)";
    dem::World w = test::makeWorldFromToml(toml);
    const int steps = 30000;  // 0.6 s
    for (int k = 0; k < steps; ++k) ASSERT_EQ(w.step(), dem::kStepOk);
    const auto& c = w.flow().counters();
    ASSERT_EQ(c.sourceDrops.size(), 1u);
    EXPECT_EQ(c.sourceDrops[0], 51u);  // drops at 0, 0.01, ..., 0.5
    EXPECT_EQ(c.inserted + c.skipped, 51u);
    EXPECT_EQ(w.store().size(), c.inserted);
    EXPECT_TRUE(w.store().consistent());
    std::set<ParticleId> ids(w.store().id.begin(), w.store().id.end());
    EXPECT_EQ(ids.size(), w.store().size());  // ids stay unique
    EXPECT_NEAR(w.totalMass(), c.massIn, 1e-15);
}

TEST(ParticleFlow, InletsEmitExactlyRateTimesTime) {
    // Two inlets at 200 /s for T = 0.5 s: 2 n pps T = 200 particles (cfddem Eq. 4.1, T8).
    const std::string toml = std::string(R"(
[run]
end_time = 0.5
[dem]
dt = 1e-4
)") + kMaterials + R"(
[[inlet]]
edge = [[-0.1, 1.0], [0.1, 1.0]]
rate = 200
radius = 0.001
velocity = [0.0, -1.0]
material = "grain"
[[inlet]]
edge = [[0.4, 0.5], [0.2, 0.5]]
rate = 200
radius = 0.001
velocity = [0.0, 1.0]
material = "grain"
)";
    dem::World w = test::makeWorldFromToml(toml);
    for (int k = 0; k < 5000; ++k) ASSERT_EQ(w.step(), dem::kStepOk);
    const auto& c = w.flow().counters();
    EXPECT_EQ(c.inletEmitted[0], 100u);
    EXPECT_EQ(c.inletEmitted[1], 100u);
    EXPECT_EQ(c.skipped, 0u);
    EXPECT_EQ(w.store().size(), 200u);
    for (std::size_t i = 0; i < w.store().size(); ++i) {  // each inside its domain, moving inward
        const bool top = w.store().x[i] < 0.15;
        EXPECT_TRUE(top ? w.store().y[i] <= 1.0 - 0.001 + 1e-12 : w.store().y[i] >= 0.5 + 0.001 - 1e-12);
        EXPECT_TRUE(top ? w.store().vy[i] < 0 : w.store().vy[i] > 0);
    }
}

TEST(ParticleFlow, OutletRemovesEveryCrossingParticleAndNoOther) {
    // Disks falling freely through y = 0; the outlet spans x in [-0.1, 0.1] (a -> b right to left,
    // so n_out points down). Those above it must go, the others fall past.
    std::string toml = std::string(R"(
[run]
end_time = 1.0
[dem]
dt = 1e-4
gravity = [0.0, -9.81]
)") + kMaterials + R"(
[[outlet]]
edge = [[0.1, 0.0], [-0.1, 0.0]]
)";
    std::vector<Real> xs;
    for (int k = 0; k < 20; ++k) xs.push_back(-0.19 + 0.02 * k);
    for (const Real x : xs)
        toml += "[[particle]]\nposition = [" + std::to_string(x) +
                ", 0.2]\nradius = 0.002\nmaterial = \"grain\"\n";
    dem::World w = test::makeWorldFromToml(toml);
    std::size_t maxRemovedAbove = 0;
    for (int k = 0; k < 4000; ++k) {  // 0.4 s: every disk has fallen below y = -0.5
        ASSERT_EQ(w.step(), dem::kStepOk);
        for (std::size_t i = 0; i < w.store().size(); ++i)
            if (w.store().y[i] < -0.0021 && std::abs(w.store().x[i]) < 0.1) ++maxRemovedAbove;  // missed one
    }
    EXPECT_EQ(maxRemovedAbove, 0u);
    std::set<ParticleId> kept(w.store().id.begin(), w.store().id.end());
    for (std::size_t k = 0; k < xs.size(); ++k)
        EXPECT_EQ(kept.count(static_cast<ParticleId>(k)) == 1, std::abs(xs[k]) > 0.1) << "x = " << xs[k];
    EXPECT_EQ(w.flow().counters().removed, 10u);
    EXPECT_TRUE(w.store().consistent());
}

TEST(ParticleFlow, RemovalKeepsContactHistoryOfTheOthers) {
    // A settled heap drained through a floor outlet: contacts of the remaining particles keep their
    // springs across the slot renumbering, so removal does not kick the pile (energy bounded).
    const std::string toml = std::string(R"(
[run]
end_time = 1.0
[dem]
dt = 2e-5
gravity = [0.0, -9.81]
[[dem.damping]]
gamma = 0.02
to = 0.3
)") + kMaterials + R"(
[[block]]
lattice = "hexagonal"
region = [-0.05, 0.002, 0.05, 0.05]
spacing = 0.0042
radius = 0.002
material = "grain"
[[wall]]
points = [[-0.06, 0.2], [-0.06, 0.0], [-0.012, 0.0]]
material = "wall"
[[wall]]
points = [[0.012, 0.0], [0.06, 0.0], [0.06, 0.2]]
material = "wall"
[[outlet]]
edge = [[0.012, 0.0], [-0.012, 0.0]]
open_at = 0.3
material = "wall"
)";
    dem::World w = test::makeWorldFromToml(toml);
    const std::size_t n0 = w.store().size();
    const Real m0 = w.totalMass();
    for (int k = 0; k < 30000; ++k) {
        ASSERT_EQ(w.step(), dem::kStepOk) << "step " << k;
        if (k % 500 == 0) {
            const auto& c = w.flow().counters();
            EXPECT_NEAR(w.totalMass(), m0 + c.massIn - c.massOut, 1e-12 * m0);
            EXPECT_EQ(w.store().size(), n0 - c.removed);
        }
    }
    EXPECT_GT(w.flow().counters().removed, 5u);
}

}  // namespace
}  // namespace granulab
