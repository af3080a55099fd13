// SPDX-License-Identifier: MIT
// Event-queue micro-benchmark (edmd spec section 2.3), the classic "hold" model: pop the
// earliest event, reschedule that particle at now + an exponential delay (mean 1), and
// reschedule one random other particle (a collision partner) the same way; N = 1e3 ... 1e6.
//   ninja -C build granulab_bench && build/bench/granulab_bench --benchmark_filter=Queue
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/rng.hpp"
#include "edmd/event_queue.hpp"

using namespace granulab;

template <class Queue>
static void BM_QueueHold(benchmark::State& state) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    Queue q;
    q.reset(n);
    CounterRng rng(5, 0);
    for (std::uint32_t i = 0; i < n; ++i) q.set(i, -std::log(1 - rng.uniform()));
    for (auto _ : state) {
        const std::uint32_t i = q.top();
        const Real now = q.topTime();
        q.set(i, now - std::log(1 - rng.uniform()));
        const auto j = static_cast<std::uint32_t>(rng.uniform() * n);
        q.set(j, now - std::log(1 - rng.uniform()));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_QueueHold, edmd::AddressableHeap)->RangeMultiplier(10)->Range(1000, 1000000);
BENCHMARK_TEMPLATE(BM_QueueHold, edmd::TournamentTree)->RangeMultiplier(10)->Range(1000, 1000000);
BENCHMARK_TEMPLATE(BM_QueueHold, edmd::CalendarQueue)->RangeMultiplier(10)->Range(1000, 1000000);
