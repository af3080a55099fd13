// SPDX-License-Identifier: MIT
// Stateless disk-segment geometry (DESIGN.md "geom/ segment tests"): closest point, and the
// contact of a disk with one segment of a polyline, claiming shared corners exactly once.
#pragma once
#include "core/types.hpp"

namespace granulab::geom {

/// Parameter s in [0,1] of the point of segment [a,b] closest to p.
inline Real closestParameter(Vec2 a, Vec2 b, Vec2 p) noexcept {
    const Vec2 d = b - a;
    const Real len2 = norm2(d);
    if (len2 <= 0) return 0;
    Real s = dot(p - a, d) / len2;
    return s < 0 ? 0 : (s > 1 ? 1 : s);
}

/// Contact of a disk with a wall segment: normal points from the wall to the disk centre.
struct SegmentContact {
    bool touching = false;
    Real overlap = 0;  ///< [m] r - distance (> 0 when touching)
    Vec2 normal;       ///< unit, wall -> disk centre
    Vec2 point;        ///< [m] closest point on the segment
};

/// Disk (centre c, radius r) against segment [a,b] of a polyline. A corner shared by two
/// segments belongs to the segment that starts there, and only when the centre also lies beyond
/// the end of the previous segment (the corner's Voronoi region); a shared end corner is never
/// claimed. So a disk at a convex joint gets one contact, and one in a concave joint one per
/// face. `reach` > 0 extends the test to near misses (broad-phase candidates).
inline SegmentContact diskSegmentContact(Vec2 c, Real r, Vec2 a, Vec2 b, bool startShared, bool endShared,
                                         Vec2 prevDirection, Real reach = 0) noexcept {
    SegmentContact out;
    const Vec2 d = b - a;
    const Real len2 = norm2(d);
    const Real proj = dot(c - a, d);
    Vec2 closest;
    if (proj <= 0) {
        if (startShared && dot(c - a, prevDirection) < 0) return out;  // previous face owns it
        closest = a;
    } else if (proj >= len2) {
        if (endShared) return out;  // the next segment's start claims this corner
        closest = b;
    } else {
        closest = a + d * (proj / len2);
    }
    const Vec2 delta = c - closest;
    const Real dist2 = norm2(delta);
    const Real limit = r + reach;
    if (dist2 >= limit * limit) return out;
    const Real dist = std::sqrt(dist2);
    out.touching = true;
    out.overlap = r - dist;
    out.point = closest;
    if (dist > 0) {
        out.normal = delta / dist;
    } else {
        const Real len = std::sqrt(len2);
        out.normal = perp(d) / len;  // centre exactly on the wall: push to the left side
    }
    return out;
}

/// Disk (centre c, radius r) against a convex polygon body (corners counter-clockwise): one
/// contact with the whole body, whatever corner or edge is nearest (gc2d spec 6.1: a wall is an
/// immovable convex particle). Outside: the closest boundary point; centre inside: the nearest
/// edge, overlap = r + depth of the centre. `reach` as in diskSegmentContact.
inline SegmentContact diskConvexContact(Vec2 c, Real r, const Vec2* corners, int n, Real reach = 0) noexcept {
    SegmentContact out;
    Real maxOut = -1e300;  // largest signed distance of c outside an edge line [m]
    int edge = 0;
    for (int k = 0; k < n; ++k) {
        const Vec2 a = corners[k], b = corners[(k + 1) % n];
        const Vec2 d = b - a;
        const Real len = norm(d);
        if (!(len > 0)) continue;
        const Real outside = -cross(d, c - a) / len;  // > 0 on the right of a -> b: outside a ccw polygon
        if (outside > maxOut) {
            maxOut = outside;
            edge = k;
        }
    }
    const Real limit = r + reach;
    if (maxOut <= 0) {  // centre inside: push out through the nearest edge
        const Vec2 a = corners[edge], b = corners[(edge + 1) % n];
        const Vec2 d = b - a;
        out.touching = true;
        out.overlap = r - maxOut;
        out.normal = Vec2{d.y, -d.x} / norm(d);
        out.point = c - out.normal * maxOut;
        return out;
    }
    if (maxOut >= limit) return out;  // separated by an edge line: no contact
    Real best2 = 1e300;
    Vec2 closest;
    for (int k = 0; k < n; ++k) {
        const Vec2 a = corners[k], b = corners[(k + 1) % n];
        const Vec2 q = a + (b - a) * closestParameter(a, b, c);
        const Real d2 = norm2(c - q);
        if (d2 < best2) {
            best2 = d2;
            closest = q;
        }
    }
    if (best2 >= limit * limit) return out;
    const Real dist = std::sqrt(best2);
    out.touching = true;
    out.overlap = r - dist;
    out.point = closest;
    out.normal = (c - closest) / dist;  // dist >= maxOut > 0
    return out;
}

}  // namespace granulab::geom
