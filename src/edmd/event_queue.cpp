// SPDX-License-Identifier: MIT
// Event queues (edmd spec section 2.3): addressable binary heap and tournament tree.
#include "edmd/event_queue.hpp"

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
    m_time[i] = t;
    std::uint32_t slot = m_pos[i];
    const auto n = static_cast<std::uint32_t>(m_heap.size());
    if (earlier(t, i, old, i)) {  // sift up
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

void TournamentTree::reset(std::uint32_t n) {
    m_n = n;
    m_leaves = 1;
    while (m_leaves < n) m_leaves *= 2;
    m_time.assign(m_leaves, kNever);  // padding leaves never win against a real particle of equal time
    m_node.assign(2 * static_cast<std::size_t>(m_leaves), 0);
    for (std::uint32_t k = 0; k < m_leaves; ++k) m_node[m_leaves + k] = k;
    for (std::uint32_t k = m_leaves - 1; k >= 1; --k) {
        const std::uint32_t a = m_node[2 * k], b = m_node[2 * k + 1];
        m_node[k] = earlier(m_time[b], b, m_time[a], a) ? b : a;
    }
}

void TournamentTree::set(std::uint32_t i, Real t) noexcept {
    m_time[i] = t;
    for (std::uint32_t k = (m_leaves + i) / 2; k >= 1; k /= 2) {
        const std::uint32_t a = m_node[2 * k], b = m_node[2 * k + 1];
        m_node[k] = earlier(m_time[b], b, m_time[a], a) ? b : a;
    }
}

}  // namespace granulab::edmd
