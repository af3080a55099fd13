// SPDX-License-Identifier: MIT
// Exact start-overlap tests of a convex polygon against a disk and a wall segment (gc2d spec
// section 2.3: particles must not overlap at start). Stateless; used by the dem scene set-up.
#pragma once
#include <vector>

#include "core/types.hpp"

namespace granulab::geom {

/// Depth [m] by which a disk (centre c, radius r) overlaps a convex counter-clockwise polygon:
/// r - distance to the boundary outside, r + distance to the boundary when c is inside; <= 0
/// when they do not overlap.
Real diskPolygonOverlap(Vec2 c, Real r, const std::vector<Vec2>& polygon);

/// Whether segment [a, b] enters the interior of a convex counter-clockwise polygon (a wall
/// crossing it or ending inside it). Touching an edge or a corner is not entering.
bool segmentEntersPolygon(Vec2 a, Vec2 b, const std::vector<Vec2>& polygon);

}  // namespace granulab::geom
