// SPDX-License-Identifier: MIT
// Global particle id -> storage slot for one rank of the parallel event-driven engine (edmd spec
// 3.6: a rank holds its own particles and the virtual copies of its halo). Open addressing with
// linear probing in one flat array (load <= 3/4, deletion by backward shift, no tombstones): a
// rank's memory grows with the particles it holds (N/P plus halo), not with N, and the rollback
// copy of spec 3.4 is one array copy.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace granulab::edmd {

class IdSlotMap {
public:
    static constexpr std::uint32_t kNone = 0xFFFFFFFFu;  ///< find(): the id is not held

    /// Slot of `id`, or kNone.
    std::uint32_t find(std::uint32_t id) const noexcept {
        if (m_table.empty()) return kNone;
        for (std::size_t i = home(id);; i = (i + 1) & mask()) {
            const std::uint64_t e = m_table[i];
            if (e == kEmpty) return kNone;
            if (static_cast<std::uint32_t>(e >> 32) == id) return static_cast<std::uint32_t>(e);
        }
    }
    /// Maps `id` to `slot` (slot != kNone), replacing its slot if it is held.
    void set(std::uint32_t id, std::uint32_t slot) {
        if (4 * (m_size + 1) > 3 * m_table.size()) grow();
        std::size_t i = home(id);
        while (m_table[i] != kEmpty && static_cast<std::uint32_t>(m_table[i] >> 32) != id)
            i = (i + 1) & mask();
        if (m_table[i] == kEmpty) ++m_size;
        m_table[i] = entry(id, slot);
    }
    /// Forgets `id` (nothing happens if it is not held).
    void erase(std::uint32_t id) noexcept {
        if (m_table.empty()) return;
        std::size_t i = home(id);
        for (;; i = (i + 1) & mask()) {
            if (m_table[i] == kEmpty) return;
            if (static_cast<std::uint32_t>(m_table[i] >> 32) == id) break;
        }
        // Backward shift: later entries of the probe run move into the hole when their home
        // position does not lie (cyclically) after it.
        for (std::size_t j = (i + 1) & mask();; j = (j + 1) & mask()) {
            const std::uint64_t e = m_table[j];
            if (e == kEmpty) break;
            const std::size_t h = home(static_cast<std::uint32_t>(e >> 32));
            if (((j - h) & mask()) >= ((j - i) & mask())) {
                m_table[i] = e;
                i = j;
            }
        }
        m_table[i] = kEmpty;
        --m_size;
    }
    std::size_t size() const noexcept { return m_size; }
    std::size_t memoryBytes() const noexcept { return m_table.capacity() * sizeof(std::uint64_t); }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    static std::uint64_t entry(std::uint32_t id, std::uint32_t slot) noexcept {
        return (std::uint64_t{id} << 32) | slot;
    }
    std::size_t mask() const noexcept { return m_table.size() - 1; }
    std::size_t home(std::uint32_t id) const noexcept {  // Fibonacci hashing
        return static_cast<std::size_t>((std::uint64_t{id} * 0x9E3779B97F4A7C15ull) >> m_shift);
    }
    void grow() {
        std::vector<std::uint64_t> old;
        old.swap(m_table);
        const std::size_t capacity = old.empty() ? 16 : 2 * old.size();
        m_table.assign(capacity, kEmpty);
        m_shift = 64;
        for (std::size_t c = capacity; c > 1; c >>= 1) --m_shift;
        m_size = 0;
        for (const std::uint64_t e : old)
            if (e != kEmpty) set(static_cast<std::uint32_t>(e >> 32), static_cast<std::uint32_t>(e));
    }

    std::vector<std::uint64_t> m_table;  ///< (id << 32) | slot per position, or kEmpty
    std::size_t m_size = 0;
    int m_shift = 64;  ///< 64 - log2(capacity)
};

}  // namespace granulab::edmd
