// SPDX-License-Identifier: MIT
// Event-driven engine beyond the periodic smooth gas (edmd spec 2.4-2.8, checklist items 6, 8,
// 11-16): a ball bouncing on a hard floor under gravity (impact time and apex exact, wall
// restitution), a gas in a closed box that never leaves it, rough spheres that conserve
// translational + rotational energy at eps = phi = 1 and share it equally, growing spheres
// that never overlap and re-grid, velocity-dependent restitution, and checkpoints that resume
// bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/rng.hpp"
#include "edmd/engine.hpp"
#include "gas_fixture.hpp"

using namespace granulab;
using namespace granulab::edmd;

using validation::latticeGas;
using validation::minimumGapRatio;

TEST(EdmdWalls, BallBouncesOnTheFloorWithExactImpactTimeAndApex) {
    // A disk of radius a dropped from rest at height h (centre) in a closed 2D box: it hits the
    // floor at t = sqrt(2 (h - a)/g) with speed sqrt(2 g (h - a)); elastic bounces return to h.
    const Real a = 0.01, h = 0.5, g = 9.81;
    EngineConfig c;
    c.box = {1, 1, 1};
    c.periodic = {false, false, false};
    c.gravity = {0, -g, 0};
    Engine<2> e(c, {VecD<2>{{0.5, h}}}, {VecD<2>{}}, {a}, {1.0});
    const Real impact = std::sqrt(2 * (h - a) / g);
    e.runUntil(impact * (1 - 1e-9));
    EXPECT_EQ(e.stats().wallCollisions, 0u);
    e.runUntil(impact * (1 + 1e-9));
    ASSERT_EQ(e.stats().wallCollisions, 1u);
    EXPECT_NEAR(e.velocityNow(0)[1], std::sqrt(2 * g * (h - a)), 1e-7);  // g * 1e-9 t_impact later
    // Impacts at t_impact, 3 t_impact, ...: at 20 t_impact, after 10 bounces, the ball is back
    // at its start, at rest.
    e.runUntil(impact * 20);
    EXPECT_EQ(e.stats().wallCollisions, 10u);
    EXPECT_NEAR(e.positionNow(0)[1], h, 1e-9);
    EXPECT_NEAR(e.velocityNow(0)[1], 0, 1e-9);
    EXPECT_NEAR(e.kineticEnergy() + e.potentialEnergy(), g * h, 1e-9);
}

TEST(EdmdWalls, WallRestitutionScalesTheReboundAndTheApex) {
    const Real a = 0.01, h = 0.5, g = 9.81, epsW = 0.8;
    EngineConfig c;
    c.box = {1, 1, 1};
    c.periodic = {false, false, false};
    c.gravity = {0, 0, -g};
    c.wallRestitution = epsW;
    Engine<3> e(c, {VecD<3>{{0.5, 0.5, h}}}, {VecD<3>{}}, {a}, {2.0});
    const Real t1 = std::sqrt(2 * (h - a) / g);
    const Real v1 = g * t1;
    e.runUntil(t1 * (1 + 1e-9));
    EXPECT_NEAR(e.velocityNow(0)[2], epsW * v1, 1e-7);
    // Apex after the first bounce: a + (eps v1)^2 / (2 g); the next impact 2 eps v1 / g later.
    e.runUntil(t1 + epsW * v1 / g);
    EXPECT_NEAR(e.positionNow(0)[2], a + epsW * epsW * (h - a), 1e-9);
    EXPECT_NEAR(e.dissipatedEnergy(), 0.5 * 2.0 * (1 - epsW * epsW) * v1 * v1, 1e-9);
}

TEST(EdmdWalls, ClosedBoxKeepsAnElasticGasInsideAndConservesEnergy) {
    auto gas = latticeGas<3>(8, 1.0, 0.04, 11);
    EngineConfig c;
    c.box = {1, 1, 1};
    c.periodic = {false, true, false};  // walls on x and z, periodic on y
    Engine<3> e(c, gas.x, gas.v, gas.radius, gas.mass);
    const Real e0 = e.kineticEnergy();
    Real t = 0;
    while (e.stats().collisions < 100000) e.runUntil(t += 0.05);
    Real worstOutside = 0;
    for (std::uint32_t i = 0; i < e.size(); ++i)
        for (int d : {0, 2}) {
            const Real x = e.positionNow(i)[d];
            worstOutside = std::max({worstOutside, 0.04 - x, x - (1 - 0.04)});
        }
    std::printf("closed box: %llu collisions, %llu wall collisions, dE/E %.2e, worst wall overlap %.2e m\n",
                (unsigned long long)e.stats().collisions, (unsigned long long)e.stats().wallCollisions,
                e.kineticEnergy() / e0 - 1, worstOutside);
    EXPECT_GT(e.stats().wallCollisions, 1000u);
    EXPECT_NEAR(e.kineticEnergy() / e0, 1.0, 1e-10);
    EXPECT_LT(worstOutside, 1e-12);
    EXPECT_GT(minimumGapRatio(e), 1 - 1e-9);
}

