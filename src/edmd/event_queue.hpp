// SPDX-License-Identifier: MIT
// Event queues of the event-driven engine (edmd spec section 2.3): one future event per
// particle, keyed by its time; the key of a particle is replaced (never removed) when its event
// changes, stale events are recognised by the caller when they reach the top. Ties are broken
// by the smaller tie key (the engine sets the global particle ids, setTieKeys; by default the
// index), so the event order is deterministic and independent of storage slots and ranks.
// Three implementations behind one interface (no virtual calls; the engine is a template on the
// queue type):
//  * AddressableHeap: implicit binary heap with heap_pos[particle] (the thesis' queue).
//  * TournamentTree: complete binary tree over the N particles (Marin, Risso & Cordero 1993),
//    each inner node holding the earlier of its two children; replace walks one leaf-to-root
//    path with no data-dependent branches on the way up.
//  * CalendarQueue: O(1) amortised, in the style of Paul (J. Comput. Phys. 221, 2007): a window
//    of B bins of width w in doubly linked lists, an overflow list beyond the window, and the
//    earliest event found by a scan of the current bin (a few events). When the window is used
//    up it is rebuilt from the overflow: it starts at the earliest pending time and spans twice
//    the mean distance of the pending times from it (w = span / B); when the current bin grows
//    long (more than 64 events) everything is re-binned, at most once per B updates, so the
//    cost stays O(1) amortised.
#pragma once
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <new>
#include <vector>

#include "core/types.hpp"

namespace granulab::edmd {

/// Allocator of the per-particle arrays: blocks of 2 MiB and more are 2 MiB aligned and marked
/// for transparent huge pages (madvise), because every event reads a few random lines of
/// arrays of up to gigabytes and 4 KiB pages would add a page walk (TLB miss) to most of them.
/// Contents and results do not depend on it.
template <class T>
struct BigArrayAllocator {
    using value_type = T;
    static constexpr std::size_t kHuge = std::size_t{1} << 21;
    BigArrayAllocator() noexcept = default;
    template <class U>
    BigArrayAllocator(const BigArrayAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kHuge) return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
        const std::size_t rounded = (bytes + kHuge - 1) / kHuge * kHuge;
        void* p = std::aligned_alloc(kHuge, rounded);
        if (!p) throw std::bad_alloc();
        madvise(p, rounded, MADV_HUGEPAGE);  // a hint; failure only costs speed
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t n) noexcept {
        if (n * sizeof(T) < kHuge)
            ::operator delete(p, std::align_val_t(alignof(T)));
        else
            std::free(p);
    }
    template <class U>
    bool operator==(const BigArrayAllocator<U>&) const noexcept {
        return true;
    }
};
template <class T>
using BigVector = std::vector<T, BigArrayAllocator<T>>;

/// The tie keys of a queue: key[i] orders events of equal time (null: the index itself).
struct TieKeys {
    const std::uint32_t* key = nullptr;
    std::uint32_t operator()(std::uint32_t i) const noexcept { return key ? key[i] : i; }
    /// (t, key) order of two entries; the key is read only on equal times (rare).
    bool earlier(Real ta, std::uint32_t a, Real tb, std::uint32_t b) const noexcept {
        return ta < tb || (ta == tb && (*this)(a) < (*this)(b));
    }
};

class AddressableHeap {
public:
    /// n particles, every time +infinity.
    void reset(std::uint32_t n);
    /// After many set() calls in a row (a whole schedule built): nothing to re-tune here.
    void beginBulk() noexcept {}
    void retune() noexcept {}
    /// Adds particles up to n (new ones at +infinity), keeping the others' times. O(added).
    void grow(std::uint32_t n);
    /// Orders equal times by key[i] (an array indexed like the queue; it must outlive the use).
    void setTieKeys(const std::uint32_t* key) noexcept { m_tie.key = key; }
    /// Sets the event time of particle i [s] (decrease or increase key). O(log n).
    void set(std::uint32_t i, Real t) noexcept;
    /// Particle with the earliest event (ties: smallest index). O(1).
    std::uint32_t top() const noexcept { return m_heap[0]; }
    Real topTime() const noexcept { return m_time[m_heap[0]]; }
    Real time(std::uint32_t i) const noexcept { return m_time[i]; }
    std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(m_time.size()); }
    std::size_t memoryBytes() const noexcept {
        return m_time.capacity() * sizeof(Real) + (m_heap.capacity() + m_pos.capacity()) * 4;
    }

private:
    bool before(std::uint32_t a, std::uint32_t b) const noexcept {
        return m_tie.earlier(m_time[a], a, m_time[b], b);
    }
    TieKeys m_tie;
    void place(std::uint32_t slot, std::uint32_t particle) noexcept {
        m_heap[slot] = particle;
        m_pos[particle] = slot;
    }
    BigVector<Real> m_time;           ///< [s] event time per particle
    BigVector<std::uint32_t> m_heap;  ///< particles in heap order
    BigVector<std::uint32_t> m_pos;   ///< heap slot of each particle
};

