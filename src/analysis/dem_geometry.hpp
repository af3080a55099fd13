// SPDX-License-Identifier: MIT
// Geometry the DEM pile analyses share (gc2d spec section 7 items 1-5, 11): a test rectangle, the
// reach of a grain along a direction, grain lookup by id, and the combined geometry of a set of
// walls (length, direction, inward normal).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// Axis-parallel test rectangle [m] (closed: points on the edge are inside).
struct Rect {
    Real xMin = 0, xMax = 0, yMin = 0, yMax = 0;  ///< [m]
    bool contains(Real x, Real y) const noexcept { return x >= xMin && x <= xMax && y >= yMin && y <= yMax; }
};

/// Throws std::invalid_argument naming `who` unless xMin <= xMax and yMin <= yMax (all finite).
void checkRect(const Rect& r, const std::string& who);

/// Largest dot(p, dir) [m] over the points p of grain i: the centre plus radius |dir| for a disk,
/// the largest corner projection for a polygon. With dir = (0, 1): the grain's top.
Real grainReach(const GrainFrame& grains, std::size_t i, Vec2 dir);

/// Index of every grain id of `grains` (ids are unique in a snapshot).
std::unordered_map<std::int64_t, std::size_t> indexById(const GrainFrame& grains);

/// The segments of a set of walls seen as one wall.
struct WallGeometry {
    Real length = 0;  ///< [m] total length of the segments
    std::size_t segments = 0;
    bool straight = false;  ///< all segments parallel (|sin| < 1e-9 between their directions)
    /// Unit direction of a straight wall, signed so that its largest component is positive (a floor
    /// runs along +x, a side wall along +y); NaN for a bent wall.
    Vec2 tangent{};
    Real sMin = 0, sMax = 0;  ///< [m] range of dot(end point, tangent) (straight walls)
    Real offset = 0;          ///< [m] dot(end point, perp(tangent)) of the first end point
};

/// Geometry of the segments of `walls` in `segments`. Throws std::invalid_argument (naming `who`)
/// when `walls` is empty, a wall has no segment, or the total length is 0.
WallGeometry wallGeometry(const WallSegments& segments, const std::vector<std::int32_t>& walls,
                          const std::string& who);

/// True when wall index w is one of `walls`.
bool isSelectedWall(const std::vector<std::int32_t>& walls, std::int32_t w) noexcept;

/// Unit normal of a straight wall pointing toward the grains: +-perp(tangent), signed so that it
/// agrees with minus the sum of the contact normals of the wall's contacts (n points from the grain
/// toward the wall). `hint` (non-zero) overrides the contacts; without contacts and hint the
/// result is perp(tangent).
Vec2 inwardNormal(const WallGeometry& geometry, const ContactFrame& contacts,
                  const std::vector<std::int32_t>& walls, Vec2 hint = {});

}  // namespace granulab::analysis
