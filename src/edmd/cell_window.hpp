// SPDX-License-Identifier: MIT
// A box of cells of the event-driven engine's grid (edmd spec sections 3.1 and 3.6): the cells
// one rank of the parallel engine keeps tables for (its own block and the halo around it), so
// that a rank's memory grows with N/P plus its halo, not with the whole grid. A window wraps
// around periodic axes and is cut at walls; an axis it would cover entirely is taken whole. A
// serial engine's window is the whole grid. Cells are named by their grid coordinates
// everywhere; only per-cell tables use window indices (x fastest).
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace granulab::edmd {

struct CellWindow {
    static constexpr std::uint32_t kOutside = 0xFFFFFFFFu;  ///< index of a cell outside the window
    std::array<int, 3> cells{1, 1, 1};                      ///< cells per axis of the whole grid
    std::array<int, 3> origin{0, 0, 0};  ///< grid coordinate of the window's first cell per axis
    std::array<int, 3> extent{1, 1, 1};  ///< window cells per axis (cells[d]: the whole axis, origin 0)

    /// The whole grid.
    static CellWindow whole(const std::array<int, 3>& cells) noexcept { return {cells, {0, 0, 0}, cells}; }

    /// The box of grid coordinates lo <= c < hi (axes >= D ignored) grown by `margin` cells on
    /// every side: wrapped on periodic axes, cut at walls (non-periodic axes). An axis that the
    /// grown box covers (or would wrap onto itself) is whole. A box empty on any axis gives an
    /// empty window (count() == 0).
    template <int D>
    static CellWindow around(const std::array<int, 3>& cells, const std::array<bool, 3>& periodic,
                             const std::array<int, 3>& lo, const std::array<int, 3>& hi,
                             int margin) noexcept {
        CellWindow w = whole(cells);
        for (int d = 0; d < D; ++d) {
            if (hi[d] <= lo[d]) {
                w.extent = {0, 0, 0};
                return w;
            }
            const int first = lo[d] - margin, end = hi[d] + margin;
            if (!periodic[d]) {
                w.origin[d] = std::max(first, 0);
                w.extent[d] = std::min(end, cells[d]) - w.origin[d];
            } else if (end - first < cells[d]) {
                w.origin[d] = (first % cells[d] + cells[d]) % cells[d];
                w.extent[d] = end - first;
            }
        }
        return w;
    }

    /// Cells in the window.
    std::size_t count() const noexcept {
        return static_cast<std::size_t>(extent[0]) * static_cast<std::size_t>(extent[1]) *
               static_cast<std::size_t>(extent[2]);
    }
    /// Window coordinate along axis d of grid coordinate c (0 <= c < cells[d]); -1 outside.
    int local(int d, int c) const noexcept {
        int k = c - origin[d];
        if (k < 0) k += cells[d];
        return k < extent[d] ? k : -1;
    }
    /// Grid coordinate along axis d of window coordinate 0 <= k < extent[d].
    int grid(int d, int k) const noexcept {
        const int c = origin[d] + k;
        return c >= cells[d] ? c - cells[d] : c;
    }
    /// Window index of the cell with grid coordinates c[0..D), or kOutside.
    template <int D, class Coords>
    std::uint32_t indexOf(const Coords& c) const noexcept {
        std::uint32_t index = 0, stride = 1;
        for (int d = 0; d < D; ++d) {
            const int k = local(d, static_cast<int>(c[d]));
            if (k < 0) return kOutside;
            index += stride * static_cast<std::uint32_t>(k);
            stride *= static_cast<std::uint32_t>(extent[d]);
        }
        return index;
    }
    /// Grid coordinates of the cell with window index `index` < count() (axes >= D: 0).
    template <int D>
    std::array<int, 3> coordsOf(std::uint32_t index) const noexcept {
        std::array<int, 3> c{0, 0, 0};
        for (int d = 0; d < D; ++d) {
            c[d] = grid(d, static_cast<int>(index % static_cast<std::uint32_t>(extent[d])));
            index /= static_cast<std::uint32_t>(extent[d]);
        }
        return c;
    }
    /// Calls visit(grid coordinates) for every cell of the 3^D block around the cell with grid
    /// coordinates c[0..D) on the whole grid: periodic axes wrap, walls cut the block.
    template <int D, class Coords, class Visit>
    void forEachInGridAround(const Coords& c, const std::array<bool, 3>& periodic, Visit&& visit) const {
        const int reach[3] = {1, D > 1 ? 1 : 0, D > 2 ? 1 : 0};
        for (int dz = -reach[2]; dz <= reach[2]; ++dz)
            for (int dy = -reach[1]; dy <= reach[1]; ++dy)
                for (int dx = -reach[0]; dx <= reach[0]; ++dx) {
                    const int delta[3] = {dx, dy, dz};
                    std::array<int, 3> k{0, 0, 0};
                    bool inside = true;
                    for (int d = 0; d < D && inside; ++d) {
                        k[d] = static_cast<int>(c[d]) + delta[d];
                        if (k[d] < 0 || k[d] >= cells[d]) {
                            inside = periodic[d];
                            k[d] = (k[d] + cells[d]) % cells[d];
                        }
                    }
                    if (inside) visit(k);
                }
    }
    /// Calls visit(window index) for the cells of that block that lie in the window.
    template <int D, class Coords, class Visit>
    void forEachAround(const Coords& c, const std::array<bool, 3>& periodic, Visit&& visit) const {
        forEachInGridAround<D>(c, periodic, [&](const std::array<int, 3>& k) {
            const std::uint32_t index = indexOf<D>(k);
            if (index != kOutside) visit(index);
        });
    }
};

}  // namespace granulab::edmd
