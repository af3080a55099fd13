// SPDX-License-Identifier: MIT
// Stateless convex-polygon geometry (gc2d spec sections 2.1-2.2, 3.1 and erratum 6 of section
// 12): mass properties, shape checks with the offending corner, and the overlap of two convex
// polygons (area, boundary crossing points c1 and c2, contact point and normal).
// Polygons are counter-clockwise corner lists in one frame.
#pragma once
#include <string>
#include <vector>

#include "core/types.hpp"

namespace granulab::geom {

/// Area [m^2], centroid [m] and polar moment of area about the centroid [m^4] (multiply by the
/// areal density for mass [kg] and moment of inertia [kg m^2]); gc2d Eq. 2.10-2.12.
struct PolygonMass {
    Real area = 0;
    Vec2 centroid;
    Real secondMoment = 0;
};
PolygonMass polygonMass(const std::vector<Vec2>& ccw) noexcept;

/// Largest circle about `centre` inside the convex counter-clockwise polygon: the distance to the
/// nearest edge line [m] (edges of zero length are skipped; +inf without any edge).
Real inradiusAbout(const std::vector<Vec2>& ccw, Vec2 centre) noexcept;

/// First problem of a corner list that is not a strictly convex, counter-clockwise, simple
/// polygon: "" if fine; `corner` is the index of the offending corner.
struct ShapeProblem {
    std::string what;  ///< "fewer than 3 corners" | "clockwise" | "collinear" | "non-convex" |
                       ///< "self-intersecting" | "duplicate"
    int corner = -1;
    bool ok() const noexcept { return what.empty(); }
};
ShapeProblem checkConvexPolygon(const std::vector<Vec2>& corners) noexcept;

/// Overlap of two convex counter-clockwise polygons i and j (gc2d spec section 3.1).
struct PolygonOverlap {
    bool overlapping = false;
    Real area = 0;              ///< [m^2] area A of the overlap polygon
    Vec2 c1, c2;                ///< [m] boundary crossing points; contact line c1c2
    Vec2 point;                 ///< [m] contact point (c1 + c2)/2
    Vec2 normal;                ///< unit, perpendicular to c1c2, pushes i away from j
    int crossings = 0;          ///< boundary crossings found (2 normally; more: the farthest pair is used)
    Vec2 pull;                  ///< [m] -dA/dx_i: sum of -n_e L_e over the overlap edges on i's boundary
    Real twist = 0;             ///< [m^2] their moment about `point` (see geom::AreaContact)
    std::vector<Vec2> polygon;  ///< the overlap polygon (counter-clockwise)
};
PolygonOverlap convexOverlap(const std::vector<Vec2>& i, const std::vector<Vec2>& j);

/// Reusable buffers of the clipping, so that repeated calls do not allocate.
struct ClipScratch {
    struct Vertex {
        Vec2 p;
        bool crossing;  ///< lies on both boundaries
        bool edgeOnI;   ///< the edge from this vertex to the next lies on i's boundary
    };
    std::vector<Vertex> poly, next;
    std::vector<Vec2> corners, crossings;
};
/// convexOverlap on corner arrays with caller-owned buffers (the overlap polygon is left in
/// scratch.corners); `polygon` of the result stays empty.
PolygonOverlap convexOverlap(const Vec2* i, int ni, const Vec2* j, int nj, ClipScratch& scratch);

}  // namespace granulab::geom
