// SPDX-License-Identifier: MIT
// Google Benchmark micro-benchmarks of the DEM engine (see bench/README.md):
//   BM_NeighborRebuild/<broad phase>/N  one full neighbour-list rebuild (broad phase + history
//                                        sync) on a random polydisperse set of N disks;
//   BM_FindPairs/<broad phase>/N         the broad phase alone on the same set;
//   BM_WorldStep/N                       one World::step on a settled-ish bed of N disks.
// items/s is particles per second of one rebuild, or particle-steps/s for the step.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/dem/dem_engine.hpp"
#include "app/engine_table.hpp"
#include "dem/broad_phase.hpp"
#include "dem/neighbor_list.hpp"
#include "dem/setup.hpp"
#include "dem/world.hpp"
#include "io/scene_reader.hpp"

namespace {

using namespace granulab;

/// Contact law, materials and a box shared by both workloads (the disk_bed.toml parameters).
constexpr const char* kCommon = R"(
[[material]]
name = "grain"
density = 1.0

[[contact]]
materials = ["*", "*"]
normal = "hooke"
kn = 2.0e5
damping = "lammps"
gamma_n = 50.0
tangential = "cundall_strack"
mu = 0.5
)";

/// Builds an initialized world from scene text (reader -> validate -> makeWorld).
std::unique_ptr<dem::World> worldFromText(const std::string& text) {
    const model::SceneDef scene = app::readSceneText(text, "<micro_dem>");
    const dem::PreparedScene valid = app::checkAndPrepareDem(scene);
    auto world = std::make_unique<dem::World>(dem::makeWorld(scene, valid.initial));
    world->initialize();
    return world;
}

/// N disks, radii uniform in [0.3, 0.7] (polydisperse, ratio 2.3), random sequential addition
/// in a square at packing fraction ~0.4, inside a box wall. Built once per N.
const dem::World& randomSet(std::int64_t n) {
    static std::map<std::int64_t, std::unique_ptr<dem::World>> cache;
    auto& w = cache[n];
    if (!w) {
        const double rmin = 0.3, rmax = 0.7, phi = 0.4;
        const double meanArea =
            std::numbers::pi * (rmax * rmax * rmax - rmin * rmin * rmin) / (3 * (rmax - rmin));
        const double side = std::sqrt(static_cast<double>(n) * meanArea / phi);
        w = worldFromText(fmt::format(R"(
[run]
seed = 7
end_time = 1.0
[dem]
dt = 1.0e-4
skin = 0.1
{}
[[block]]
lattice = "random"
count = {}
region = [0.0, 0.0, {:.6f}, {:.6f}]
radius = {{ distribution = "uniform", min = 0.3, max = 0.7 }}
material = "grain"
[[wall]]
name = "box"
points = [[0.0, 0.0], [{:.6f}, 0.0], [{:.6f}, {:.6f}], [0.0, {:.6f}]]
closed = true
material = "grain"
)",
                                      kCommon, n, side, side, side, side, side, side));
    }
    return *w;
}

void BM_NeighborRebuild(benchmark::State& state, const std::string& broadName) {
    const std::int64_t n = state.range(0);
    const dem::World& world = randomSet(n);
    auto broad = dem::makeBroadPhase(broadName);
    dem::NeighborList list;
    const std::vector<std::uint32_t> noPermutation;
    for (auto _ : state) {
        list.rebuild(world.store(), world.walls(), world.config().skin, 0.0, *broad, world.laws(),
                     noPermutation, false);
        benchmark::DoNotOptimize(list.pairs.first.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * n);
    state.counters["pairs/particle"] = static_cast<double>(list.pairs.size()) / static_cast<double>(n);
}
BENCHMARK_CAPTURE(BM_NeighborRebuild, cell_grid, std::string("cell_grid"))
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NeighborRebuild, brute_force, std::string("brute_force"))
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond);

/// The broad phase alone (BroadPhase::findPairs), to separate it from the history sync.
void BM_FindPairs(benchmark::State& state, const std::string& broadName) {
    const std::int64_t n = state.range(0);
    const dem::World& world = randomSet(n);
    auto broad = dem::makeBroadPhase(broadName);
    std::vector<std::uint64_t> pairs;
    for (auto _ : state) {
        broad->findPairs(world.store(), world.config().skin, pairs);
        benchmark::DoNotOptimize(pairs.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * n);
    state.counters["pairs/particle"] = static_cast<double>(pairs.size()) / static_cast<double>(n);
}
BENCHMARK_CAPTURE(BM_FindPairs, cell_grid, std::string("cell_grid"))
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FindPairs, brute_force, std::string("brute_force"))
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond);

/// A settled-ish bed: NX x NX disks on a hexagonal lattice of spacing 1.0 with radii uniform in
/// [0.48, 0.5] (gaps <= 0.04, so the neighbour lists are bed-like from the start) in a box under
/// gravity, with viscous damping for the first 0.2 s; the fixture pre-runs 2000 steps once.
dem::World& bed(std::int64_t nx) {
    static std::map<std::int64_t, std::unique_ptr<dem::World>> cache;
    auto& w = cache[nx];
    if (!w) {
        const double a = 1.0, xmax = static_cast<double>(nx) * a + 0.25;
        const double ymax = static_cast<double>(nx) * a * std::sqrt(3.0) / 2;
        const double width = static_cast<double>(nx) * a + 0.5;
        w = worldFromText(fmt::format(R"(
[run]
seed = 12345
end_time = 1000.0
[dem]
dt = 1.0e-4
gravity = [0.0, -10.0]
skin = 0.1
[[dem.damping]]
gamma = 2.0
from = 0.0
to = 0.2
{}
[[block]]
lattice = "hexagonal"
spacing = {}
origin = [0.5, 0.5]
region = [0.1, 0.0, {:.6f}, {:.6f}]
radius = {{ distribution = "uniform", min = 0.48, max = 0.5 }}
material = "grain"
temperature = 0.01
[[wall]]
name = "box"
points = [[0.0, {:.6f}], [0.0, 0.0], [{:.6f}, 0.0], [{:.6f}, {:.6f}]]
material = "grain"
)",
                                      kCommon, a, xmax, ymax, 4 * ymax, width, width, 4 * ymax));
        for (int k = 0; k < 2000; ++k)
            if (w->step() != dem::kStepOk) throw std::runtime_error("micro_dem: bed fixture became unstable");
    }
    return *w;
}

void BM_WorldStep(benchmark::State& state) {
    const std::int64_t nx = state.range(0);
    dem::World& world = bed(nx);
    const auto n = static_cast<std::int64_t>(world.store().size());
    for (auto _ : state) {
        const std::uint32_t status = world.step();
        if (status != dem::kStepOk) {
            state.SkipWithError("World::step reported an unstable state");
            break;
        }
    }
    state.SetItemsProcessed(state.iterations() * n);  // particle-steps
    state.counters["particles"] = static_cast<double>(n);
    state.counters["contacts/particle"] =
        static_cast<double>(world.forceStats().contacts) / static_cast<double>(n);
    state.counters["pairs/particle"] =
        static_cast<double>(world.neighbors().pairs.size()) / static_cast<double>(n);
}
BENCHMARK(BM_WorldStep)->Arg(100)->ArgName("nx")->Unit(benchmark::kMicrosecond);  // 100 x 100 = 1e4 disks

}  // namespace
