// SPDX-License-Identifier: MIT
// Morton numbering of the cell grid (edmd spec section 3.1); see morton.hpp.
#include "edmd/parallel/morton.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace granulab::edmd {

template <int D>
MortonGrid<D>::MortonGrid(std::array<int, D> cells) : m_cells(cells) {
    for (int d = 0; d < D; ++d) {
        if (cells[d] < 1 || cells[d] > (1 << 30))
            throw std::invalid_argument("MortonGrid: cell count " + std::to_string(cells[d]) + " on axis " +
                                        std::to_string(d) + " (must be 1 to 2^30)");
        int b = 0;
        while ((std::int64_t{1} << b) < cells[d]) ++b;
        m_bits[d] = b;
        m_totalBits += b;
    }
    if (m_totalBits > 62)
        throw std::invalid_argument("MortonGrid: " + std::to_string(m_totalBits) +
                                    " Morton bits in total (at most 62)");
    // Positions from the least significant end, cycling x, y, (z) and skipping used-up axes.
    std::array<int, D> used{};
    for (int p = 0; p < m_totalBits;) {
        for (int d = 0; d < D; ++d) {
            if (used[d] < m_bits[d]) {
                m_axis[p] = static_cast<std::int8_t>(d);
                m_axisBit[p] = static_cast<std::int8_t>(used[d]);
                ++used[d];
                ++p;
            }
        }
    }
}

template <int D>
std::uint64_t MortonGrid<D>::index(const std::array<int, D>& c) const noexcept {
    std::uint64_t m = 0;
    for (int p = 0; p < m_totalBits; ++p) {
        const auto bit = (static_cast<std::uint64_t>(c[m_axis[p]]) >> m_axisBit[p]) & 1u;
        m |= bit << p;
    }
    return m;
}

template <int D>
std::array<int, D> MortonGrid<D>::coords(std::uint64_t m) const noexcept {
    std::array<int, D> c{};
    for (int p = 0; p < m_totalBits; ++p) c[m_axis[p]] |= static_cast<int>((m >> p) & 1u) << m_axisBit[p];
    return c;
}

namespace {
/// ceil(p n / 2^b): the first real cell at padded coordinate >= p on an axis of n cells.
std::int64_t firstCellFrom(std::int64_t p, std::int64_t n, int b) noexcept {
    return ((p * n) + (std::int64_t{1} << b) - 1) >> b;
}
}  // namespace

template <int D>
std::array<int, D> MortonGrid<D>::padded(const std::array<int, D>& cell) const noexcept {
    std::array<int, D> p{};
    for (int d = 0; d < D; ++d)
        p[d] = static_cast<int>((static_cast<std::int64_t>(cell[d]) << m_bits[d]) / m_cells[d]);
    return p;
}

template <int D>
bool MortonGrid<D>::real(std::uint64_t m) const noexcept {
    // Padded coordinate p holds a real cell when the first real cell at or after it sits there.
    const std::array<int, D> p = coords(m);
    for (int d = 0; d < D; ++d) {
        const std::int64_t c = firstCellFrom(p[d], m_cells[d], m_bits[d]);
        if (c >= m_cells[d] || ((c << m_bits[d]) / m_cells[d]) != p[d]) return false;
    }
    return true;
}

template <int D>
void MortonGrid<D>::blockBox(std::uint64_t start, int log2Size, std::array<int, D>& lo,
                             std::array<int, D>& hi) const noexcept {
    // The low log2Size positions run over all values inside the block: per axis they are its
    // lowest bits, so the block spans 2^(number of those positions on the axis) cells from the
    // coordinates of its first number.
    lo = coords(start);
    std::array<int, D> freeBits{};
    for (int p = 0; p < log2Size; ++p) ++freeBits[m_axis[p]];
    for (int d = 0; d < D; ++d) hi[d] = lo[d] + (1 << freeBits[d]);
}

template <int D>
void MortonGrid<D>::realBox(std::uint64_t start, int log2Size, std::array<int, D>& lo,
                            std::array<int, D>& hi) const noexcept {
    blockBox(start, log2Size, lo, hi);
    // Real cells c with lo <= floor(c 2^b / n) < hi: from ceil(lo n / 2^b) to ceil(hi n / 2^b).
    for (int d = 0; d < D; ++d) {
        const int first = static_cast<int>(firstCellFrom(lo[d], m_cells[d], m_bits[d]));
        const int end = static_cast<int>(firstCellFrom(hi[d], m_cells[d], m_bits[d]));
        lo[d] = first;
        hi[d] = std::max(first, std::min(end, m_cells[d]));
    }
}

template <int D>
std::uint64_t MortonGrid<D>::realCellsIn(std::uint64_t start, int log2Size) const noexcept {
    std::array<int, D> lo, hi;
    realBox(start, log2Size, lo, hi);
    std::uint64_t n = 1;
    for (int d = 0; d < D; ++d) n *= static_cast<std::uint64_t>(hi[d] - lo[d]);
    return n;
}

template class MortonGrid<2>;
template class MortonGrid<3>;

}  // namespace granulab::edmd
