// SPDX-License-Identifier: MIT
// Cell grid shared by the gas analyses of edmd spec section 5.2 (cluster search, pair
// correlation): particles binned by a counting sort into cells of edge >= a search distance,
// positions copied in cell order, and a visitor over adjacent cell pairs with periodic wrapping.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "analysis/point_set.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// Throws std::invalid_argument unless dim is 2 or 3, the box edges of the used axes are finite
/// and > 0, x holds dim values per particle and N < 2^32. `who` names the caller in the message.
void checkPointSet(const PointSet& points, const char* who);

/// Particles sorted into a grid of cells. Every cell edge is >= the minimum edge asked for, so two
/// particles closer than that edge (minimum image on periodic axes) lie in the same or in adjacent
/// cells. Slots are the particles in cell order; cell c holds slots [cellStart[c], cellStart[c+1]).
struct CellGrid {
    int dim = 3;
    std::array<std::uint32_t, 3> cells{1, 1, 1};     ///< cells per axis (1 on unused axes)
    std::array<bool, 3> periodic{true, true, true};  ///< as in the PointSet
    std::array<Real, 3> box{1, 1, 1};                ///< [m] box edge per axis
    std::array<Real, 3> halfBox{};                   ///< [m] box/2 on periodic axes, +infinity on the others
    std::vector<std::uint32_t> cellStart;            ///< cellCount() + 1 entries
    std::vector<std::uint32_t> particle;             ///< slot -> original particle index
    std::vector<Real> x;  ///< [m] positions by slot (dim per slot), wrapped into [0, box) on periodic axes

    std::size_t cellCount() const noexcept { return cellStart.empty() ? 0 : cellStart.size() - 1; }

    /// Minimum image of a coordinate difference [m] of two wrapped positions (|dx| < box).
    Real minimumImage(Real dx, int axis) const noexcept {
        const auto a = static_cast<std::size_t>(axis);
        if (dx > halfBox[a]) return dx - box[a];
        if (dx < -halfBox[a]) return dx + box[a];
        return dx;
    }
};

/// Bins `points` into cells of edge >= minCellEdge [m] on every used axis. When that would give
/// more than maxCells cells (tiny particles in a big box), the cells are made larger (still a valid
/// grid, only slower). On non-periodic axes the grid spans [0, box) and particles outside are put
/// into the end cells. O(N + cells). Precondition: checkPointSet(points) passed, minCellEdge > 0.
CellGrid buildCellGrid(const PointSet& points, Real minCellEdge, std::size_t maxCells);

