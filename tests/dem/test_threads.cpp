// SPDX-License-Identifier: MIT
// The threaded DEM step (gc2d spec section 5.4; docs/physics/dem-threads.md): the same scene gives
// the same state bit for bit on 1, 2, 3 and 4 threads (disks with rolling resistance and walls,
// polygons with the Gear integrator, an iterating predictor-corrector, particles leaving through
// an outlet and entering from a source), and splitting the slots into many tiles changes the
// forces only by round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support.hpp"
#include "../support/dem_scenes.hpp"
#include "core/parallel.hpp"
#include "dem/broad_phase.hpp"

using namespace granulab;

namespace {

/// The dense rolling bed of tests/support/dem_scenes.hpp.
const std::string& kDiskBed = test::kRollingDiskBed;

std::string fileText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// examples/machines/pile_dropsource.toml (7-gons poured from a source onto a body floor) with 400
/// grains more on a lattice above the floor, moving in random directions so that they collide
/// within a few hundred steps.
std::string pileWithBed() {
    return fileText(std::string(GRANULAB_SOURCE_DIR) + "/examples/machines/pile_dropsource.toml") + R"(
[[block]]
shape = "grain"
lattice = "hexagonal"
spacing = 3.6e-3
region = [-0.09, 0.0018, 0.09, 0.1]
count = 400
material = "sand"
speed_range = [0.3, 0.6]
)";
}

/// Every column of the state that the step writes, and the wall forces and contact count.
struct Snapshot {
    std::vector<Real> columns;
    std::vector<ParticleId> ids;
    std::uint64_t contacts = 0;
    bool operator==(const Snapshot& o) const {
        if (ids != o.ids || contacts != o.contacts || columns.size() != o.columns.size()) return false;
        for (std::size_t k = 0; k < columns.size(); ++k)  // bitwise: NaN or -0 differences count
            if (std::memcmp(&columns[k], &o.columns[k], sizeof(Real)) != 0) return false;
        return true;
    }
};

Snapshot snapshotOf(const dem::World& w) {
    Snapshot snap;
    const auto& s = w.store();
    for (const auto* col : {&s.x, &s.y, &s.angle, &s.vx, &s.vy, &s.omega, &s.fx, &s.fy, &s.torque})
        snap.columns.insert(snap.columns.end(), col->begin(), col->end());
    for (const Vec2 f : w.wallForce()) {
        snap.columns.push_back(f.x);
        snap.columns.push_back(f.y);
    }
    for (const auto* l : {&w.neighbors().pairs, &w.neighbors().wallPairs})
        snap.columns.insert(snap.columns.end(), l->xi.begin(), l->xi.end());
    const dem::Energies e = w.energies();
    snap.columns.push_back(e.total());
    snap.columns.push_back(e.elastic);
    snap.ids = s.id;
    snap.contacts = w.forceStats().contacts + w.forceStats().wallContacts;
    return snap;
}

/// The state after `steps` steps of `toml` on `threads` threads.
Snapshot runOn(const std::string& toml, int threads, int steps, std::vector<io::Override> overrides = {}) {
    overrides.push_back(io::parseOverride("run.threads=" + std::to_string(threads)));
    dem::World w = test::makeWorldFromToml(toml, overrides);
    EXPECT_EQ(w.threads(), threads);
    w.setParticlesPerThread(16);  // small scenes on every thread asked for
    EXPECT_EQ(w.team(), threads);
    for (int k = 0; k < steps; ++k) {
        const std::uint32_t status = w.step();
        EXPECT_EQ(status, dem::kStepOk) << "step " << k;
        if (status != dem::kStepOk) break;
    }
    return snapshotOf(w);
}

void expectSameOnAllThreadCounts(const std::string& toml, int steps,
                                 const std::vector<io::Override>& overrides, std::size_t minTiles,
                                 std::uint64_t minContacts) {
    const Snapshot one = runOn(toml, 1, steps, overrides);
    ASSERT_GT(one.ids.size(), 0u);
    EXPECT_GE(one.contacts, minContacts) << "too few contacts to test the force sums";
    // Enough slots for several tiles: otherwise the test would not exercise the cross pairs.
    ASSERT_GE(dem::SlotTiles::forParticles(one.ids.size()).count, minTiles);
    for (const int threads : {2, 3, 4})
        EXPECT_TRUE(runOn(toml, threads, steps, overrides) == one) << threads << " threads";
}

}  // namespace

TEST(DemThreads, DiskBedWithRollingAndWallsIsBitIdentical) {
    expectSameOnAllThreadCounts(kDiskBed, 400, {}, 8, 300);
}

TEST(DemThreads, IteratingPredictorCorrectorIsBitIdentical) {
    expectSameOnAllThreadCounts(
        kDiskBed, 150, {io::parseOverride("dem.integrator=\"pc\""), io::parseOverride("dem.pc_iterations=3")},
        8, 200);
}

TEST(DemThreads, PolygonsWithGearAndSourceAreBitIdentical) {
    // A point-source pile of 7-gons on a body floor, fed fast from a pre-filled bed, so that grains
    // enter (the lists regrouped by the tiles of the new count) while 400 others are in contact.
    expectSameOnAllThreadCounts(pileWithBed(), 600, {io::parseOverride("source[0].interval=5e-4")}, 3, 40);
}

