// SPDX-License-Identifier: MIT
// Serial event-driven engine benchmark (edmd spec sections 2 and 8, issue 5 targets): elastic
// hard spheres (3D) or disks (2D) in a periodic unit box, started on a lattice with Gaussian
// velocities and equilibrated (melted) before the timed part. Counters: collisions/s and
// events/s (rates over the timed part), bytes per particle (Engine::memoryBytes() / N) and the
// process' peak resident set [MiB] (a check; it is the maximum over the whole process, so run
// one big-N case alone to read it).
//   ninja -C build granulab_bench
//   build/bench/granulab_bench --benchmark_filter=Edmd              # fast set (N = 32768, ~1 min)
//   GRANULAB_BENCH_LARGE=1 build/bench/granulab_bench --benchmark_filter='BM_EdmdScaling/3/1000000'
//   GRANULAB_BENCH_LARGE=1 build/bench/granulab_bench --benchmark_filter=BM_EdmdScaling   # N = 1e4 ... 1e7
//                                                   (minutes, about 2 GB at 1e7)
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "edmd/engine.hpp"

using namespace granulab;
using namespace granulab::edmd;

namespace {

/// About `target` particles (n^D with n = round(target^(1/D))) on a simple cubic/square lattice
/// in the unit box at volume fraction `fraction`; unit masses, Gaussian velocities with zero
/// total momentum.
template <int D, class Queue>
Engine<D, Queue> latticeGas(std::int64_t target, Real fraction, std::uint64_t seed) {
    const int n = static_cast<int>(std::lround(std::pow(static_cast<Real>(target), 1.0 / D)));
    std::size_t count = 1;
    for (int d = 0; d < D; ++d) count *= static_cast<std::size_t>(n);
    const Real unitVolume = D == 2 ? kPi : 4.0 / 3.0 * kPi;
    const Real a = std::pow(fraction / (static_cast<Real>(count) * unitVolume), 1.0 / D);
    std::vector<VecD<D>> x(count), v(count);
    CounterRng rng(seed, 0);
    VecD<D> mean;
    for (std::size_t k = 0; k < count; ++k) {
        std::size_t rest = k;
        for (int d = 0; d < D; ++d) {
            x[k][d] = (static_cast<Real>(rest % static_cast<std::size_t>(n)) + 0.5) / n;
            rest /= static_cast<std::size_t>(n);
            v[k][d] = rng.normal();
        }
        mean = mean + v[k];
    }
    for (auto& u : v) u = u - mean * (1.0 / static_cast<Real>(count));
    EngineConfig c;
    return Engine<D, Queue>(c, std::move(x), std::move(v), std::vector<Real>(count, a),
                            std::vector<Real>(count, 1.0));
}

double peakRssMiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;  // ru_maxrss in KiB on Linux
}

template <int D, class Queue>
void report(benchmark::State& state, const Engine<D, Queue>& e, std::uint64_t collisions,
            std::uint64_t events) {
    state.counters["collisions/s"] =
        benchmark::Counter(static_cast<double>(collisions), benchmark::Counter::kIsRate);
    state.counters["events/s"] = benchmark::Counter(static_cast<double>(events), benchmark::Counter::kIsRate);
    state.counters["bytes/particle"] = static_cast<double>(e.memoryBytes()) / e.size();
    state.counters["N"] = e.size();
    state.counters["events/collision"] =
        collisions ? static_cast<double>(events) / static_cast<double>(collisions) : 0;
    state.counters["peak_rss_MiB"] = peakRssMiB();
    const auto& st = e.stats();  // over the whole run, equilibration included
    state.counters["crossings/collision"] =
        static_cast<double>(st.cellCrossings) / static_cast<double>(st.collisions);
    state.counters["annulled/collision"] =
        static_cast<double>(st.annulled) / static_cast<double>(st.collisions);
}

}  // namespace

/// Target 1 of issue 5: 3D elastic spheres, N = 32768, fraction = arg(0)/100, equilibrated for
/// 20 collisions per particle, then 3 x 1e6 collisions timed.
template <class Queue>
static void BM_EdmdDense(benchmark::State& state) {
    auto e = latticeGas<3, Queue>(state.range(1), static_cast<Real>(state.range(0)) / 100, 7);
    e.runCollisions(20ull * e.size());
    const auto c0 = e.stats().collisions, e0 = e.stats().events;
    for (auto _ : state) e.runCollisions(1000000);
    report(state, e, e.stats().collisions - c0, e.stats().events - e0);
}
BENCHMARK_TEMPLATE(BM_EdmdDense, CalendarQueue)
    ->Args({45, 32768})
    ->Args({30, 32768})
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_EdmdDense, AddressableHeap)
    ->Args({45, 32768})
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_EdmdDense, TournamentTree)
    ->Args({45, 32768})
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);

/// Target 2 of issue 5: events/s versus N at fraction 0.25, D = arg(0), N = arg(1); melted for
/// 2 collisions per particle (at least 2e5), then 2 x 2e6 events timed.
template <int D>
static void BM_EdmdScalingD(benchmark::State& state) {
    auto e = latticeGas<D, CalendarQueue>(state.range(1), 0.25, 11);
    e.runCollisions(std::max<std::uint64_t>(200000, 2ull * e.size()));
    const auto c0 = e.stats().collisions, e0 = e.stats().events;
    for (auto _ : state) {
        const std::uint64_t target = e.stats().events + 2000000;
        // runUntil in small time steps would add output overhead; run by collisions instead,
        // in chunks, until 2e6 events are done.
        while (e.stats().events < target) e.runCollisions(100000);
    }
    report(state, e, e.stats().collisions - c0, e.stats().events - e0);
}
static void BM_EdmdScaling(benchmark::State& state) {
    if (state.range(0) == 2)
        BM_EdmdScalingD<2>(state);
    else
        BM_EdmdScalingD<3>(state);
}
BENCHMARK(BM_EdmdScaling)
    ->ArgsProduct({{3, 2}, {10000, 100000}})
    ->Iterations(2)
    ->Unit(benchmark::kMillisecond);
// N = 1e6 and 1e7 (about 2 GB and several minutes) only with GRANULAB_BENCH_LARGE=1 in the
// environment, so that --benchmark_filter=Edmd stays fast.
static const bool kLargeRegistered = [] {
    const char* large = std::getenv("GRANULAB_BENCH_LARGE");
    if (large && std::string(large) == "1")
        benchmark::RegisterBenchmark("BM_EdmdScaling", BM_EdmdScaling)
            ->ArgsProduct({{3, 2}, {1000000, 10000000}})
            ->Iterations(2)
            ->Unit(benchmark::kMillisecond);
    return true;
}();
