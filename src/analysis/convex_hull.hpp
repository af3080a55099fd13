// SPDX-License-Identifier: MIT
// Area of the convex hull of a point set, as the DEM analyses need it (gc2d spec section 7:
// A_k of Eq. 2.45, V of Eq. 2.52).
#pragma once
#include <vector>

#include "core/types.hpp"

namespace granulab::analysis {

/// Area [m^2] of the convex hull of `points` [m] (Andrew's monotone chain, O(n log n)); 0 for
/// fewer than 3 points or collinear points. Reorders `points` and removes points inside the
/// octagon of the extreme points first (Akl-Toussaint), so dense sets cost ~O(n).
Real convexHullArea(std::vector<Vec2>& points);

}  // namespace granulab::analysis
