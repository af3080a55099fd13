// SPDX-License-Identifier: MIT
// The parallel event-driven engine against the serial one (edmd spec 5.7 AT-4; issue 15), run
// under mpirun with 2 and 3 ranks (granulab_mpi_tests): the same collisions in the same order
// (per-particle collision counts equal, the global count equal) and the state equal bit for
// bit, also at collision-count stops; forced causality errors and rollbacks leave the result unchanged; a
// state gathered on P ranks resumes on P ranks and on the serial engine event for event; inelastic cooling
// loses and duplicates no particle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "../edmd/gas_fixture.hpp"
#include "core/communicator.hpp"
#include "edmd/parallel/parallel_engine.hpp"

namespace granulab::edmd {
namespace {

template <int D>
struct Scene {
    EngineConfig config;
    GasState<D> gas;
};

/// n^D particles on a lattice in a periodic box at volume fraction nu (radius 1, mass 1).
template <int D>
Scene<D> scene(int n, Real nu, std::uint64_t seed, bool powerOfTwo = true) {
    const Real count = std::pow(n, D);
    const Real L = boxLengthFor(D, count, nu, 1.0);
    Scene<D> s;
    s.config.box = {L, L, L};
    s.config.powerOfTwoCells = powerOfTwo;
    s.gas = validation::latticeGas<D>(n, L, 1.0, seed);
    return s;
}

/// Largest difference of positions (minimum image) and velocities between the serial engine
/// and the gathered parallel records; -1 if the ids or collision counts differ.
template <int D>
std::pair<Real, Real> compare(const Engine<D>& serial, const std::vector<ParticleRecord>& records) {
    if (records.size() != serial.size()) return {-1, -1};
    Real dx = 0, dv = 0;
    for (std::uint32_t i = 0; i < serial.size(); ++i) {
        const auto& r = records[i];
        if (r.id != i || r.counter != serial.collisions(i)) return {-1, -1};
        const auto x = serial.positionNow(i), v = serial.velocityNow(i);
        for (int d = 0; d < D; ++d) {
            Real e = std::abs(r.x[d] - x[d]);
            e = std::min(e, serial.config().box[d] - e);
            dx = std::max(dx, e);
            dv = std::max(dv, std::abs(r.v[d] - v[d]));
        }
    }
    return {dx, dv};
}

template <int D>
void expectSameAsSerial(int n, Real nu, Real tEnd, int stops, std::uint64_t forcedErrors, bool balance,
                        bool powerOfTwo = true) {
    Communicator& comm = worldCommunicator();
    auto s = scene<D>(n, nu, 7, powerOfTwo);
    Engine<D> serial(s.config, s.gas.x, s.gas.v, s.gas.radius, s.gas.mass);
    ParallelConfig pc;
    pc.forcedErrorEvery = forcedErrors;
    pc.loadBalancing = balance;
    ParallelEngine<D> parallel(comm, s.config, pc, s.gas.x, s.gas.v, s.gas.radius, s.gas.mass);
    EXPECT_EQ(parallel.cellsPerAxis(), serial.cellsPerAxis());
    if (!powerOfTwo) {  // the case under test: a grid the Morton numbering pads
        const int cells = serial.cellsPerAxis()[0];
        EXPECT_NE(cells & (cells - 1), 0) << cells << " cells per axis";
    }
    for (int k = 1; k <= stops; ++k) {
        const Real t = tEnd * k / stops;
        serial.runUntil(t);
        parallel.runUntil(t);
        const auto records = parallel.gatherNow();
        const EngineGlobals g = parallel.globals();
        if (comm.root()) {
            EXPECT_EQ(g.stats.collisions, serial.stats().collisions) << "stop " << k;
            const auto [dx, dv] = compare(serial, records);
            EXPECT_GE(dx, 0) << "ids or per-particle collision counts differ at stop " << k;
            // Bit for bit: the same events in the same order on the same grid.
            EXPECT_EQ(dx, 0) << "stop " << k;
            EXPECT_EQ(dv, 0) << "stop " << k;
            if (std::getenv("GRANULAB_TEST_VERBOSE"))
                for (std::uint32_t i = 0; i < serial.size(); ++i) {
                    const auto x = serial.positionNow(i);
                    for (int d = 0; d < D; ++d)
                        if (x[d] != records[i].x[d]) {
                            std::fprintf(stderr, "id %u differs (axis %d) tst %.17g\n", i, d, records[i].tst);
                            break;
                        }
                }
            if (std::getenv("GRANULAB_TEST_VERBOSE"))
                std::fprintf(stderr, "stop %d: collisions %llu dx %g dv %g\n", k,
                             static_cast<unsigned long long>(g.stats.collisions), dx, dv);
        }
    }
    if (std::getenv("GRANULAB_TEST_VERBOSE"))
        std::fprintf(
            stderr,
            "rank %d: steps %llu records %llu rollbacks %llu sections %llu careful %llu owned %u nb %d\n",
            comm.rank(), static_cast<unsigned long long>(parallel.parallelStats().steps),
            static_cast<unsigned long long>(parallel.parallelStats().recordsSent),
            static_cast<unsigned long long>(parallel.parallelStats().rollbacks),
            static_cast<unsigned long long>(parallel.parallelStats().sections),
            static_cast<unsigned long long>(parallel.parallelStats().carefulSections), parallel.ownedCount(),
            parallel.neighbourCount());
    std::array<std::uint64_t, 1> rollbacks{parallel.parallelStats().rollbacks};
    comm.allSum(rollbacks);
    if (forcedErrors > 0) {
        EXPECT_GT(rollbacks[0], 0u) << "the forced errors made no rollback";
    }
}

TEST(ParallelEdmd, ElasticDisksMatchSerial) {
    expectSameAsSerial<2>(40, 0.3, 4.0, 4, 0, false);
}

TEST(ParallelEdmd, ElasticSpheresMatchSerial) {
    expectSameAsSerial<3>(12, 0.2, 3.0, 3, 0, false);
}

// The serial default grid (not a power of two per axis here): the Morton numbering spreads the
// padding; the events are the same, with forced rollbacks and balancing too.
TEST(ParallelEdmd, FreeGridMatchesSerial) {
    expectSameAsSerial<2>(40, 0.3, 4.0, 4, 0, true, false);
    expectSameAsSerial<3>(12, 0.15, 3.0, 3, 3, true, false);
}

TEST(ParallelEdmd, ForcedRollbacksLeaveTheResultUnchanged) {
    expectSameAsSerial<2>(40, 0.3, 4.0, 4, 2, false);
}

// Collision-count stops (the edmd pre-run and collision-count scenes): the parallel engine
// stops exactly after the serial engine's k-th collision, also with forced rollbacks, and goes
// on from there event for event.
TEST(ParallelEdmd, CollisionCountStopsMatchSerial) {
    Communicator& comm = worldCommunicator();
    auto s = scene<2>(40, 0.3, 5);
    Engine<2> serial(s.config, s.gas.x, s.gas.v, s.gas.radius, s.gas.mass);
    ParallelConfig pc;
    pc.forcedErrorEvery = 3;
    ParallelEngine<2> parallel(comm, s.config, pc, s.gas.x, s.gas.v, s.gas.radius, s.gas.mass);
    for (const std::uint64_t more : {1u, 777u, 1600u, 5u, 3000u}) {
        serial.runCollisions(more);
        parallel.runCollisions(more);
        const EngineGlobals g = parallel.globals();
        const auto records = parallel.gatherNow();
        EXPECT_EQ(parallel.time(), serial.time()) << "after " << more;
        if (std::getenv("GRANULAB_TEST_VERBOSE"))
            std::fprintf(stderr, "rank %d after %llu: rollbacks %llu careful %llu sections %llu\n",
                         comm.rank(), static_cast<unsigned long long>(more),
                         static_cast<unsigned long long>(parallel.parallelStats().rollbacks),
                         static_cast<unsigned long long>(parallel.parallelStats().carefulSections),
                         static_cast<unsigned long long>(parallel.parallelStats().sections));
        if (comm.root()) {
            EXPECT_EQ(g.stats.collisions, serial.stats().collisions);
            const auto [dx, dv] = compare(serial, records);
            EXPECT_EQ(dx, 0) << "after " << more;
            EXPECT_EQ(dv, 0) << "after " << more;
        }
    }
    // A time stop after count stops lands on the same state too.
    serial.runUntil(serial.time() + 0.5);
    parallel.runUntil(parallel.time() + 0.5);
    const auto records = parallel.gatherNow();
    if (comm.root()) {
        const auto [dx, dv] = compare(serial, records);
        EXPECT_EQ(dx, 0);
        EXPECT_EQ(dv, 0);
    }
}

TEST(ParallelEdmd, ResumeOnAnotherRankCountAndOnTheSerialEngine) {
    Communicator& comm = worldCommunicator();
    auto s = scene<2>(32, 0.3, 11);
    ParallelConfig pc;
    ParallelEngine<2> first(comm, s.config, pc, s.gas.x, s.gas.v, s.gas.radius, s.gas.mass);
    first.runUntil(2.0);
    std::vector<ParticleRecord> state;
    const EngineGlobals g = first.gatherState(state);
    // Every rank gets the records (as a resumed run reads its checkpoint).
    const ByteBuffer bytes = comm.broadcast(packPod(std::span<const ParticleRecord>(state)));
    state.clear();
    unpackPod(bytes, state);
    first.runUntil(4.0);
    const auto uninterrupted = first.gatherNow();
    ParallelEngine<2> resumed(comm, s.config, pc, g, state);
    resumed.runUntil(4.0);
    const auto again = resumed.gatherNow();
    EngineConfig serialConfig = s.config;
    Engine<2> serial(serialConfig, DomainLayout::serial(first.cellsPerAxis()), g, state);
    serial.runUntil(4.0);
    if (comm.root()) {
        ASSERT_EQ(again.size(), uninterrupted.size());
        for (std::size_t i = 0; i < again.size(); ++i) {
            EXPECT_EQ(again[i].counter, uninterrupted[i].counter);
            EXPECT_EQ(again[i].x[0], uninterrupted[i].x[0]);
            EXPECT_EQ(again[i].v[1], uninterrupted[i].v[1]);
        }
        const auto [dx, dv] = compare(serial, uninterrupted);
        EXPECT_GE(dx, 0);
        EXPECT_LE(dx, 1e-9 * s.config.box[0]);
        EXPECT_LE(dv, 1e-9);
    }
}

TEST(ParallelEdmd, CoolingGasKeepsEveryParticle) {
    Communicator& comm = worldCommunicator();
    auto s = scene<2>(48, 0.25, 5);
    s.config.restitution = Restitution{};
    s.config.restitution.eps = 0.7;
    s.config.tc = 1e-5;
    ParallelConfig pc;
    ParallelEngine<2> parallel(comm, s.config, pc, s.gas.x, s.gas.v, s.gas.radius, s.gas.mass);
    for (int k = 1; k <= 5; ++k) {
        parallel.runUntil(2.0 * k);
        const auto records = parallel.gatherNow();
        if (comm.root()) {
            ASSERT_EQ(records.size(), s.gas.x.size());
            for (std::size_t i = 0; i < records.size(); ++i) ASSERT_EQ(records[i].id, i);
        }
    }
}

}  // namespace
}  // namespace granulab::edmd
