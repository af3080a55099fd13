// SPDX-License-Identifier: MIT
// Event queues of the event-driven engine (edmd spec section 2.3): every queue agrees with a
// sorted reference on random event streams, including equal times (ties by particle index),
// +infinity and replacements by earlier and later times.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include "core/rng.hpp"
#include "edmd/event_queue.hpp"

using namespace granulab;

namespace {
/// The queue under test and its reference (a sorted set of (time, index)), kept in step.
using Reference = std::set<std::pair<Real, std::uint32_t>>;
template <class Queue>
void setBoth(Queue& q, Reference& ref, std::vector<Real>& time, std::uint32_t i, Real t) {
    ref.erase({time[i], i});
    time[i] = t;
    ref.insert({t, i});
    q.set(i, t);
}

template <class Queue>
void agreesWithSortedReference(std::uint32_t n, std::uint64_t seed, int operations) {
    Queue q;
    q.reset(n);
    const Real inf = std::numeric_limits<Real>::infinity();
    Reference ref;
    std::vector<Real> time(n, inf);
    for (std::uint32_t i = 0; i < n; ++i) ref.insert({inf, i});
    CounterRng rng(seed, 0);
    Real now = 0;
    for (int op = 0; op < operations; ++op) {
        // Like the engine: pop the earliest, give it (and maybe a partner) a later event; now and
        // then move an arbitrary particle earlier or to +infinity; times on a coarse grid so
        // that ties occur.
        std::uint32_t i;
        Real t;
        const Real u = rng.uniform();
        if (u < 0.6) {
            i = q.top();
            now = q.topTime() < inf ? q.topTime() : now;
            t = now + std::floor(rng.uniform() * 50) * 0.125;
        } else if (u < 0.95) {
            i = static_cast<std::uint32_t>(rng.uniform() * n);
            t = now + std::floor(rng.uniform() * 50) * 0.125;
        } else {
            i = static_cast<std::uint32_t>(rng.uniform() * n);
            t = inf;
        }
        setBoth(q, ref, time, i, t);
        ASSERT_EQ(q.top(), ref.begin()->second) << "operation " << op;
        ASSERT_EQ(q.topTime(), ref.begin()->first) << "operation " << op;
        ASSERT_EQ(q.time(i), t);
    }
}
}  // namespace

TEST(EventQueue, AddressableHeapAgreesWithSortedReference) {
    for (std::uint32_t n : {1u, 2u, 3u, 7u, 64u, 1000u})
        agreesWithSortedReference<edmd::AddressableHeap>(n, n, 20000);
}

TEST(EventQueue, TournamentTreeAgreesWithSortedReference) {
    for (std::uint32_t n : {1u, 2u, 3u, 7u, 64u, 1000u})
        agreesWithSortedReference<edmd::TournamentTree>(n, n, 20000);
}

TEST(EventQueue, TiesGoToTheSmallerIndex) {
    edmd::AddressableHeap h;
    edmd::TournamentTree t;
    edmd::CalendarQueue c;
    h.reset(5);
    t.reset(5);
    c.reset(5);
    for (std::uint32_t i : {4u, 2u, 3u}) {
        h.set(i, 1.0);
        t.set(i, 1.0);
        c.set(i, 1.0);
    }
    EXPECT_EQ(h.top(), 2u);
    EXPECT_EQ(t.top(), 2u);
    EXPECT_EQ(c.top(), 2u);
}

TEST(EventQueue, CalendarQueueAgreesWithSortedReference) {
    for (std::uint32_t n : {1u, 2u, 3u, 7u, 64u, 1000u})
        agreesWithSortedReference<edmd::CalendarQueue>(n, n, 20000);
}

TEST(EventQueue, CalendarQueueHandlesOnlyInfiniteAndFarFutureEvents) {
    edmd::CalendarQueue q;
    q.reset(4);
    EXPECT_EQ(q.top(), 0u);  // all at +infinity: the smallest index
    q.set(2, 1e9);
    EXPECT_EQ(q.top(), 2u);
    q.set(3, 1e-9);
    EXPECT_EQ(q.top(), 3u);
    q.set(3, std::numeric_limits<Real>::infinity());
    EXPECT_EQ(q.top(), 2u);
    q.set(2, std::numeric_limits<Real>::infinity());
    EXPECT_EQ(q.top(), 0u);
    EXPECT_GE(q.rebuilds(), 1u);
}

// A clump of events within round-off of one instant (the first cell crossings of a lattice whose
// sites fall on cell faces) beside ordinary ones, loaded in bulk as the engine does: no bin width
// splits the clump, so the queue keeps that bin sorted. Every top must still be the reference's,
// also while events are set into the clump, before it, after it and to +infinity.
TEST(EventQueue, CalendarQueueKeepsAClumpOfNearlyEqualTimesInOrder) {
    const std::uint32_t n = 4000;
    const Real inf = std::numeric_limits<Real>::infinity();
    edmd::CalendarQueue q;
    q.reset(n);
    q.beginBulk();
    Reference ref;
    std::vector<Real> time(n);
    CounterRng rng(3, 0);
    for (std::uint32_t i = 0; i < n; ++i) {
        time[i] = i % 3 == 0 ? 1e-15 * std::floor(rng.uniform() * 8) : 0.1 + rng.uniform();
        q.set(i, time[i]);
        ref.insert({time[i], i});
    }
    q.retune();
    ASSERT_EQ(q.top(), ref.begin()->second);
    for (int op = 0; op < 20000; ++op) {
        const std::uint32_t i = q.top();
        const Real now = q.topTime();
        const Real u = rng.uniform();
        // Mostly later (as a popped event is), sometimes back into the clump or to +infinity.
        const Real t = u < 0.1 ? now + 1e-15 * std::floor(rng.uniform() * 4)
                               : (u < 0.12 ? inf : now + 0.5 * rng.uniform());
        setBoth(q, ref, time, i, t);
        // An arbitrary particle moved earlier into the clump's instant now and then.
        if (u > 0.97) {
            const auto j = static_cast<std::uint32_t>(rng.uniform() * n);
            const Real tj = ref.begin()->first < inf ? ref.begin()->first : now;
            setBoth(q, ref, time, j, tj);
        }
        ASSERT_EQ(q.top(), ref.begin()->second) << "operation " << op;
        ASSERT_EQ(q.topTime(), ref.begin()->first) << "operation " << op;
    }
}
