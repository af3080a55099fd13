// SPDX-License-Identifier: MIT
// Morton numbering of the cell grid for the domain decomposition of the parallel event-driven
// engine (edmd spec section 3.1): the cell number is the bit interleave of the cell coordinates,
// x least significant, so every aligned block of 2^n consecutive numbers is a box of cells
// (side ratios 1:1 or 1:2 in 2D, 1:1:1, 1:1:2 or 1:2:2 in 3D when all axes have enough bits).
// Grids that are not 2^k cells per axis are numbered as if padded to the next power of two per
// axis, the padding spread evenly over the axis: real cell c of n sits at padded coordinate
// floor(c 2^b / n), so aligned blocks of equal size hold real cells within one per axis of each
// other (a first split of a 1618-cell axis gives 809 + 809, not 1024 + 594).
// Used at set-up and at synchronisation points, not per event.
#pragma once
#include <array>
#include <cstdint>

namespace granulab::edmd {

/// Morton numbering of a D-dimensional grid of cells[d] cells per axis (D = 2 or 3; edmd spec 3.1).
/// Each axis is padded to the next power of two: bits[d] = ceil(log2(cells[d])) (0 for one cell).
/// Interleaving: the bits of the number are assigned from the least significant end in the cycle
/// x, y, (z), x, y, (z), ...; an axis whose bits are used up is skipped. With equal bits per axis
/// this is the spec's order (most significant first) z[k] y[k] x[k] ... z[1] y[1] x[1]; with
/// unequal bits (16 x 4 cells: positions 0:x0 1:y0 2:x1 3:y1 4:x2 5:x3) every aligned block of
/// 2^n consecutive numbers is still a box.
template <int D>
class MortonGrid {
    static_assert(D == 2 || D == 3, "MortonGrid: D must be 2 or 3");

public:
    /// Throws std::invalid_argument if a count is < 1 or > 2^30 (so that the exclusive upper
    /// corner of a block fits an int) or the total number of bits exceeds 62.
    explicit MortonGrid(std::array<int, D> cells);

    /// Morton number of the cell with (padded) coordinates c, 0 <= c[d] < 2^bits[d]. O(totalBits).
    std::uint64_t index(const std::array<int, D>& c) const noexcept;
    /// Padded coordinates of the real cell `cell` (0 <= cell[d] < cells[d]): floor(c 2^b / n).
    std::array<int, D> padded(const std::array<int, D>& cell) const noexcept;
    /// Morton number of the real cell `cell`: index(padded(cell)).
    std::uint64_t indexOfCell(const std::array<int, D>& cell) const noexcept { return index(padded(cell)); }
    /// Inverse of index(): the (padded) coordinates of Morton number m < paddedCount(). O(totalBits).
    std::array<int, D> coords(std::uint64_t m) const noexcept;

    /// Sum of bits[d].
    int totalBits() const noexcept { return m_totalBits; }
    /// Bits of axis d, ceil(log2(cells[d])).
    int bits(int d) const noexcept { return m_bits[d]; }
    /// Number of Morton numbers, 2^totalBits (real and padded cells).
    std::uint64_t paddedCount() const noexcept { return std::uint64_t{1} << m_totalBits; }
    /// Real (unpadded) cells per axis.
    std::array<int, D> cells() const noexcept { return m_cells; }
    /// True if the cell with number m < paddedCount() is a real cell (not padding).
    bool real(std::uint64_t m) const noexcept;

    /// Real (unpadded) cells in the aligned block [start, start + 2^log2Size) (start divisible by
    /// 2^log2Size, log2Size <= totalBits): exact, from the box the block is, O(totalBits).
    std::uint64_t realCellsIn(std::uint64_t start, int log2Size) const noexcept;
    /// The real cells of the aligned block [start, start + 2^log2Size): the box lo <= c < hi of
    /// real-cell coordinates (hi[d] == lo[d] on some axis when the block holds none). O(totalBits).
    void realBox(std::uint64_t start, int log2Size, std::array<int, D>& lo,
                 std::array<int, D>& hi) const noexcept;
    /// The box of cells (lo inclusive, hi exclusive, in padded coordinates) that the aligned block
    /// [start, start + 2^log2Size) is. O(totalBits).
    void blockBox(std::uint64_t start, int log2Size, std::array<int, D>& lo,
                  std::array<int, D>& hi) const noexcept;

private:
    std::array<int, D> m_cells{};
    std::array<int, D> m_bits{};
    int m_totalBits = 0;
    /// Per Morton bit position p (from the least significant): the axis it belongs to and the
    /// bit of that axis' coordinate it holds.
    std::array<std::int8_t, 64> m_axis{};
    std::array<std::int8_t, 64> m_axisBit{};
};

extern template class MortonGrid<2>;
extern template class MortonGrid<3>;

}  // namespace granulab::edmd
