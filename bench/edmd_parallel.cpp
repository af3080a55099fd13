// SPDX-License-Identifier: MIT
// Strong and weak scaling of the parallel event-driven engine (edmd spec 3.10; issue 15): a gas
// of hard disks (2D) or spheres (3D) on a lattice with Gaussian velocities, elastic or cooling
// (--restitution, with the TC model), warmed up and then run for given multiples of the initial
// Enskog collision time; reports collisions per second of wall time, the rollbacks, steps,
// records sent, time shares, the event load of the busiest rank over the mean (imbalance) and
// memory per rank. With one rank and --serial it runs the serial engine on the same grid (the
// speed-up's reference): the serial default grid, or with --power-of-two the "morton" one. A clustering gas
// with and without --no-balance shows the balancing.
//   mpirun -np P build/bench/granulab_bench_edmd_parallel --dim 2 --particles 1000000 --fraction 0.3
// Output: one line of key=value pairs on rank 0 (bench/README.md "Parallel EDMD").
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/communicator.hpp"
#include "core/rng.hpp"
#include "core/timer.hpp"
#include "edmd/initial_state.hpp"
#include "edmd/kinetic_theory.hpp"
#include "edmd/parallel/parallel_engine.hpp"
#include "mpi/mpi_communicator.hpp"

using namespace granulab;
using namespace granulab::edmd;