TEST(DemThreads, SiloDischargeThroughAnOutletIsBitIdentical) {
    // Particles leave through the orifice from the first steps: slots renumbered, lists regrouped.
    const std::string silo =
        fileText(std::string(GRANULAB_SOURCE_DIR) + "/examples/machines/silo_discharge.toml");
    const std::vector<io::Override> sets = {io::parseOverride("outlet[0].open_at=0.0"),
                                            io::parseOverride("outlet[1].region=[-1.0,-1.0,1.2,0.05]")};
    const Snapshot one = runOn(silo, 1, 300, sets);
    EXPECT_TRUE(runOn(silo, 2, 300, sets) == one);
    EXPECT_TRUE(runOn(silo, 3, 300, sets) == one);
}

namespace {
/// One force evaluation of the state of `w` with one tile and with tiles of 16 slots (most pairs
/// cross a tile border): every force and torque agrees to round-off, the springs are identical.
void expectTilingsAgree(const dem::World& w, std::uint64_t minContacts) {
    const auto evaluate = [&](std::uint32_t minTileSlots, model::ParticleStore& s, dem::NeighborList& list,
                              std::vector<Vec2>& wallForce, int threads) {
        s = w.store();
        list.minTileSlots = minTileSlots;
        dem::CellGrid grid;
        list.rebuild(s, w.walls(), w.config().skin, 0, grid, w.laws(), {}, false);
        // The springs of the world, carried over by pair key.
        for (const auto* src : {&w.neighbors().pairs, &w.neighbors().wallPairs}) {
            dem::ContactList& dst = src == &w.neighbors().pairs ? list.pairs : list.wallPairs;
            for (std::size_t p = 0; p < src->size(); ++p)
                for (std::size_t q = 0; q < dst.size(); ++q)
                    if (dst.first[q] == src->first[p] && dst.second[q] == src->second[p]) {
                        dst.xi[q] = src->xi[p];
                        if (!src->zeta.empty()) dst.zeta[q] = src->zeta[p];
                        if (!src->areaOld.empty()) dst.areaOld[q] = src->areaOld[p];
                    }
        }
        wallForce.assign(w.walls().walls.size(), Vec2{});
        dem::ShapeContext shapes;
        shapes.pool = &w.shapes();
        shapes.anyPolygon = w.shapes().size() > 0;
        shapes.scale = w.sizeScale();
        dem::ForceStats stats;
        dem::ForceWorkspace ws;
        ws.threads = threads;
        const std::vector<Real> still(s.size(), 0.0);
        dem::computeForces(s, w.walls(), list, w.laws(), {}, {still.data(), still.data(), still.data()},
                           w.config().dt, false, stats, wallForce, shapes, nullptr, &ws);
        return stats;
    };
    model::ParticleStore one, many;
    dem::NeighborList listOne, listMany;
    std::vector<Vec2> wallOne, wallMany;
    const auto statsOne = evaluate(1u << 30, one, listOne, wallOne, 1);
    const auto statsMany = evaluate(16, many, listMany, wallMany, 2);
    ASSERT_EQ(listOne.tiles.count, 1u);
    ASSERT_GE(listMany.tiles.count, one.size() / 16);
    ASSERT_GT(listMany.crossPairs(), listMany.pairs.size() / 4) << "most tiles should share pairs";
    EXPECT_EQ(statsOne.contacts, statsMany.contacts);
    EXPECT_EQ(statsOne.wallContacts, statsMany.wallContacts);
    EXPECT_GE(statsOne.contacts, minContacts);
    Real scale = 0;  // the largest force and torque: round-off is relative to the sums
    for (std::size_t i = 0; i < one.size(); ++i)
        scale = std::max({scale, std::abs(one.fx[i]), std::abs(one.fy[i]), std::abs(one.torque[i])});
    for (std::size_t i = 0; i < one.size(); ++i) {
        EXPECT_NEAR(many.fx[i], one.fx[i], 1e-12 * scale) << i;
        EXPECT_NEAR(many.fy[i], one.fy[i], 1e-12 * scale) << i;
        EXPECT_NEAR(many.torque[i], one.torque[i], 1e-12 * scale) << i;
    }
    for (std::size_t k = 0; k < wallOne.size(); ++k)
        EXPECT_NEAR(norm(wallMany[k] - wallOne[k]), 0, 1e-12 * scale);
    // The same pairs, each with the same spring: sort both by key to compare.
    const auto springs = [](const dem::ContactList& l) {
        std::vector<std::pair<std::uint64_t, Real>> v;
        for (std::size_t p = 0; p < l.size(); ++p)
            v.push_back({dem::pairKey(l.first[p], l.second[p]), l.xi[p]});
        std::sort(v.begin(), v.end());
        return v;
    };
    EXPECT_EQ(springs(listOne.pairs), springs(listMany.pairs));
    EXPECT_EQ(springs(listOne.wallPairs), springs(listMany.wallPairs));
}
}  // namespace

