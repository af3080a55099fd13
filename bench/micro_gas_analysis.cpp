// SPDX-License-Identifier: MIT
// Gas-analysis micro-benchmark (edmd spec section 5.2): cluster search of N random spheres
// (radius 1 m, overlaps allowed) at nu = 0.25 in a periodic cube, and the density histogram.
//   ninja -C build granulab_bench && build/bench/granulab_bench --benchmark_filter=Gas
#include <benchmark/benchmark.h>

#include <cmath>

#include "analysis/gas_clusters.hpp"
#include "analysis/gas_structure.hpp"
#include "core/rng.hpp"

using namespace granulab;

static analysis::PointSet randomSpheres(std::size_t n, Real volumeFraction) {
    analysis::PointSet p;
    p.dim = 3;
    const Real edge = std::cbrt(static_cast<Real>(n) * (4.0 / 3.0) * kPi / volumeFraction);  // [m]
    p.box = {edge, edge, edge};
    CounterRng rng(41, 0);
    p.x.resize(3 * n);
    for (Real& x : p.x) x = rng.uniform(0, edge);
    p.radius.assign(n, 1.0);
    return p;
}

static void BM_GasFindClusters(benchmark::State& state) {
    const analysis::PointSet p = randomSpheres(static_cast<std::size_t>(state.range(0)), 0.25);
    std::size_t clusters = 0;
    for (auto _ : state) {
        const analysis::ClusterResult r = analysis::findClusters(p);
        clusters = r.sizes.size();
        benchmark::DoNotOptimize(r.label.data());
    }
    state.counters["clusters"] = static_cast<double>(clusters);
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_GasFindClusters)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

static void BM_GasDensityDistribution(benchmark::State& state) {
    const analysis::PointSet p = randomSpheres(static_cast<std::size_t>(state.range(0)), 0.25);
    for (auto _ : state) {
        const analysis::DensityDistribution d = analysis::densityDistribution(p);
        benchmark::DoNotOptimize(d.quantiles.data());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_GasDensityDistribution)->Arg(1000000)->Unit(benchmark::kMillisecond);