/// Calls fn(cellA, cellB) once for every unordered pair of adjacent non-empty cells with
/// cellB > cellA, and fn(c, c) once for every non-empty cell c. "Adjacent" includes wrapping on
/// periodic axes; with 1 or 2 cells on a periodic axis the wrapped neighbours coincide and are
/// visited once only, so every pair of particles within the cell edge is seen exactly once.
template <class Fn>
void forEachCellPair(const CellGrid& grid, Fn&& fn) {
    // Distinct neighbour offsets per axis: {-1, 0, 1}; a periodic axis with 2 cells has only one
    // neighbour ({0, 1}), with 1 cell none ({0}); unused axes {0}.
    std::array<std::array<int, 3>, 3> offsets{};
    std::array<int, 3> offsetCount{};
    for (int d = 0; d < 3; ++d) {
        const auto a = static_cast<std::size_t>(d);
        const std::uint32_t n = grid.cells[a];
        if (d >= grid.dim || n == 1) {
            offsets[a] = {0, 0, 0};
            offsetCount[a] = 1;
        } else if (grid.periodic[a] && n == 2) {
            offsets[a] = {0, 1, 0};
            offsetCount[a] = 2;
        } else {
            offsets[a] = {-1, 0, 1};
            offsetCount[a] = 3;
        }
    }
    const auto nx = static_cast<int>(grid.cells[0]);
    const auto ny = static_cast<int>(grid.cells[1]);
    const auto nz = static_cast<int>(grid.cells[2]);
    // Wraps (periodic) or rejects (-1) a neighbour cell coordinate.
    auto neighbour = [&grid](int c, int n, std::size_t axis) {
        if (c >= 0 && c < n) return c;
        if (!grid.periodic[axis]) return -1;
        return c < 0 ? c + n : c - n;
    };
    // Fast path for cells away from the box faces when every used axis has >= 3 cells: the
    // neighbours with a larger index are at fixed index offsets (13 in 3D, 4 in 2D).
    bool threeOrMore = true;
    for (int d = 0; d < grid.dim; ++d)
        threeOrMore = threeOrMore && offsetCount[static_cast<std::size_t>(d)] == 3;
    std::array<int, 13> forward{};
    std::size_t forwardCount = 0;
    if (threeOrMore) {
        for (int iz = 0; iz < offsetCount[2]; ++iz)
            for (int iy = 0; iy < offsetCount[1]; ++iy)
                for (int ix = 0; ix < offsetCount[0]; ++ix) {
                    const int oz = offsets[2][static_cast<std::size_t>(iz)];
                    const int oy = offsets[1][static_cast<std::size_t>(iy)];
                    const int ox = offsets[0][static_cast<std::size_t>(ix)];
                    const int delta = (oz * ny + oy) * nx + ox;  // index offset of the neighbour
                    if (delta > 0) forward[forwardCount++] = delta;
                }
    }
    auto inside = [](int c, int n, int count) { return count == 1 || (c >= 1 && c <= n - 2); };
    auto nonEmpty = [&grid](std::uint32_t c) { return grid.cellStart[c] != grid.cellStart[c + 1]; };
    for (int cz = 0; cz < nz; ++cz) {
        for (int cy = 0; cy < ny; ++cy) {
            for (int cx = 0; cx < nx; ++cx) {
                const auto cell = static_cast<std::uint32_t>((cz * ny + cy) * nx + cx);
                if (!nonEmpty(cell)) continue;  // empty: no pairs
                fn(cell, cell);
                if (threeOrMore && inside(cx, nx, offsetCount[0]) && inside(cy, ny, offsetCount[1]) &&
                    inside(cz, nz, offsetCount[2])) {
                    for (std::size_t k = 0; k < forwardCount; ++k) {
                        const auto other = static_cast<std::uint32_t>(static_cast<int>(cell) + forward[k]);
                        if (nonEmpty(other)) fn(cell, other);
                    }
                    continue;
                }
                for (int iz = 0; iz < offsetCount[2]; ++iz) {
                    const int z = neighbour(cz + offsets[2][static_cast<std::size_t>(iz)], nz, 2);
                    if (z < 0) continue;
                    for (int iy = 0; iy < offsetCount[1]; ++iy) {
                        const int y = neighbour(cy + offsets[1][static_cast<std::size_t>(iy)], ny, 1);
                        if (y < 0) continue;
                        for (int ix = 0; ix < offsetCount[0]; ++ix) {
                            const int x = neighbour(cx + offsets[0][static_cast<std::size_t>(ix)], nx, 0);
                            if (x < 0) continue;
                            const auto other = static_cast<std::uint32_t>((z * ny + y) * nx + x);
                            if (other > cell && nonEmpty(other)) fn(cell, other);
                        }
                    }
                }
            }
        }
    }
}

/// Calls fn(a, b, distance2) once for every unordered pair of slots a, b in the same or adjacent
/// cells, with their squared minimum-image centre distance [m^2]; the callers filter by distance.
template <int D, class Fn>
void forEachNearPair(const CellGrid& grid, Fn&& fn) {
    const Real* x = grid.x.data();
    forEachCellPair(grid, [&](std::uint32_t cellA, std::uint32_t cellB) {
        const std::uint32_t aEnd = grid.cellStart[cellA + 1];
        const std::uint32_t bBegin = grid.cellStart[cellB];
        const std::uint32_t bEnd = grid.cellStart[cellB + 1];
        for (std::uint32_t a = grid.cellStart[cellA]; a < aEnd; ++a) {
            const Real* xa = x + std::size_t{a} * D;
            for (std::uint32_t b = (cellA == cellB) ? a + 1 : bBegin; b < bEnd; ++b) {
                const Real* xb = x + std::size_t{b} * D;
                Real distance2 = 0;  // [m^2]
                for (int d = 0; d < D; ++d) {
                    const Real dx = grid.minimumImage(xb[d] - xa[d], d);
                    distance2 += dx * dx;
                }
                fn(a, b, distance2);
            }
        }
    });
}

}  // namespace granulab::analysis
