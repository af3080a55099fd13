// SPDX-License-Identifier: MIT
// Cell grid for the gas analyses (edmd spec section 5.2): a counting sort of the particles by
// cell, O(N + cells), with the positions copied in cell order so that the pair loops of the
// cluster search and of g(r) read memory sequentially.
#include "analysis/gas_cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace granulab::analysis {

void checkPointSet(const PointSet& points, const char* who) {
    const std::string prefix = std::string(who) + ": ";
    if (points.dim != 2 && points.dim != 3)
        throw std::invalid_argument(prefix + "dim must be 2 or 3, got " + std::to_string(points.dim));
    for (int d = 0; d < points.dim; ++d) {
        const Real edge = points.box[static_cast<std::size_t>(d)];
        if (!(edge > 0) || !std::isfinite(edge))
            throw std::invalid_argument(prefix + "box edges must be finite and > 0");
    }
    const std::size_t n = points.size();
    if (n >= std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument(prefix + "too many particles for 32-bit labels");
    if (points.x.size() != static_cast<std::size_t>(points.dim) * n)
        throw std::invalid_argument(prefix + "x must hold dim values per particle (" + std::to_string(n) +
                                    " radii, " + std::to_string(points.x.size()) + " coordinates)");
}

CellGrid buildCellGrid(const PointSet& points, Real minCellEdge, std::size_t maxCells) {
    const int dim = points.dim;
    const std::size_t n = points.size();
    CellGrid grid;
    grid.dim = dim;
    grid.periodic = points.periodic;
    grid.box = points.box;
    maxCells = std::max<std::size_t>(maxCells, 1);

    // Cells per axis: as many as fit with edge >= minCellEdge, then fewer if above maxCells.
    std::array<Real, 3> count{1, 1, 1};
    for (int d = 0; d < dim; ++d) {
        const auto a = static_cast<std::size_t>(d);
        count[a] = std::max<Real>(1, std::floor(std::min<Real>(points.box[a] / minCellEdge, 1e6)));
    }
    for (;;) {
        const Real total = count[0] * count[1] * count[2];
        if (total <= static_cast<Real>(maxCells)) break;
        const Real shrink = std::pow(total / static_cast<Real>(maxCells), 1.0 / dim) * 1.0001;
        for (int d = 0; d < dim; ++d) {
            const auto a = static_cast<std::size_t>(d);
            count[a] = std::max<Real>(1, std::floor(count[a] / shrink));
        }
    }
    std::array<Real, 3> inverseEdge{0, 0, 0};  // [1/m]
    for (int d = 0; d < 3; ++d) {
        const auto a = static_cast<std::size_t>(d);
        grid.cells[a] = static_cast<std::uint32_t>(count[a]);
        grid.halfBox[a] =
            (d < dim && points.periodic[a]) ? 0.5 * points.box[a] : std::numeric_limits<Real>::infinity();
        if (d < dim) inverseEdge[a] = count[a] / points.box[a];
    }
    const std::size_t cellTotal = std::size_t{grid.cells[0]} * grid.cells[1] * grid.cells[2];

    // Wrapped positions and cell of every particle (original order).
    std::vector<Real> wrapped(points.x);
    std::vector<std::uint32_t> cellOf(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t cell = 0;
        for (int d = dim - 1; d >= 0; --d) {
            const auto a = static_cast<std::size_t>(d);
            Real& xi = wrapped[i * static_cast<std::size_t>(dim) + a];
            if (points.periodic[a]) {
                xi -= points.box[a] * std::floor(xi / points.box[a]);
                if (xi >= points.box[a]) xi = 0;  // -tiny wraps to box after rounding
            }
            const Real c = std::clamp<Real>(std::floor(xi * inverseEdge[a]), 0, count[a] - 1);
            cell = cell * grid.cells[a] + static_cast<std::size_t>(c);
        }
        cellOf[i] = static_cast<std::uint32_t>(cell);
    }

    // Counting sort by cell; stable, so slots within a cell keep increasing particle indices.
    grid.cellStart.assign(cellTotal + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++grid.cellStart[cellOf[i] + 1];
    for (std::size_t c = 0; c < cellTotal; ++c) grid.cellStart[c + 1] += grid.cellStart[c];
    std::vector<std::uint32_t> next(grid.cellStart.begin(), grid.cellStart.end() - 1);
    grid.particle.resize(n);
    grid.x.resize(wrapped.size());
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t slot = next[cellOf[i]]++;
        grid.particle[slot] = static_cast<std::uint32_t>(i);
        for (int d = 0; d < dim; ++d) {
            const auto a = static_cast<std::size_t>(d);
            grid.x[std::size_t{slot} * static_cast<std::size_t>(dim) + a] =
                wrapped[i * static_cast<std::size_t>(dim) + a];
        }
    }
    return grid;
}

}  // namespace granulab::analysis
