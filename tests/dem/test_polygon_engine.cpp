// SPDX-License-Identifier: MIT
// The gc2d area-law kernel term by term (gc2d spec sections 3.2-3.7, errata 1-5), and the
// polygon pipeline's broad phases: sort-and-sweep and the cell grid find exactly the
// brute-force candidate pairs on random grain scenes, so whole runs are bit-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "../support.hpp"
#include "app/dem/dem_engine.hpp"
#include "dem/broad_phase.hpp"
#include "dem/forces_area.hpp"

using namespace granulab;
using namespace granulab::dem;

namespace {
/// A contact with area A between bodies whose contact point lies r_i, r_j from the centres.
area::AreaPair pairWith(Real area, Real ri, Real rj, Vec2 vi = {}, Vec2 vj = {}) {
    area::AreaPair c;
    c.g.touching = true;
    c.g.area = area;
    c.g.c1 = {0, -0.5e-3};  // contact line along y, L_c = 1 mm
    c.g.c2 = {0, 0.5e-3};
    c.g.point = {0, 0};
    c.g.normal = {1, 0};  // i sits at +x, j at -x: n pushes i away from j; t = perp(n) = +y
    c.ri = {-ri, 0};
    c.rj = {rj, 0};
    c.vi = vi;
    c.vj = vj;
    c.di = vi;
    c.dj = vj;
    c.hasDrift = true;
    c.invMi = 1 / 0.02;
    c.invMj = 1 / 0.03;
    c.invIi = 1.0 / 1e-8;
    c.invIj = 1.0 / 2e-8;
    return c;
}
}  // namespace

TEST(AreaLaw, ElasticForceIsEAOverL) {
    const AreaNormal nl{1e7, 0};
    Real xi = 0, aOld = 0;
    const auto f =
        area::areaLaw(nl, NoDamping{}, NoFriction{}, pairWith(2e-9, 1e-3, 3e-3), 1e-6, 1 / 1e-6, xi, aOld);
    const Real l = 1e-3 * 3e-3 / 4e-3;
    EXPECT_NEAR(f.onI.x, 1e7 * 2e-9 / l, 1e-12);  // Eq. 2.20, along n
    EXPECT_EQ(f.onI.y, 0.0);
    EXPECT_DOUBLE_EQ(aOld, 2e-9);  // Old_Area stored
    // Wall: infinite lever arm, l = r_i (spec 3.7).
    auto w = pairWith(2e-9, 1e-3, 0);
    w.wall = true;
    const auto fw = area::areaLaw(nl, NoDamping{}, NoFriction{}, w, 1e-6, 1 / 1e-6, xi, aOld);
    EXPECT_NEAR(fw.onI.x, 1e7 * 2e-9 / 1e-3, 1e-12);
}

TEST(AreaLaw, DampingUsesDeltaAreaOverLDtAndNeverAttracts) {
    const AreaNormal nl{1e7, 0};
    const AreaDamping dl{0.5};
    const Real dt = 1e-6, ri = 1e-3, rj = 1e-3, l = 0.5e-3;
    const Real mperp = 0.02 * 0.03 / 0.05;
    Real xi = 0, aOld = 1e-9;
    // Approaching: A grows by 1e-10 m^2 in one step (erratum 1: divide by l).
    auto f = area::areaLaw(nl, dl, NoFriction{}, pairWith(1.1e-9, ri, rj), dt, 1 / dt, xi, aOld);
    const Real fel = 1e7 * 1.1e-9 / l;
    EXPECT_NEAR(f.onI.x, fel + 0.5 * std::sqrt(1e7 * mperp) * 1e-10 / (l * dt), 1e-9 * fel);
    // Separating fast: the damping is clipped at -F_el, the total never attractive.
    aOld = 5e-9;
    f = area::areaLaw(nl, dl, NoFriction{}, pairWith(1e-9, ri, rj), dt, 1 / dt, xi, aOld);
    EXPECT_GE(f.onI.x, 0.0);
    EXPECT_NEAR(f.onI.x, 0.0, 1e-12);
    // Separating slowly: not clipped, total reduced but positive.
    aOld = 1.0001e-9;
    f = area::areaLaw(nl, dl, NoFriction{}, pairWith(1e-9, ri, rj), dt, 1 / dt, xi, aOld);
    EXPECT_LT(f.onI.x, 1e7 * 1e-9 / l);
    EXPECT_GT(f.onI.x, 0.0);
}

