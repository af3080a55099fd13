// SPDX-License-Identifier: MIT
// The grid of rectangular test areas of the DEM analyses (gc2d spec section 7 items 6-10,
// "overlapping areas allowed"): area (i, j) is [x0 + i sx, x0 + i sx + w) x [y0 + j sy, y0 + j sy + h)
// with the flat index k = j nx + i (x fastest). Steps smaller than the size give overlapping areas.
// Also the membership lists (which grains belong to which area) that make the analyses
// O(N x overlap) instead of O(N x areas).
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

#include "core/types.hpp"

namespace granulab::analysis {

struct TestAreaGrid {
    Real x0 = 0, y0 = 0;  ///< [m] lower-left corner of area (0, 0)
    Real w = 1, h = 1;    ///< [m] size of every area
    Real sx = 1, sy = 1;  ///< [m] step between neighbouring areas (<= size: overlapping)
    std::size_t nx = 1, ny = 1;

    std::size_t count() const noexcept { return nx * ny; }
    std::size_t index(std::size_t i, std::size_t j) const noexcept { return j * nx + i; }
    Real left(std::size_t i) const noexcept { return x0 + static_cast<Real>(i) * sx; }
    Real bottom(std::size_t j) const noexcept { return y0 + static_cast<Real>(j) * sy; }
    /// Centre of area k [m].
    Vec2 centre(std::size_t k) const noexcept { return {left(k % nx) + 0.5 * w, bottom(k / nx) + 0.5 * h}; }
    Real area() const noexcept { return w * h; }  ///< [m^2]
};

/// The grid that covers the box [xmin, xmax] x [ymin, ymax] [m] with areas of w x h [m] at steps
/// sx, sy [m], starting at (xmin, ymin): nx = 1 + ceil((xmax - xmin - w) / sx) (at least 1), so
/// the last column may reach past xmax; likewise ny. Throws std::invalid_argument unless the box
/// is non-empty and w, h, sx, sy > 0 are finite.
TestAreaGrid coveringGrid(Real xmin, Real ymin, Real xmax, Real ymax, Real w, Real h, Real sx, Real sy);

/// Throws std::invalid_argument unless the grid has finite w, h, sx, sy > 0 and nx, ny >= 1.
void checkGrid(const TestAreaGrid& grid, const char* who);

/// Members of every area as a compressed list: area k holds items[start[k] .. start[k + 1]).
struct AreaMembers {
    std::vector<std::size_t> start;  ///< count() + 1 entries
    std::vector<std::size_t> items;  ///< item indices, ascending within each area
};

/// Item n (of `count`) belongs to every area whose rectangle overlaps the item's box
/// [lo.x, hi.x] x [lo.y, hi.y] (open overlap; a point box lo = hi is a member of the areas whose
/// half-open rectangle contains it). `box(n, lo, hi)` fills the box; returning false skips the
/// item. Cost O(count + pairs).
AreaMembers areaMembers(const TestAreaGrid& grid, std::size_t count,
                        const std::function<bool(std::size_t, Vec2&, Vec2&)>& box);

}  // namespace granulab::analysis