TEST(DemThreads, ManyTilesChangeDiskForcesOnlyByRoundOff) {
    dem::World w = test::makeWorldFromToml(kDiskBed);
    for (int k = 0; k < 300; ++k) w.step();  // a compacting bed: springs stretched, walls loaded
    expectTilingsAgree(w, 200);
}

TEST(DemThreads, ManyTilesChangePolygonForcesOnlyByRoundOff) {
    dem::World w = test::makeWorldFromToml(pileWithBed());
    for (int k = 0; k < 600; ++k) w.step();
    expectTilingsAgree(w, 40);
}

TEST(DemThreads, TilesDependOnTheParticleCountOnly) {
    EXPECT_EQ(dem::SlotTiles::forParticles(0).count, 0u);
    EXPECT_EQ(dem::SlotTiles::forParticles(100).count, 1u);
    const auto t = dem::SlotTiles::forParticles(10000);
    EXPECT_EQ(t.slotsPerTile, dem::SlotTiles::kMinSlots);
    EXPECT_EQ(t.count, (10000 + 127) / 128);
    EXPECT_EQ(t.end(t.count - 1), 10000u);
    const auto big = dem::SlotTiles::forParticles(1000000);
    EXPECT_LE(big.count, dem::SlotTiles::kMaxTiles);
    EXPECT_EQ(big.end(big.count - 1), 1000000u);
    EXPECT_EQ(big.tileOf(999999), big.count - 1);
}

TEST(DemThreads, SceneAndCommandLineSetTheThreadCount) {
    dem::World w = test::makeWorldFromToml(kDiskBed, {io::parseOverride("run.threads=3")});
    EXPECT_EQ(w.threads(), 3);
    dem::World all =
        test::makeWorldFromToml(kDiskBed);  // 0: automatic, at most every core this process may use
    EXPECT_EQ(all.threads(), availableCores());
    EXPECT_ANY_THROW(test::makeWorldFromToml(kDiskBed, {io::parseOverride("run.threads=-1")}));
}

TEST(DemThreads, ContactForcesCancelInPairsWhileGrainsEnter) {
    // Newton's third law through the tiles: after grains entered (lists regrouped, cross pairs
    // re-indexed), the forces on all grains add up to their weight minus what the walls carry.
    dem::World w = test::makeWorldFromToml(pileWithBed(), {io::parseOverride("source[0].interval=5e-4")});
    for (int k = 0; k < 3000; ++k) ASSERT_EQ(w.step(), dem::kStepOk);
    const auto& s = w.store();
    ASSERT_GT(s.size(), 400u);
    Vec2 sum, weight;
    Real scale = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        sum += Vec2{s.fx[i], s.fy[i]};
        weight += w.gravity() * s.mass[i];
        scale = std::max(scale, std::hypot(s.fx[i], s.fy[i]));
    }
    for (const Vec2 f : w.wallForce()) sum += f;  // the walls' share back
    EXPECT_GT(w.forceStats().contacts, 10u);
    EXPECT_NEAR(sum.x, weight.x, 1e-9 * scale * static_cast<Real>(s.size()));
    EXPECT_NEAR(sum.y, weight.y, 1e-9 * scale * static_cast<Real>(s.size()));
}

TEST(DemThreads, ASmallSceneRunsOnOneThreadByDefault) {
    // run.threads = 0: the automatic count; ~400 disks are too few to share (World::team).
    dem::World w =
        test::makeWorldFromToml(kDiskBed, {io::parseOverride("block[0].region=[0.1, 0.1, 20.0, 20.0]")});
    ASSERT_TRUE(w.threadGovernor().automatic());
    ASSERT_LT(w.store().size(), 2 * dem::World::kParticlesPerThread);
    for (int k = 0; k < 300; ++k) ASSERT_EQ(w.step(), dem::kStepOk);
    EXPECT_EQ(w.team(), 1);
    EXPECT_EQ(w.threadGovernor().trials(), 0u);
    EXPECT_NE(w.threadGovernor().reason().find("1 thread: "), std::string::npos);
    EXPECT_NE(w.threadGovernor().reason().find("too few for 2 threads"), std::string::npos)
        << w.threadGovernor().reason();
}

TEST(DemThreads, ChangingTheThreadCountDuringARunChangesNoBit) {
    // What the automatic count does when it tries another team: 1, 2, 3, 4, 1, ... threads from one
    // step to the next give the state of one thread throughout, bit for bit.
    const Snapshot one = runOn(kDiskBed, 1, 300);
    dem::World w = test::makeWorldFromToml(kDiskBed, {io::parseOverride("run.threads=1")});
    w.setParticlesPerThread(16);
    for (int k = 0; k < 300; ++k) {
        w.setThreads(1 + k % 4);
        ASSERT_EQ(w.team(), 1 + k % 4);
        ASSERT_EQ(w.step(), dem::kStepOk);
    }
    EXPECT_TRUE(snapshotOf(w) == one);
    w.setThreads(0);  // back to the automatic count
    EXPECT_TRUE(w.threadGovernor().automatic());
}