TEST(AreaLaw, CundallStrackSpringViscousTermAndCap) {
    const AreaNormal nl{1e7, 0};
    AreaFriction fr;
    fr.mu = 0.5;
    fr.kt = 2.0 / 7.0 * 1e7;
    const Real dt = 1e-6, ri = 1e-3, rj = 2e-3;
    Real xi = 0, aOld = 0;
    // i slides along t = perp(n) = +y relative to j at 1 mm/s: spring and damper oppose it.
    auto c = pairWith(1e-9, ri, rj, {0, 1e-3}, {0, 0});
    const auto f = area::areaLaw(nl, NoDamping{}, fr, c, dt, 1 / dt, xi, aOld);
    EXPECT_NEAR(xi, 1e-3 * dt, 1e-20);  // Eq. 2.23: S = k_t xi grows by k_t v dt
    const Real invMpar = 1 / 0.02 + 1 / 0.03 + ri * ri / 1e-8 + rj * rj / 2e-8;
    const Real expected = fr.kt * xi + std::sqrt(fr.kt / invMpar) * 1e-3;  // Eq. 2.26
    EXPECT_NEAR(f.onI.y, -expected, 1e-12 * expected);
    // Far past the cap: |F_par| = mu F_el and the spring is clipped to the cap (erratum 3).
    const Real fel = 1e7 * 1e-9 * (ri + rj) / (ri * rj);
    xi = 1.0;
    const auto g = area::areaLaw(nl, NoDamping{}, fr, c, dt, 1 / dt, xi, aOld);
    EXPECT_NEAR(g.onI.y, -0.5 * fel, 1e-12 * fel);
    EXPECT_NEAR(fr.kt * xi, 0.5 * fel, 1e-12 * fel);
    // Rabinowicz: the cap mu (|v|/1 m/s)^(-1/10) F_el exceeds Coulomb's for |v| < 1 m/s.
    fr.rabinowicz = true;
    xi = 1.0;
    const auto h = area::areaLaw(nl, NoDamping{}, fr, c, dt, 1 / dt, xi, aOld);
    EXPECT_NEAR(h.onI.y, -0.5 * std::pow(1e-3, -0.1) * fel, 1e-12 * fel);
}

TEST(AreaLaw, CohesionPullsAlongMinusNormalWithContactLength) {
    const AreaNormal nl{1e7, 2e4};
    Real xi = 0, aOld = 0;
    const auto f =
        area::areaLaw(nl, NoDamping{}, NoFriction{}, pairWith(1e-12, 1e-3, 1e-3), 1e-6, 1 / 1e-6, xi, aOld);
    EXPECT_NEAR(f.onI.x, 1e7 * 1e-12 / 0.5e-3 - 2e4 * 1e-3, 1e-12);  // Eq. 2.28: L_c = 1 mm
    EXPECT_LT(f.onI.x, 0.0);                                         // attractive at this tiny overlap
}

namespace {
const char* kGrainBox = R"(
[run]
end_time = 0.004
seed = 11
[dem]
dt = 2e-6
gravity = [0, -9.81]
sort_every = 4
[[material]]
name = "grain"
density = 5000
[[contact]]
materials = ["*", "*"]
normal = "area"
E = 1e7
damping = "gamma"
gamma = 0.5
tangential = "gc2d"
mu = 0.6
[[shape]]
name = "sand"
kind = "grain"
size = [0.0015, 0.001]
size_mode = "equal"
size_variation = 0.1
corner_count = 7
corner_count_mode = "equal"
corner_variation = 3
corner_angles = "rand2"
rotation_mode = "equal"
[[shape]]
name = "hex"
kind = "regular"
corner_count = 6
radius = 0.0012
[[block]]
shape = "sand"
lattice = "hexagonal"
spacing = 0.0034
region = [0, 0, 0.06, 0.04]
material = "grain"
temperature = 2e-3
[[block]]
shape = "hex"
lattice = "random"
count = 30
region = [0, 0.04, 0.06, 0.06]
material = "grain"
temperature = 2e-3
[[block]]
lattice = "random"
count = 30
region = [0, 0.06, 0.06, 0.08]
radius = 0.001
material = "grain"
temperature = 2e-3
[[wall]]
points = [[-0.002, 0.1], [-0.002, -0.002], [0.062, -0.002], [0.062, 0.1]]
material = "grain"
)";
}  // namespace

