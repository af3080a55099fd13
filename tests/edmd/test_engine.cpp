// SPDX-License-Identifier: MIT
// Serial event-driven engine (edmd spec section 2): an elastic gas of disks and of spheres
// conserves energy and momentum to round-off over 1e5 collisions and never overlaps; the three
// event queues give the same trajectories bit for bit (deterministic ties); an inelastic gas
// loses energy, collision by collision, as (m/4)(1 - eps^2) v_n^2 predicts on average.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "edmd/engine.hpp"
#include "gas_fixture.hpp"

using namespace granulab;
using namespace granulab::edmd;
using validation::minimumGapRatio;

namespace {
template <int D, class Queue>
Engine<D, Queue> gas(int n, Real fraction, Real eps, std::uint64_t seed) {
    const Real box = 1.0;
    int count = 1;
    for (int d = 0; d < D; ++d) count *= n;
    // packing fraction = count * volume(a) / box^D
    const Real unitVolume = D == 2 ? kPi : 4.0 / 3.0 * kPi;
    const Real a = std::pow(fraction * std::pow(box, D) / (count * unitVolume), 1.0 / D);
    auto g = validation::latticeGas<D>(n, box, a, seed);
    auto& x = g.x;
    auto& v = g.v;
    EngineConfig c;
    c.box = {box, box, box};
    c.restitution.eps = eps;
    return Engine<D, Queue>(c, x, v, std::vector<Real>(x.size(), a), std::vector<Real>(x.size(), 1.0));
}

}  // namespace

TEST(EdmdEngine, ElasticDisksConserveEnergyAndMomentumAndNeverOverlap) {
    auto e = gas<2, CalendarQueue>(20, 0.3, 1.0, 1);
    const Real e0 = e.kineticEnergy();
    Real t = 0;
    while (e.stats().collisions < 100000) e.runUntil(t += 0.05);
    const auto p = e.momentum();
    std::printf(
        "disks: %llu collisions, %llu events (%llu annulled, %llu cell crossings), dE/E %.2e, |P| %.2e, "
        "min gap / contact %.15f\n",
        (unsigned long long)e.stats().collisions, (unsigned long long)e.stats().events,
        (unsigned long long)e.stats().annulled, (unsigned long long)e.stats().cellCrossings,
        e.kineticEnergy() / e0 - 1, std::sqrt(dot(p, p)), minimumGapRatio(e));
    EXPECT_NEAR(e.kineticEnergy() / e0, 1.0, 1e-10);  // round-off of 1e5 collision rules
    EXPECT_LT(std::sqrt(dot(p, p)), 1e-9);
    EXPECT_GT(minimumGapRatio(e), 1 - 1e-9);
}

TEST(EdmdEngine, ElasticSpheresConserveEnergyAndNeverOverlap) {
    auto e = gas<3, CalendarQueue>(8, 0.3, 1.0, 2);
    const Real e0 = e.kineticEnergy();
    Real t = 0;
    while (e.stats().collisions < 100000) e.runUntil(t += 0.05);
    std::printf("spheres: %llu collisions, dE/E %.2e, min gap / contact %.15f\n",
                (unsigned long long)e.stats().collisions, e.kineticEnergy() / e0 - 1, minimumGapRatio(e));
    EXPECT_NEAR(e.kineticEnergy() / e0, 1.0, 1e-10);
    EXPECT_GT(minimumGapRatio(e), 1 - 1e-9);
}

TEST(EdmdEngine, QueuesGiveIdenticalTrajectories) {
    auto a = gas<2, AddressableHeap>(12, 0.4, 0.9, 3);
    auto b = gas<2, TournamentTree>(12, 0.4, 0.9, 3);
    auto c = gas<2, CalendarQueue>(12, 0.4, 0.9, 3);
    a.runUntil(2.0);
    b.runUntil(2.0);
    c.runUntil(2.0);
    EXPECT_GT(a.stats().collisions, 2000u);
    EXPECT_EQ(a.stats().events, b.stats().events);
    EXPECT_EQ(a.stats().events, c.stats().events);
    for (std::uint32_t i = 0; i < a.size(); ++i) {
        for (int d = 0; d < 2; ++d) {
            ASSERT_EQ(a.positionNow(i)[d], b.positionNow(i)[d]);
            ASSERT_EQ(a.positionNow(i)[d], c.positionNow(i)[d]);
            ASSERT_EQ(a.velocityNow(i)[d], c.velocityNow(i)[d]);
        }
    }
}

TEST(EdmdEngine, InelasticGasCools) {
    auto e = gas<2, CalendarQueue>(16, 0.1, 0.9, 4);
    const Real e0 = e.kineticEnergy();
    e.runUntil(0.2);
    const Real e1 = e.kineticEnergy();
    EXPECT_LT(e1, e0);
    const auto p = e.momentum();
    EXPECT_LT(std::sqrt(dot(p, p)), 1e-9);
}

TEST(EdmdEngine, TcModelMakesQuickRepeatCollisionsElastic) {
    // Two disks on the x axis of a periodic box of 1 m approach at 2 m/s, collide (eps = 0.5),
    // and meet again through the boundary after (1 - 2 s)/v_rel. With t_c longer than that
    // interval the second collision is elastic, with t_c shorter it is inelastic again.
    for (const Real tc : {0.0, 10.0}) {
        EngineConfig c;
        c.box = {1.0, 1.0, 1.0};
        c.restitution.eps = 0.5;
        c.tc = tc;
        const Real a = 0.05;
        Engine<2, CalendarQueue> e(c, {VecD<2>{{0.3, 0.5}}, VecD<2>{{0.7, 0.5}}},
                                   {VecD<2>{{1, 0}}, VecD<2>{{-1, 0}}}, {a, a}, {1.0, 1.0});
        e.runUntil(0.16);  // first contact at t = (0.4 - 0.1)/2 = 0.15
        ASSERT_EQ(e.stats().collisions, 1u);
        EXPECT_NEAR(e.velocityNow(0)[0] - e.velocityNow(1)[0], -1.0, 1e-14);  // |v_rel| 2 -> 1
        e.runUntil(1.0);  // second contact 0.8 s later (gap 1 - 4 a at 1 m/s) through the boundary
        ASSERT_EQ(e.stats().collisions, 2u);
        const Real vrel = std::abs(e.velocityNow(0)[0] - e.velocityNow(1)[0]);
        EXPECT_NEAR(vrel, tc > 0 ? 1.0 : 0.5, 1e-14) << "tc " << tc;
    }
}
