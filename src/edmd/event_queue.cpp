// SPDX-License-Identifier: MIT
// Event queues (edmd spec section 2.3): addressable binary heap, tournament tree and calendar
// queue.
#include "edmd/event_queue.hpp"

#include <algorithm>
#include <cmath>

namespace granulab::edmd {

namespace {
constexpr Real kNever = std::numeric_limits<Real>::infinity();
}

void AddressableHeap::reset(std::uint32_t n) {
    m_time.assign(n, kNever);
    m_heap.resize(n);
    m_pos.resize(n);
    for (std::uint32_t k = 0; k < n; ++k) place(k, k);  // all +infinity, index order: a valid heap
}

void AddressableHeap::set(std::uint32_t i, Real t) noexcept {
    const Real old = m_time[i];
    // The same key: the heap stays ordered (the parallel kernel's border queue resets most of
    // its entries to +infinity, where a sift would walk down the ids of all other infinities).
    if (t == old) return;
    m_time[i] = t;
    std::uint32_t slot = m_pos[i];
    const auto n = static_cast<std::uint32_t>(m_heap.size());
    if (t < old) {  // sift up
        while (slot > 0) {
            const std::uint32_t parent = (slot - 1) / 2;
            if (!before(i, m_heap[parent])) break;
            place(slot, m_heap[parent]);
            slot = parent;
        }
    } else {  // sift down
        for (;;) {
            const std::uint32_t left = 2 * slot + 1;
            if (left >= n) break;
            std::uint32_t child = left;
            if (left + 1 < n && before(m_heap[left + 1], m_heap[left])) child = left + 1;
            if (!before(m_heap[child], i)) break;
            place(slot, m_heap[child]);
            slot = child;
        }
    }
    place(slot, i);
}

void AddressableHeap::grow(std::uint32_t n) {
    // New entries at +infinity go to the end: their parents are finite or also +infinity with a
    // key that may be larger, so each is sifted up (rarely moves).
    const auto old = static_cast<std::uint32_t>(m_time.size());
    if (n <= old) return;
    m_time.resize(n, kNever);
    m_heap.resize(n);
    m_pos.resize(n);
    for (std::uint32_t k = old; k < n; ++k) {
        std::uint32_t slot = k;
        while (slot > 0 && before(k, m_heap[(slot - 1) / 2])) {
            place(slot, m_heap[(slot - 1) / 2]);
            slot = (slot - 1) / 2;
        }
        place(slot, k);
    }
}

void TournamentTree::grow(std::uint32_t n) {
    if (n <= m_n) return;
    std::vector<Real> times(m_time.begin(), m_time.begin() + m_n);
    reset(n);
    for (std::uint32_t i = 0; i < times.size(); ++i) set(i, times[i]);
}

void CalendarQueue::grow(std::uint32_t n) {
    // New particles at +infinity join the overflow list; bins and window are kept.
    const auto old = static_cast<std::uint32_t>(m_node.size());
    if (n <= old) return;
    m_node.resize(n, Node{kNever, kNone, kNone});
    for (std::uint32_t i = old; i < n; ++i) link(i, m_bins);
    if (old == 0) {
        m_top = 0;
        settle();
    }
}

void TournamentTree::reset(std::uint32_t n) {
    m_n = n;
    m_leaves = 1;
    while (m_leaves < n) m_leaves *= 2;
    m_time.assign(m_leaves, kNever);  // padding leaves never win against a real particle of equal time
    m_node.assign(2 * static_cast<std::size_t>(m_leaves), 0);
    for (std::uint32_t k = 0; k < m_leaves; ++k) m_node[m_leaves + k] = k;
    for (std::uint32_t k = m_leaves - 1; k >= 1; --k) {
        const std::uint32_t a = m_node[2 * k], b = m_node[2 * k + 1];
        m_node[k] = before(b, a) ? b : a;
    }
}

void TournamentTree::set(std::uint32_t i, Real t) noexcept {
    m_time[i] = t;
    for (std::uint32_t k = (m_leaves + i) / 2; k >= 1; k /= 2) {
        const std::uint32_t a = m_node[2 * k], b = m_node[2 * k + 1];
        m_node[k] = before(b, a) ? b : a;
    }
}

// ---------------------------------------------------------------- calendar queue

std::uint32_t CalendarQueue::binOf(Real t) const noexcept {
    const Real x = (t - m_start) * m_invWidth;  // +inf and beyond-window times go to the overflow
    if (!(x < static_cast<Real>(m_bins))) return m_bins;
    if (!(x >= static_cast<Real>(m_current)))
        return m_current;  // earlier than the current bin: scan it there
    return static_cast<std::uint32_t>(x);
}

void CalendarQueue::link(std::uint32_t i, std::uint32_t bin) noexcept {
    if (bin == m_sortedBin && m_head[bin] != kNone &&
        !m_tie.earlier(m_node[i].time, i, m_node[m_head[bin]].time, m_head[bin])) {
        // Keep the sorted bin sorted: after the last entry that comes before i.
        std::uint32_t after = m_head[bin];
        while (m_node[after].next != kNone &&
               m_tie.earlier(m_node[m_node[after].next].time, m_node[after].next, m_node[i].time, i))
            after = m_node[after].next;
        m_node[i].prev = after;
        m_node[i].next = m_node[after].next;
        if (m_node[after].next != kNone) m_node[m_node[after].next].prev = i;
        m_node[after].next = i;
        return;
    }
    m_node[i].prev = kHeadOf | bin;  // the head of a list keeps its bin in the back link
    m_node[i].next = m_head[bin];
    if (m_head[bin] != kNone) m_node[m_head[bin]].prev = i;
    m_head[bin] = i;
}

void CalendarQueue::unlink(std::uint32_t i) noexcept {
    const std::uint32_t prev = m_node[i].prev;
    if (prev & kHeadOf)
        m_head[prev & ~kHeadOf] = m_node[i].next;
    else
        m_node[prev].next = m_node[i].next;
    if (m_node[i].next != kNone) m_node[m_node[i].next].prev = prev;  // a new head inherits the bin tag
}

void CalendarQueue::reset(std::uint32_t n) {
    m_node.assign(n, Node{kNever, kNone, kNone});
    m_bins = std::clamp<std::uint32_t>(n, 1, kHeadOf - 1);  // bin numbers must fit beside the tag
    m_head.assign(m_bins + 1, kNone);
    m_current = 0;
    m_sortedBin = kNone;
    m_start = 0;
    m_width = m_invWidth = 1;
    m_rebuilds = 0;
    for (std::uint32_t i = n; i-- > 0;) link(i, m_bins);  // all in the overflow
    m_top = 0;
    m_bulk = false;
    if (n) settle();
}

void CalendarQueue::rebuild() noexcept {
    ++m_rebuilds;
    // settle() calls this when every bin is empty, so every node waits in the overflow: the
    // nodes are read in index order (a sequential pass) rather than along the overflow list (a
    // random walk through memory, one cache miss per node at N = 1e6). The bins' list order
    // changes nothing: the top is the (time, key) minimum of its bin, and a sorted bin is
    // sorted by (time, key).
    const auto n = static_cast<std::uint32_t>(m_node.size());
    // New window from the pending (finite) times: starts at the earliest, bin width such that
    // the window spans twice the mean distance of the events from the earliest one.
    Real tmin = kNever, sum = 0;
    std::uint32_t finite = 0;
    for (std::uint32_t i = 0; i < n; ++i)
        if (m_node[i].time < kNever) {
            tmin = std::min(tmin, m_node[i].time);
            sum += m_node[i].time;
            ++finite;
        }
    if (finite == 0) return;  // only +infinity pending: everything stays in the overflow
    const Real span = 2 * (sum / finite - tmin);
    m_start = tmin;
    m_width = span > 0 ? span / m_bins : 1;
    if (!(m_width > 0) || !(tmin + m_width > tmin)) m_width = std::max<Real>(1, std::abs(tmin)) * 1e-12;
    m_invWidth = 1 / m_width;
    m_current = 0;
    m_sortedBin = kNone;
    m_head[m_bins] = kNone;
    for (std::uint32_t i = n; i-- > 0;) link(i, binOf(m_node[i].time));  // ascending within a bin
}

void CalendarQueue::retune() noexcept {
    m_bulk = false;
    if (m_node.empty()) return;
    rebuildAll();
    settle();
}

void CalendarQueue::rebuildAll() noexcept {
    // Every node to the overflow, in index order (as rebuild(): sequential, not list walks).
    m_sortedBin = kNone;
    std::fill(m_head.begin(), m_head.end(), kNone);
    for (auto i = static_cast<std::uint32_t>(m_node.size()); i-- > 0;) link(i, m_bins);
    m_current = m_bins;
    m_setsSinceRebuild = 0;
}

void CalendarQueue::settle() noexcept {
    for (;;) {
        while (m_current < m_bins && m_head[m_current] == kNone) ++m_current;
        if (m_current < m_bins) break;
        const std::uint32_t before = m_head[m_bins];
        rebuild();
        if (m_head[m_bins] == before && m_current >= m_bins) break;  // only +infinity left
        if (m_current >= m_bins) break;
    }
    const std::uint32_t bin = m_current < m_bins ? m_current : m_bins;
    if (bin == m_sortedBin) {  // a long bin, kept sorted: its head is the earliest
        m_top = m_head[bin];
        m_topBin = bin;
        return;
    }
    std::uint32_t best = m_head[bin];
    std::uint32_t scanned = 0;
    for (std::uint32_t i = m_node[best].next; i != kNone; i = m_node[i].next) {
        ++scanned;
        if (m_tie.earlier(m_node[i].time, i, m_node[best].time, best)) best = i;
    }
    m_top = best;
    m_topBin = bin;
    constexpr std::uint32_t kLongBin = 64;
    if (scanned > kLongBin && bin < m_bins && m_setsSinceRebuild > m_bins) {
        rebuildAll();  // re-tune the width from all pending times, then find the top again
        settle();
    } else if (scanned > kLongBin && bin < m_bins) {
        // A bin no width splits (a clump of events within round-off of one instant, such as
        // the first cell crossings of a lattice whose sites fall on cell faces): sorted once,
        // its head is the top until the window moves on (else every event rescans it).
        sortBin(bin);
        m_top = m_head[bin];
    }
}

void CalendarQueue::sortBin(std::uint32_t bin) {
    m_scratch.clear();
    for (std::uint32_t i = m_head[bin]; i != kNone; i = m_node[i].next) m_scratch.push_back(i);
    std::sort(m_scratch.begin(), m_scratch.end(), [this](std::uint32_t a, std::uint32_t b) {
        return m_tie.earlier(m_node[a].time, a, m_node[b].time, b);
    });
    std::uint32_t prev = kHeadOf | bin;
    for (const std::uint32_t i : m_scratch) {
        m_node[i].prev = prev;
        if (prev & kHeadOf)
            m_head[bin] = i;
        else
            m_node[prev].next = i;
        prev = i;
    }
    m_node[prev].next = kNone;
    m_sortedBin = bin;
}

void CalendarQueue::set(std::uint32_t i, Real t) noexcept {
    ++m_setsSinceRebuild;
    unlink(i);
    m_node[i].time = t;
    if (m_bulk) {  // bulk loading: everything waits in the overflow for retune()
        link(i, m_bins);
        return;
    }
    link(i, binOf(t));
    // The earliest event changes only if i was it or i now beats it.
    if (i == m_top || m_tie.earlier(t, i, m_node[m_top].time, m_top) || m_topBin != m_current) settle();
}

}  // namespace granulab::edmd
