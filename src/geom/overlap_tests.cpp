// SPDX-License-Identifier: MIT
// Start-overlap tests of polygons against disks and wall segments (geom/overlap_tests.hpp).
#include "geom/overlap_tests.hpp"

#include <algorithm>
#include <cmath>

#include "geom/segment.hpp"

namespace granulab::geom {

Real diskPolygonOverlap(Vec2 c, Real r, const std::vector<Vec2>& poly) {
    const std::size_t n = poly.size();
    bool inside = true;
    Real dist = 1e300;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec2 a = poly[k], b = poly[(k + 1) % n];
        inside = inside && cross(b - a, c - a) > 0;
        const Vec2 q = a + (b - a) * closestParameter(a, b, c);
        dist = std::min(dist, norm(c - q));
    }
    return inside ? r + dist : r - dist;
}

bool segmentEntersPolygon(Vec2 a, Vec2 b, const std::vector<Vec2>& poly) {
    const std::size_t n = poly.size();
    Real scale = 0;
    for (const Vec2& p : poly) scale = std::max(scale, norm(p - poly[0]));
    const Real tol = 1e-12 * scale;  // an edge lying on the wall is touching, not entering
    Real t0 = 0, t1 = 1;             // Cyrus-Beck: the part of [a, b] strictly inside every edge
    for (std::size_t k = 0; k < n; ++k) {
        const Vec2 p = poly[k], e = poly[(k + 1) % n] - p;
        const Real len = norm(e);
        if (!(len > 0)) continue;
        const Vec2 inward = perp(e) / len;
        const Real fa = dot(inward, a - p) - tol, fb = dot(inward, b - p) - tol;
        if (fa <= 0 && fb <= 0) return false;
        if (fa > 0 && fb > 0) continue;
        const Real t = fa / (fa - fb);
        if (fa < fb)
            t0 = std::max(t0, t);  // entering this half-plane
        else
            t1 = std::min(t1, t);  // leaving it
        if (t1 <= t0) return false;
    }
    return t1 - t0 > 1e-12;
}

}  // namespace granulab::geom
