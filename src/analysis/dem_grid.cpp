// SPDX-License-Identifier: MIT
// Test-area grid of the DEM analyses (gc2d spec section 7 items 6-10) and its membership lists.
#include "analysis/dem_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granulab::analysis {

namespace {

bool positiveFinite(Real v) {
    return std::isfinite(v) && v > 0;
}

/// Index range [first, last] of the areas along one axis that overlap [lo, hi]; empty when
/// first > last. Origin o, size s, step d, n areas.
void axisRange(Real lo, Real hi, Real o, Real s, Real d, std::size_t n, long& first, long& last) {
    const long maxIndex = static_cast<long>(n) - 1;
    if (lo == hi) {  // point: o + i d <= p < o + i d + s
        first = static_cast<long>(std::floor((lo - o - s) / d)) + 1;
        last = static_cast<long>(std::floor((lo - o) / d));
        // Rounding at the edges: keep only areas that really contain the point.
        while (first <= last && !(o + static_cast<Real>(first) * d + s > lo)) ++first;
        while (last >= first && !(o + static_cast<Real>(last) * d <= lo)) --last;
    } else {  // open overlap: o + i d < hi and o + i d + s > lo
        first = static_cast<long>(std::floor((lo - o - s) / d)) + 1;
        last = static_cast<long>(std::ceil((hi - o) / d)) - 1;
    }
    first = std::max(first, 0L);
    last = std::min(last, maxIndex);
}

}  // namespace

void checkGrid(const TestAreaGrid& g, const char* who) {
    if (!positiveFinite(g.w) || !positiveFinite(g.h) || !positiveFinite(g.sx) || !positiveFinite(g.sy) ||
        !std::isfinite(g.x0) || !std::isfinite(g.y0) || g.nx == 0 || g.ny == 0)
        throw std::invalid_argument(std::string(who) +
                                    ": test-area grid needs finite w, h, sx, sy > 0 and nx, ny >= 1");
}

TestAreaGrid coveringGrid(Real xmin, Real ymin, Real xmax, Real ymax, Real w, Real h, Real sx, Real sy) {
    if (!(std::isfinite(xmin) && std::isfinite(xmax) && std::isfinite(ymin) && std::isfinite(ymax)) ||
        !(xmax > xmin) || !(ymax > ymin))
        throw std::invalid_argument("coveringGrid: the box must be finite and non-empty");
    TestAreaGrid g{xmin, ymin, w, h, sx, sy, 1, 1};
    checkGrid(g, "coveringGrid");
    const auto steps = [](Real extent, Real size, Real step) {
        if (extent <= size) return std::size_t{1};
        return 1 + static_cast<std::size_t>(std::ceil((extent - size) / step - 1e-9));
    };
    g.nx = steps(xmax - xmin, w, sx);
    g.ny = steps(ymax - ymin, h, sy);
    return g;
}

AreaMembers areaMembers(const TestAreaGrid& grid, std::size_t count,
                        const std::function<bool(std::size_t, Vec2&, Vec2&)>& box) {
    checkGrid(grid, "areaMembers");
    struct Range {
        long i0, i1, j0, j1;
    };
    std::vector<Range> ranges(count, Range{0, -1, 0, -1});
    AreaMembers m;
    m.start.assign(grid.count() + 1, 0);
    for (std::size_t n = 0; n < count; ++n) {
        Vec2 lo, hi;
        if (!box(n, lo, hi)) continue;
        Range& r = ranges[n];
        axisRange(lo.x, hi.x, grid.x0, grid.w, grid.sx, grid.nx, r.i0, r.i1);
        axisRange(lo.y, hi.y, grid.y0, grid.h, grid.sy, grid.ny, r.j0, r.j1);
        for (long j = r.j0; j <= r.j1; ++j)
            for (long i = r.i0; i <= r.i1; ++i)
                ++m.start[grid.index(static_cast<std::size_t>(i), static_cast<std::size_t>(j)) + 1];
    }
    for (std::size_t k = 0; k < grid.count(); ++k) m.start[k + 1] += m.start[k];
    m.items.resize(m.start.back());
    std::vector<std::size_t> fill(m.start.begin(), m.start.end() - 1);
    for (std::size_t n = 0; n < count; ++n) {
        const Range& r = ranges[n];
        for (long j = r.j0; j <= r.j1; ++j)
            for (long i = r.i0; i <= r.i1; ++i)
                m.items[fill[grid.index(static_cast<std::size_t>(i), static_cast<std::size_t>(j))]++] = n;
    }
    return m;
}

}  // namespace granulab::analysis