class TournamentTree {
public:
    void reset(std::uint32_t n);
    /// After many set() calls in a row (a whole schedule built): nothing to re-tune here.
    void beginBulk() noexcept {}
    void retune() noexcept {}
    void grow(std::uint32_t n);
    void setTieKeys(const std::uint32_t* key) noexcept { m_tie.key = key; }
    void set(std::uint32_t i, Real t) noexcept;
    std::uint32_t top() const noexcept { return m_node[1]; }
    Real topTime() const noexcept { return m_time[m_node[1]]; }
    Real time(std::uint32_t i) const noexcept { return m_time[i]; }
    std::uint32_t size() const noexcept { return m_n; }
    std::size_t memoryBytes() const noexcept {
        return m_time.capacity() * sizeof(Real) + m_node.capacity() * 4;
    }

private:
    /// Whether leaf b's event comes before leaf a's; the padding leaves (index >= n, no tie key)
    /// come after every particle of equal time.
    bool before(std::uint32_t b, std::uint32_t a) const noexcept {
        if (m_time[b] != m_time[a]) return m_time[b] < m_time[a];
        return (b < m_n ? m_tie(b) : ~std::uint32_t{0}) < (a < m_n ? m_tie(a) : ~std::uint32_t{0});
    }
    TieKeys m_tie;
    std::uint32_t m_n = 0, m_leaves = 1;  ///< particles; leaves (power of two >= n)
    BigVector<Real> m_time;               ///< [s] per particle, padded leaves at +infinity
    BigVector<std::uint32_t> m_node;      ///< 1-based tree: node k holds the winner of 2k, 2k+1
};

/// Particle indices must be below 2^31 (the top bit of a back link tags a list head).
class CalendarQueue {
public:
    void reset(std::uint32_t n);
    /// Bulk loading (a whole schedule about to be set): set() only records times, and top() is
    /// undefined until retune(). Without it a window cut from the first times set would pile
    /// every earlier one into the current bin and scan it on every set (quadratic: minutes at
    /// N = 10^6 when many first events fall in one instant).
    void beginBulk() noexcept { m_bulk = true; }
    /// Ends bulk loading: the bin width from all pending times, then the earliest event. Also
    /// re-tunes a queue in use.
    void retune() noexcept;
    void grow(std::uint32_t n);
    void setTieKeys(const std::uint32_t* key) noexcept { m_tie.key = key; }
    void set(std::uint32_t i, Real t) noexcept;
    std::uint32_t top() const noexcept { return m_top; }
    Real topTime() const noexcept { return m_node[m_top].time; }
    Real time(std::uint32_t i) const noexcept { return m_node[i].time; }
    std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(m_node.size()); }
    std::uint64_t rebuilds() const noexcept { return m_rebuilds; }
    std::size_t memoryBytes() const noexcept {
        return m_node.capacity() * sizeof(Node) + m_head.capacity() * 4;
    }

private:
    static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
    static constexpr std::uint32_t kHeadOf = 0x80000000u;  ///< back link of a list head: kHeadOf | bin
    std::uint32_t binOf(Real t) const noexcept;
    void link(std::uint32_t i, std::uint32_t bin) noexcept;
    void unlink(std::uint32_t i) noexcept;
    /// Makes the current bin the first non-empty one (rebuilding the window if needed) and
    /// finds its earliest event.
    void settle() noexcept;
    void rebuild() noexcept;
    /// Moves every event to the overflow and rebuilds: re-tunes the bin width when the current
    /// bin has grown long (the first window was made from too few or unrepresentative times).
    void rebuildAll() noexcept;
    /// Sorts the list of `bin` by (time, key) and keeps it sorted (m_sortedBin) until the
    /// window moves on.
    void sortBin(std::uint32_t bin);

    /// Per particle, one 16-byte record (a quarter cache line): an update reads and writes the
    /// time and both links of a particle with one miss at large N.
    struct alignas(16) Node {
        Real time;           ///< [s]
        std::uint32_t next;  ///< list links (prev of a head: kHeadOf | bin)
        std::uint32_t prev;
    };
    TieKeys m_tie;
    BigVector<Node> m_node;
    BigVector<std::uint32_t> m_head;  ///< first particle of each bin; [B] is the overflow list
    std::uint32_t m_bins = 1, m_current = 0, m_top = 0;
    std::uint32_t m_topBin = 0;  ///< bin in which settle() found m_top
    Real m_start = 0;            ///< [s] start of bin 0
    Real m_width = 1;            ///< [s] bin width
    Real m_invWidth = 1;
    std::uint64_t m_rebuilds = 0;
    std::uint64_t m_setsSinceRebuild = 0;  ///< amortisation guard of rebuildAll
    bool m_bulk = false;                   ///< between beginBulk() and retune()
    std::uint32_t m_sortedBin = kNone;     ///< the current bin when it is kept sorted
    std::vector<std::uint32_t> m_scratch;  ///< sortBin's list
};

}  // namespace granulab::edmd
