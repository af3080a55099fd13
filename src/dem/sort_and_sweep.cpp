// SPDX-License-Identifier: MIT
// Incremental sort-and-sweep broad phase (gc2d spec section 5.2, Schinner 1999): bounding boxes
// [x - r - m/2, x + r + m/2] x [y - r - m/2, y + r + m/2] (m = the neighbour-list margin), two
// endpoint lists kept sorted by insertion sort from the previous call, and the set of overlapping
// boxes updated by the swap rules of Table 2.3:
//   b_m b_n -> b_n b_m, e_m e_n -> e_n e_m : no change
//   b_m e_n -> e_n b_m (separate)          : remove the pair
//   e_m b_n -> b_n e_m (start overlapping) : add the pair if the other axis overlaps
// For slowly moving particles the lists are almost sorted and an update costs O(N + swaps). New
// particles (slots appended since the last call) are inserted by the same insertion sort.
// The overlapping boxes are then filtered with the exact disk test, so the result equals the
// brute-force pair set.
#include <algorithm>

#include "dem/broad_phase.hpp"

namespace granulab::dem {

namespace {
inline std::uint64_t orderedKey(std::uint32_t a, std::uint32_t b) noexcept {
    return a < b ? pairKey(a, b) : pairKey(b, a);
}
}  // namespace

void SortAndSweep::updateBoxes(const model::ParticleStore& s, Real margin) {
    const std::size_t n = s.size();
    m_box.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Real h = s.radius[i] + 0.5 * margin;
        m_box[i] = {s.x[i] - h, s.x[i] + h, s.y[i] - h, s.y[i] + h};
    }
}

bool SortAndSweep::overlapOn(int axis, std::uint32_t a, std::uint32_t b) const noexcept {
    const auto& p = m_box[a];
    const auto& q = m_box[b];
    return axis == 0 ? (p[0] < q[1] && q[0] < p[1]) : (p[2] < q[3] && q[2] < p[3]);
}

void SortAndSweep::sortAxis(int axis) {
    auto& list = axis == 0 ? m_xs : m_ys;
    const int off = axis == 0 ? 0 : 2;
    for (auto& e : list) e.value = m_box[e.box][off + (e.isEnd ? 1 : 0)];
    // Insertion sort; every adjacent swap applies one rule of Table 2.3.
    for (std::size_t k = 1; k < list.size(); ++k) {
        const Endpoint moving = list[k];
        std::size_t j = k;
        // At equal values an end sorts before a begin, so the list order always says "strict
        // overlap" exactly when the values do (touching boxes do not overlap).
        while (j > 0 && (list[j - 1].value > moving.value ||
                         (list[j - 1].value == moving.value && !list[j - 1].isEnd && moving.isEnd))) {
            const Endpoint& left = list[j - 1];
            if (left.box != moving.box) {
                if (!left.isEnd && moving.isEnd) {
                    m_overlaps.erase(orderedKey(left.box, moving.box));  // b_m e_n -> e_n b_m: separate
                } else if (left.isEnd && !moving.isEnd) {                // e_m b_n -> b_n e_m: start
                    if (overlapOn(1 - axis, left.box, moving.box))
                        m_overlaps.insert(orderedKey(left.box, moving.box));
                }
            }
            list[j] = list[j - 1];
            --j;
        }
        list[j] = moving;
    }
}

void SortAndSweep::findPairs(const model::ParticleStore& s, Real margin, std::vector<std::uint64_t>& out) {
    const std::size_t n = s.size();
    if (n < m_tracked || margin != m_margin) {  // particles removed or margin changed: start over
        m_xs.clear();
        m_ys.clear();
        m_overlaps.clear();
        m_tracked = 0;
        m_margin = margin;
    }
    updateBoxes(s, margin);
    // New slots enter at the far end of both lists (value +inf) and are sorted into place; the
    // swap rules then find their overlaps, as for moving boxes.
    for (std::size_t i = m_tracked; i < n; ++i)
        for (auto* list : {&m_xs, &m_ys}) {
            list->push_back({1e300, static_cast<std::uint32_t>(i), false});
            list->push_back({1e300, static_cast<std::uint32_t>(i), true});
        }
    if (m_tracked == 0 && n > 0) {  // first call: sort fully, then sweep once for the overlaps
        for (int axis = 0; axis < 2; ++axis) {
            auto& list = axis == 0 ? m_xs : m_ys;
            const int off = axis == 0 ? 0 : 2;
            for (auto& e : list) e.value = m_box[e.box][off + (e.isEnd ? 1 : 0)];
            std::sort(list.begin(), list.end(), [](const Endpoint& a, const Endpoint& b) {
                return a.value < b.value || (a.value == b.value && a.isEnd && !b.isEnd);
            });
        }
        std::vector<std::uint32_t> active;
        for (const auto& e : m_xs) {
            if (e.isEnd) {
                // A box narrower than the coordinate resolution sorts its end before its begin
                // (equal values); it overlaps nothing and was never made active.
                if (const auto it = std::find(active.begin(), active.end(), e.box); it != active.end())
                    active.erase(it);
                continue;
            }
            for (const std::uint32_t other : active)
                if (overlapOn(1, other, e.box)) m_overlaps.insert(orderedKey(other, e.box));
            active.push_back(e.box);
        }
    } else {
        sortAxis(0);
        sortAxis(1);
    }
    m_tracked = n;
    out.clear();
    for (const std::uint64_t key : m_overlaps) {
        const std::uint32_t i = keyFirst(key), j = keySecond(key);
        const Real dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
        const Real reach = s.radius[i] + s.radius[j] + margin;
        if (dx * dx + dy * dy < reach * reach) out.push_back(key);
    }
    std::sort(out.begin(), out.end());
}

void SortAndSweep::findWallPairs(const model::ParticleStore& s, const model::WallSet& walls, Real margin,
                                 std::vector<std::uint64_t>& out) {
    m_wallGrid.findWallPairs(s, walls, margin, out);
}

std::size_t SortAndSweep::memoryBytes() const noexcept {
    return (m_xs.capacity() + m_ys.capacity()) * sizeof(Endpoint) + m_box.capacity() * sizeof(m_box[0]) +
           m_overlaps.size() * (sizeof(std::uint64_t) + 2 * sizeof(void*)) + m_wallGrid.memoryBytes();
}

}  // namespace granulab::dem