namespace {

struct Options {
    int dim = 2;
    double particles = 1e6;
    double fraction = 0.3;
    double collisionsPerParticle = 5;  ///< timed Enskog times (collisions per particle if elastic)
    double warm = 1;                   ///< Enskog times of warm-up before the timing
    double restitution = 1;            ///< eps (< 1: a cooling, clustering gas; TC model on)
    bool serial = false;
    bool balance = true;
    bool fringe = true;
    bool powerOfTwo = false;
};

template <int D>
int run(const Options& o, Communicator& comm) {
    const auto side = static_cast<int>(std::llround(std::pow(o.particles, 1.0 / D)));
    std::uint64_t count = 1;
    for (int d = 0; d < D; ++d) count *= static_cast<std::uint64_t>(side);
    const Real L = unitLatticeEdge(D, count, o.fraction);
    auto s = unitLatticeGas<D>(count, o.fraction, 1);
    EngineConfig c;
    c.box = {L, L, L};
    c.powerOfTwoCells = o.powerOfTwo;  // default: the serial engine's default (free) grid
    // Time per collision per particle from the Enskog collision frequency (edmd spec 4.4).
    const Real perCollision = enskogCollisionTime(D, o.fraction, 1.0, 1.0, 1.0);
    const Real warm = o.warm * perCollision, timed = o.collisionsPerParticle * perCollision;
    if (o.restitution < 1) {
        c.restitution.eps = o.restitution;
        c.tc = 1e-4 * perCollision;  // TC model (edmd spec 4.3): no inelastic collapse
    }
    double imbalance = 1;
    std::array<int, 3> grid{1, 1, 1};
    double wall = 0;
    std::uint64_t collisions = 0;
    std::size_t memory = 0;
    ParallelStats ps;
    if (o.serial) {
        Engine<D> e(c, s.x, s.v, s.radius, s.mass);
        grid = e.cellsPerAxis();
        e.runUntil(warm);
        const std::uint64_t before = e.stats().collisions;
        const double t0 = wallSeconds();
        e.runUntil(warm + timed);
        wall = wallSeconds() - t0;
        collisions = e.stats().collisions - before;
        memory = e.memoryBytes();
    } else {
        ParallelConfig pc;
        pc.loadBalancing = o.balance;
        pc.fringeBorderEvents = o.fringe;
        ParallelEngine<D> e(comm, c, pc, s.x, s.v, s.radius, s.mass);
        grid = e.cellsPerAxis();
        e.runUntil(warm);
        const std::uint64_t before = e.globals().stats.collisions;
        const std::uint64_t eventsBefore = e.localStats().events;
        comm.barrier();
        const double t0 = wallSeconds();
        e.runUntil(warm + timed);
        comm.barrier();
        wall = wallSeconds() - t0;
        collisions = e.globals().stats.collisions - before;
        // Events per rank in the timed part (a rank rebuilt by balancing keeps counting).
        std::array<double, 1> mine{static_cast<double>(e.localStats().events - eventsBefore)};
        std::array<double, 1> busiest = mine, sum = mine;
        comm.allMax(busiest);
        comm.allSum(sum);
        imbalance = sum[0] > 0 ? busiest[0] * comm.size() / sum[0] : 1;
        ps = e.parallelStats();
        std::array<double, 1> most{static_cast<double>(e.memoryBytes())};
        comm.allMax(most);
        memory = static_cast<std::size_t>(most[0]);
        std::array<std::uint64_t, 4> sums{ps.rollbacks, ps.steps, ps.recordsSent, ps.sections};
        comm.allSum(sums);
        ps.rollbacks = sums[0] / comm.size();  // every rank counts every rollback and section
        ps.steps = sums[1] / comm.size();
        ps.recordsSent = sums[2];
        ps.sections = sums[3] / comm.size();
        std::array<double, 3> shares{ps.computeSeconds, ps.communicationSeconds, ps.rebuildSeconds};
        comm.allSum(shares);
        ps.computeSeconds = shares[0] / comm.size();
        ps.communicationSeconds = shares[1] / comm.size();
        ps.rebuildSeconds = shares[2] / comm.size();
    }
    if (comm.root())
        fmt::print(
            "dim={} ranks={} serial={} cells_per_axis={} particles={} fraction={} collisions={} "
            "wall_s={:.3f} "
            "collisions_per_s={:.4g} "
            "sections={} rollbacks={} steps={} records={} compute_s={:.3f} communication_s={:.3f} "
            "rebuild_s={:.3f} imbalance={:.3f} balance_moves={} "
            "max_memory_bytes_per_rank={} bytes_per_particle_per_rank={:.1f}\n",
            D, comm.size(), o.serial, grid[0], count, o.fraction, collisions, wall, collisions / wall,
            ps.sections, ps.rollbacks, ps.steps, ps.recordsSent, ps.computeSeconds, ps.communicationSeconds,
            ps.rebuildSeconds, imbalance, ps.balanceMoves, memory,
            static_cast<double>(memory) * comm.size() / static_cast<double>(count));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    mpi::MpiEnvironment environment(argc, argv);
    Options o;
    CLI::App cli{"granulab parallel EDMD scaling benchmark"};
    cli.add_option("--dim", o.dim)->check(CLI::IsMember({2, 3}));
    cli.add_option("--particles", o.particles, "about this many (a lattice of side round(N^(1/D)))");
    cli.add_option("--fraction", o.fraction, "area or volume fraction");
    cli.add_option("--collisions", o.collisionsPerParticle,
                   "timed Enskog times (collisions per particle when elastic)");
    cli.add_option("--warm", o.warm, "Enskog times of warm-up");
    cli.add_option("--restitution", o.restitution, "eps < 1: a cooling gas (TC model on)")
        ->check(CLI::Range(0.0, 1.0));
    cli.add_flag("--serial", o.serial, "the serial engine on the same grid (one rank)");
    cli.add_flag("!--no-balance", o.balance, "no load balancing");
    cli.add_flag("!--no-fringe", o.fringe, "collisions in fringe cells are not announced as border events");
    cli.add_flag("--power-of-two", o.powerOfTwo, "power-of-two cells per axis (edmd.cell_grid = \"morton\")");
    CLI11_PARSE(cli, argc, argv);
    Communicator& comm = worldCommunicator();
    return o.dim == 2 ? run<2>(o, comm) : run<3>(o, comm);
}