TEST(PolygonEngine, BroadPhasesAgreeAndRunsAreBitIdentical) {
    std::vector<std::vector<Real>> finals;
    for (const char* bp : {"brute_force", "sort_and_sweep", "cell_grid"}) {
        dem::World w = test::makeWorldFromToml(kGrainBox, {{"dem.broad_phase", bp}});
        for (int k = 0; k < 3000; ++k) ASSERT_EQ(w.step(), 0u) << bp << " step " << k;
        std::vector<Real> state(w.store().size() * 3);
        for (std::size_t i = 0; i < w.store().size(); ++i) {
            const auto id = w.store().id[i];
            state[3 * id] = w.store().x[i];
            state[3 * id + 1] = w.store().y[i];
            state[3 * id + 2] = w.store().angle[i];
        }
        EXPECT_GT(w.forceStats().contacts, 5u) << bp;
        finals.push_back(state);
        // Candidate pairs of the settled-in state: every broad phase finds the brute-force set.
        std::vector<std::uint64_t> ref, sap, grid;
        const Real margin = 2e-4;
        dem::BruteForce().findPairs(w.store(), margin, ref);
        dem::SortAndSweep().findPairs(w.store(), margin, sap);
        dem::CellGrid().findPairs(w.store(), margin, grid);
        EXPECT_GT(ref.size(), 100u);
        EXPECT_EQ(ref, sap);
        EXPECT_EQ(ref, grid);
    }
    // Sort-and-sweep and the cell grid re-sort the slots along the same Morton curve and find the
    // same sorted pairs, so the force sums run in the same order and the runs agree bit for bit.
    // Brute force keeps the slot order (a different but equally deterministic summation order),
    // so only its pair sets are compared.
    EXPECT_EQ(finals[1], finals[2]);
}

TEST(PolygonEngine, TimeStepAdviceCoversFlatFaces) {
    // A 10 x 2 mm block (0.1 kg at 5000 kg/m^2) on a floor: the gc2d rule (pi/10) sqrt(m/E) =
    // 3.14e-5 s assumes round grains; its long face is 2 L/r_in = 20 times stiffer between two
    // blocks (E L / l, l >= r_in/2), so dt must stay below 3.14e-5 / sqrt(20) = 7.0e-6 s. A run at
    // 3e-5 s bounces the block off the floor, one at 4e-6 s is clean (measured while writing the
    // friction tests); the face bound warns for the first and not the second.
    const std::string scene = R"(
[run]
end_time = 0.01
[dem]
gravity = [0, -9.81]
[[material]]
name = "m"
density = 5000
[[contact]]
materials = ["*", "*"]
normal = "area"
E = 1e7
damping = "gamma"
gamma = 0.5
tangential = "gc2d"
mu = 0.5
[[shape]]
name = "block"
kind = "rectangle"
size = [0.01, 0.002]
[[particle]]
shape = "block"
position = [0, 0.0011]
material = "m"
[[wall]]
points = [[-1, 0], [1, 0]]
material = "m"
)";
    const auto validateAt = [&](const char* dt) {
        return app::checkAndPrepareDem(test::readSceneText(scene, "block.toml", {{"dem.dt", dt}}));
    };
    const auto coarse = validateAt("3e-5");
    EXPECT_NEAR(coarse.advice.areaAdvisedDt, kPi / 10 * std::sqrt(0.1 / 1e7), 1e-12);
    EXPECT_NEAR(coarse.advice.faceAdvisedDt, coarse.advice.areaAdvisedDt / std::sqrt(20.0), 1e-12);
    ASSERT_EQ(coarse.warnings.size(), 1u);
    EXPECT_NE(coarse.warnings[0].find("flat faces"), std::string::npos) << coarse.warnings[0];
    EXPECT_TRUE(validateAt("4e-6").warnings.empty());
}