TEST(EdmdWalls, InelasticGasSettlesOnTheFloorWithTheTcModel) {
    // 2D, eps = 0.7 with the floor at eps_w = 0.7: without the TC model the settling grains
    // would collapse inelastically (infinitely many collisions); with t_c the run completes
    // and the bed settles on the floor, nobody below it. A resting bed keeps a little energy
    // in TC-elastic micro-collisions and costs ~1/t_c collisions per grain per second, so t_c
    // is 1 ms here (a resting bed is the worst case of event-driven dynamics).
    auto gas = latticeGas<2>(10, 1.0, 0.02, 12);
    EngineConfig c;
    c.box = {1, 1, 1};
    c.periodic = {true, false, false};
    c.gravity = {0, -9.81, 0};
    c.restitution.eps = 0.7;
    c.wallRestitution = 0.7;
    c.tc = 1e-3;
    Engine<2> e(c, gas.x, gas.v, gas.radius, gas.mass);
    const Real kinetic0 = e.kineticEnergy();
    const Real e0 = kinetic0 + e.potentialEnergy();
    e.runUntil(1.5);
    Real lowest = 1, highest = 0;
    for (std::uint32_t i = 0; i < e.size(); ++i) {
        lowest = std::min(lowest, e.positionNow(i)[1]);
        highest = std::max(highest, e.positionNow(i)[1]);
    }
    std::printf(
        "settling: %llu events, %llu collisions (%llu TC-elastic), KE %.3e J, lowest %.6f highest %.4f m\n",
        (unsigned long long)e.stats().events, (unsigned long long)e.stats().collisions,
        (unsigned long long)e.stats().tcElastic, e.kineticEnergy(), lowest, highest);
    EXPECT_GT(lowest, 0.02 - 1e-12);
    // 100 disks of diameter 0.04 in a 1 m wide box: 4 layers; the bed top below 0.2 m.
    EXPECT_LT(highest, 0.2);
    EXPECT_LT(e.kineticEnergy(), 1e-2 * kinetic0);  // 99 % of the motion dissipated
    EXPECT_NEAR(e0 - (e.kineticEnergy() + e.potentialEnergy()), e.dissipatedEnergy(), 1e-9 * std::abs(e0));
}

TEST(EdmdRough, PerfectlyRoughElasticSpheresConserveEnergyAndShareItEqually) {
    auto gas = latticeGas<3>(8, 1.0, 0.05, 13);
    EngineConfig c;
    c.tangentialRestitution = 1;  // phi = +1, eps = 1: energy conserved (spec 2.5.2 acceptance)
    c.inertiaFactor = 0.4;
    Engine<3> e(c, gas.x, gas.v, gas.radius, gas.mass);
    const Real e0 = e.kineticEnergy();
    Real t = 0, ratioSum = 0;
    int samples = 0;
    while (e.stats().collisions < 200000) {
        e.runUntil(t += 0.02);
        if (e.stats().collisions > 50000) {  // equilibrated: average the rotational share
            ratioSum += e.rotationalEnergy() / e.kineticEnergy();
            ++samples;
        }
    }
    const Real total = e.kineticEnergy() + e.rotationalEnergy();
    const Real ratio = ratioSum / samples;
    std::printf("rough spheres: dE/E %.2e, <E_rot/E_trans> = %.4f over %d samples\n", total / e0 - 1, ratio,
                samples);
    EXPECT_NEAR(total / e0, 1.0, 1e-10);
    // Equipartition: 3 rotational and 3 translational degrees of freedom. N = 512 gives
    // fluctuations of the ratio of ~sqrt(4/(3N)) = 5 % per sample; the average over
    // correlated samples is good to ~1 %; 5 % is a safe bound that a wrong spin update fails.
    EXPECT_NEAR(ratio, 1.0, 0.05);
}

TEST(EdmdRough, RoughDisksShareEnergyOneToTwo) {
    auto gas = latticeGas<2>(20, 1.0, 0.01, 14);
    EngineConfig c;
    c.tangentialRestitution = 1;
    c.inertiaFactor = 0.5;
    Engine<2> e(c, gas.x, gas.v, gas.radius, gas.mass);
    const Real e0 = e.kineticEnergy();
    Real t = 0, ratioSum = 0;
    int samples = 0;
    while (e.stats().collisions < 200000) {
        e.runUntil(t += 0.05);
        if (e.stats().collisions > 50000) {
            ratioSum += e.rotationalEnergy() / e.kineticEnergy();
            ++samples;
        }
    }
    std::printf("rough disks: <E_rot/E_trans> = %.4f (equipartition 0.5)\n", ratioSum / samples);
    EXPECT_NEAR((e.kineticEnergy() + e.rotationalEnergy()) / e0, 1.0, 1e-10);
    EXPECT_NEAR(ratioSum / samples, 0.5, 0.03);  // 1 rotational vs 2 translational degrees
}

