// SPDX-License-Identifier: MIT
// DEM analysis micro-benchmark (gc2d spec section 7; issue target: the analysis of a 1e5-grain
// snapshot, stress grid, density and coordination, in under 2 s): 1e5 disks on a jittered
// hexagonal lattice with 3 lattice contacts each (3e5 contacts) and a floor, test areas of ~150
// grains at half-size steps.
//   ninja -C build granulab_bench && build/bench/granulab_bench --benchmark_filter=DemAnalysis
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "../tests/analysis/dem_lattice.hpp"
#include "analysis/dem_coordination.hpp"
#include "analysis/dem_force_stats.hpp"
#include "analysis/dem_packing.hpp"
#include "analysis/dem_pressure.hpp"
#include "analysis/dem_stress.hpp"
#include "analysis/dem_surface.hpp"

using namespace granulab;

namespace {

constexpr Real kR = 1e-3;  // [m]
constexpr std::size_t kNx = 316, kNy = 317;

struct Snapshot {
    analysis::GrainFrame grains;
    analysis::ContactFrame contacts;
    analysis::WallSegments walls;
    analysis::TestAreaGrid grid;
};

const Snapshot& snapshot() {
    static const Snapshot s = [] {
        Snapshot out;
        out.grains = test::hexLattice(kNx, kNy, kR, 0, kR);
        std::mt19937 rng(9);
        std::normal_distribution<Real> jitter(0, 0.01 * kR), force(1, 0.3);
        auto& f = out.grains;
        for (std::size_t i = 0; i < f.size(); ++i) {
            f.x[i] += jitter(rng);
            f.y[i] += jitter(rng);
        }
        const auto link = [&](std::size_t a, std::size_t b) {
            const Vec2 pa{f.x[a], f.y[a]}, pb{f.x[b], f.y[b]}, n = (pb - pa) / norm(pb - pa);
            test::addContact(out.contacts, static_cast<std::int64_t>(a), static_cast<std::int64_t>(b), -1,
                             0.5 * (pa + pb), n, -force(rng) * n);
        };
        for (std::size_t j = 0; j + 1 < kNy; ++j)
            for (std::size_t i = 0; i + 1 < kNx; ++i) {
                const std::size_t k = j * kNx + i;
                link(k, k + 1);
                link(k, k + kNx);
                link(k + 1, k + kNx);
            }
        for (std::size_t i = 0; i < kNx; ++i)  // the bottom row on the floor
            test::addContact(out.contacts, static_cast<std::int64_t>(i), -1, 0, {f.x[i], 0}, {0, -1},
                             {0, force(rng)});
        test::addSegment(out.walls, 0, {-kR, 0}, {2 * kR * (kNx + 1), 0});
        out.grid = analysis::coveringGrid(0, 0, 2 * kR * kNx, std::sqrt(3.0) * kR * kNy + kR, 24 * kR,
                                          22 * kR, 12 * kR, 11 * kR);
        return out;
    }();
    return s;
}

void BM_DemAnalysisStressGrid(benchmark::State& state) {
    const Snapshot& s = snapshot();
    for (auto _ : state)
        benchmark::DoNotOptimize(analysis::stressGrid(s.grains, s.contacts, s.grid).sigmaZz.data());
    state.counters["areas"] = static_cast<double>(s.grid.count());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(s.grains.size()));
}
BENCHMARK(BM_DemAnalysisStressGrid)->Unit(benchmark::kMillisecond);

void BM_DemAnalysisPackingGrid(benchmark::State& state) {
    const Snapshot& s = snapshot();
    for (auto _ : state) benchmark::DoNotOptimize(analysis::packingGrid(s.grains, s.grid).improved.data());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(s.grains.size()));
}
BENCHMARK(BM_DemAnalysisPackingGrid)->Unit(benchmark::kMillisecond);

void BM_DemAnalysisCoordination(benchmark::State& state) {
    const Snapshot& s = snapshot();
    for (auto _ : state) benchmark::DoNotOptimize(analysis::coordination(s.grains, s.contacts).meanK);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(s.grains.size()));
}
BENCHMARK(BM_DemAnalysisCoordination)->Unit(benchmark::kMillisecond);

/// The default set of `granulab analyze` minus file I/O: pressure, forces, coordination, repose,
/// packing, stress.
void BM_DemAnalysisDefaultSet(benchmark::State& state) {
    const Snapshot& s = snapshot();
    for (auto _ : state) {
        analysis::PressureProfileParams pp;
        pp.walls = {0};
        pp.halfWidth = 10 * kR;
        pp.step = 5 * kR;
        benchmark::DoNotOptimize(analysis::wallPressure(s.contacts, s.walls, {{0}, {}}).pressure);
        benchmark::DoNotOptimize(analysis::pressureProfile(s.contacts, s.walls, pp).p.data());
        benchmark::DoNotOptimize(analysis::forceDirections(s.contacts).density.data());
        benchmark::DoNotOptimize(analysis::forceMagnitudes(s.contacts).meanForce);
        benchmark::DoNotOptimize(analysis::coordination(s.grains, s.contacts).meanK);
        benchmark::DoNotOptimize(
            analysis::angleOfRepose(
                analysis::surfaceProfile(s.grains, {2 * kR, {}, {}, analysis::SurfaceHeight::Centroid}))
                .meanAngleDeg);
        benchmark::DoNotOptimize(analysis::packingGrid(s.grains, s.grid).improved.data());
        benchmark::DoNotOptimize(analysis::stressGrid(s.grains, s.contacts, s.grid).sigmaZz.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(s.grains.size()));
}
BENCHMARK(BM_DemAnalysisDefaultSet)->Unit(benchmark::kMillisecond);

}  // namespace
