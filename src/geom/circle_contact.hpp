// SPDX-License-Identifier: MIT
// Overlap-area contacts with a disk as the first body (gc2d spec section 3.1, Fig. 2.4, and
// erratum 6 of section 12): disk-disk (closed-form lens) and disk-convex polygon (exact area of
// the disk clipped by the polygon). Stateless, allocation-free and noexcept: force-loop kernels.
//
// Conventions shared by both functions (see AreaContact):
// * area [m^2] is exact up to rounding; tiny overlaps are evaluated without cancellation
//   (a circular segment of sagitta k <= 0.1 r by a series in k/r, larger ones by atan2 and
//   x - sin x, itself a series below x = 1).
// * the normal pushes the disk (first body) away from the second body; c1, c2 are ordered so that
//   c2 - c1 points along perp(normal) (normal turned +90 degrees).
// * touching is true exactly when area > 0; otherwise the result is value-initialised.
#pragma once
#include "core/types.hpp"
#include "geom/area_contact.hpp"

namespace granulab::geom {

/// Both fill AreaContact::pull and twist (the exact area gradient of the disk): the lens L_c n,
/// the disk-polygon G below with its moment about the contact point; 0 under containment.

/// Lens contact of disk i (centre ci [m], radius ri [m]) with disk j (cj, rj).
/// Partial overlap: c1, c2 = the two circle intersection points, normal = (ci - cj)/|ci - cj|.
/// One disk inside the other: area = pi r_min^2, c1 = c2 = point = the point of the smaller
/// circle on the line of centres on the side away from the larger centre (where the two circles
/// touch internally at the onset of containment), normal = (ci - cj)/|ci - cj|, or +x when the
/// centres coincide exactly.
AreaContact circleCircleContact(Vec2 ci, Real ri, Vec2 cj, Real rj) noexcept;

/// Contact of the disk (centre [m], radius r [m]) with the convex counter-clockwise polygon
/// corners[0..n) (world frame [m]); O(n).
/// Crossings: c1, c2 = the two points where the circle crosses the polygon boundary; with more
/// than two crossings the farthest pair (erratum 6).
/// Normal: perpendicular to c1c2, oriented along G = -dA/d(centre), the direction in which a
/// translation of the disk shrinks the overlap fastest (G = sum over the overlap's circular arcs
/// of perp(arc end - arc start)). With two crossings G is itself perpendicular to c1c2, so this
/// is the natural "from the polygon side towards the circle side" rule, and it stays right when
/// the centre lies inside the polygon (then the disk is pushed out through the cut-off cap, never
/// deeper in). If G vanishes (an overlap symmetric about the centre, e.g. a strip through it)
/// the orientation falls back to centre - mean of the polygon corners.
/// Containment: disk inside the polygon: area = pi r^2, c1 = c2 = closest boundary point,
/// normal = outward normal of the nearest edge (continuous with the partial case, where the
/// disk leaves through that edge). Polygon inside the disk: area = polygon area,
/// c1 = c2 = polygon centroid, normal = (centre - centroid)/|.|, or +x if they coincide.
AreaContact circlePolygonContact(Vec2 centre, Real r, const Vec2* corners, int n) noexcept;

}  // namespace granulab::geom
