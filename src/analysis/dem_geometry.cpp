// SPDX-License-Identifier: MIT
// Geometry the DEM pile analyses share (analysis/dem_geometry.hpp; gc2d spec section 7).
#include "analysis/dem_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace granulab::analysis {

void checkRect(const Rect& r, const std::string& who) {
    const bool finite =
        std::isfinite(r.xMin) && std::isfinite(r.xMax) && std::isfinite(r.yMin) && std::isfinite(r.yMax);
    if (!finite || r.xMin > r.xMax || r.yMin > r.yMax)
        throw std::invalid_argument(who + ": the rectangle needs finite xMin <= xMax and yMin <= yMax");
}

Real grainReach(const GrainFrame& grains, std::size_t i, Vec2 dir) {
    if (!grains.isPolygon(i)) return grains.x[i] * dir.x + grains.y[i] * dir.y + grains.radius[i] * norm(dir);
    Real best = -std::numeric_limits<Real>::infinity();
    for (std::size_t c = grains.cornerStart[i]; c < grains.cornerStart[i + 1]; ++c)
        best = std::max(best, dot(grains.corners[c], dir));
    return best;
}

std::unordered_map<std::int64_t, std::size_t> indexById(const GrainFrame& grains) {
    std::unordered_map<std::int64_t, std::size_t> index;
    index.reserve(grains.size());
    for (std::size_t i = 0; i < grains.size(); ++i) index.emplace(grains.id[i], i);
    return index;
}

bool isSelectedWall(const std::vector<std::int32_t>& walls, std::int32_t w) noexcept {
    return w >= 0 && std::find(walls.begin(), walls.end(), w) != walls.end();
}

WallGeometry wallGeometry(const WallSegments& segments, const std::vector<std::int32_t>& walls,
                          const std::string& who) {
    if (walls.empty()) throw std::invalid_argument(who + ": no wall index selected");
    WallGeometry g;
    std::vector<Vec2> directions;
    std::vector<std::size_t> used;
    for (std::int32_t w : walls) {
        std::size_t found = 0;
        for (std::size_t s = 0; s < segments.size(); ++s) {
            if (segments.wall[s] != w) continue;
            ++found;
            const Vec2 d = segments.b[s] - segments.a[s];
            const Real len = norm(d);  // [m]
            g.length += len;
            if (len > 0) {
                directions.push_back(d / len);
                used.push_back(s);
            }
        }
        if (found == 0)
            throw std::invalid_argument(who + ": wall " + std::to_string(w) +
                                        " has no segment in the snapshot");
        g.segments += found;
    }
    if (!(g.length > 0)) throw std::invalid_argument(who + ": the selected walls have zero length");
    g.straight = std::all_of(directions.begin(), directions.end(),
                             [&](Vec2 d) { return std::abs(cross(d, directions.front())) < 1e-9; });
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    if (!g.straight) {
        g.tangent = {nan, nan};
        g.sMin = g.sMax = g.offset = nan;
        return g;
    }
    Vec2 t = directions.front();
    if ((std::abs(t.x) >= std::abs(t.y) && t.x < 0) || (std::abs(t.y) > std::abs(t.x) && t.y < 0)) t = -t;
    g.tangent = t;
    g.sMin = std::numeric_limits<Real>::infinity();
    g.sMax = -g.sMin;
    for (std::size_t s : used)
        for (Vec2 p : {segments.a[s], segments.b[s]}) {
            g.sMin = std::min(g.sMin, dot(p, t));
            g.sMax = std::max(g.sMax, dot(p, t));
        }
    g.offset = dot(segments.a[used.front()], perp(t));
    return g;
}

Vec2 inwardNormal(const WallGeometry& geometry, const ContactFrame& contacts,
                  const std::vector<std::int32_t>& walls, Vec2 hint) {
    const Vec2 n = perp(geometry.tangent);
    Real vote = dot(hint, n);
    if (hint == Vec2{})
        for (std::size_t k = 0; k < contacts.size(); ++k)
            if (isSelectedWall(walls, contacts.wall[k])) vote -= contacts.nx[k] * n.x + contacts.ny[k] * n.y;
    return vote < 0 ? -n : n;
}

}  // namespace granulab::analysis