TEST(EdmdGrowing, GrowingSpheresNeverOverlapAndReGrid) {
    // 3D, 512 spheres from nu = 0.1 to nu = 0.4 at u_a = 1e-3 <v>: elastic rule (2.17) adds
    // energy, the cells are rebuilt as the spheres outgrow them, and no pair ever overlaps.
    const int n = 8;
    const Real L = 1;
    const Real a0 = std::cbrt(0.1 * L * L * L / (512 * 4.0 / 3.0 * kPi));
    const Real a1 = std::cbrt(0.4 * L * L * L / (512 * 4.0 / 3.0 * kPi));
    auto gas = latticeGas<3>(n, L, a0, 15);
    EngineConfig c;
    c.growthRate = 2e-3;
    Engine<3> e(c, gas.x, gas.v, gas.radius, gas.mass);
    const Real e0 = e.kineticEnergy();
    const Real tEnd = (a1 - a0) / c.growthRate;
    Real worst = 2;
    for (int k = 1; k <= 20; ++k) {
        e.runUntil(tEnd * k / 20);
        worst = std::min(worst, minimumGapRatio(e));
    }
    std::printf(
        "growing: a %.4f -> %.4f, %llu collisions, %llu regrids, cells %d, E/E0 %.3f, min gap %.15f\n", a0,
        e.radius(0), (unsigned long long)e.stats().collisions, (unsigned long long)e.stats().regrids,
        e.cellsPerAxis()[0], e.kineticEnergy() / e0, worst);
    EXPECT_NEAR(e.radius(0), a1, 1e-12);
    EXPECT_GT(e.stats().regrids, 0u);
    EXPECT_GT(worst, 1 - 1e-9);
    EXPECT_GT(e.kineticEnergy(), e0);  // growth pumps energy in (Eq. 2.17)
}

TEST(EdmdRestitution, SpeedDependentModelsHaveTheirLimits) {
    Restitution mf{RestitutionModel::McNamaraFalcon, 0.6, 2.0};
    EXPECT_DOUBLE_EQ(mf(0), 1.0);
    EXPECT_DOUBLE_EQ(mf(2.0), 0.6);
    EXPECT_DOUBLE_EQ(mf(5.0), 0.6);
    EXPECT_NEAR(mf(1.0), 1 - 0.4 * std::pow(0.5, 0.75), 1e-15);
    Restitution ve{RestitutionModel::Viscoelastic, 1, 1.0};
    EXPECT_DOUBLE_EQ(ve(0), 1.0);
    EXPECT_GT(ve(1e-3), ve(1e-2));
    EXPECT_GT(ve(1e-2), ve(1e-1));
    EXPECT_NEAR(ve(1.0), 1 - 1.15344 + 0.79826, 1e-12);
    // In the engine: a head-on pair at relative speed 1 with v0 = 2 leaves at eps(1) * 1.
    EngineConfig c;
    c.restitution = mf;
    Engine<2> e(c, {VecD<2>{{0.3, 0.5}}, VecD<2>{{0.7, 0.5}}}, {VecD<2>{{0.5, 0}}, VecD<2>{{-0.5, 0}}},
                {0.05, 0.05}, {1.0, 1.0});
    e.runUntil(0.4);
    ASSERT_EQ(e.stats().collisions, 1u);
    EXPECT_NEAR(e.velocityNow(1)[0] - e.velocityNow(0)[0], mf(1.0), 1e-14);
}

TEST(EdmdCheckpoint, ResumedRunMatchesAnUninterruptedOneBitForBit) {
    // Walls, gravity, TC, rough spheres and inelastic collisions all at once.
    auto gas = latticeGas<3>(6, 1.0, 0.05, 16);
    EngineConfig c;
    c.periodic = {true, true, false};
    c.gravity = {0, 0, -1};
    c.restitution.eps = 0.8;
    c.wallRestitution = 0.9;
    c.tangentialRestitution = 0.5;
    c.tc = 1e-4;
    Engine<3> a(c, gas.x, gas.v, gas.radius, gas.mass);
    a.runUntil(0.5);
    std::stringstream saved;
    a.saveState(saved);
    a.runUntil(1.0);
    Engine<3> b(c, gas.x, gas.v, gas.radius, gas.mass);
    b.loadState(saved);
    EXPECT_EQ(b.time(), 0.5);
    b.runUntil(1.0);
    ASSERT_GT(a.stats().collisions, 1000u);
    EXPECT_EQ(a.stats().events, b.stats().events);
    EXPECT_EQ(a.dissipatedEnergy(), b.dissipatedEnergy());
    for (std::uint32_t i = 0; i < a.size(); ++i)
        for (int d = 0; d < 3; ++d) {
            ASSERT_EQ(a.positionNow(i)[d], b.positionNow(i)[d]);
            ASSERT_EQ(a.velocityNow(i)[d], b.velocityNow(i)[d]);
            ASSERT_EQ(a.omega(i)[d], b.omega(i)[d]);
        }
}
