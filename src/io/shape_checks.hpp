// SPDX-License-Identifier: MIT
// Validation of [[shape]] tables and of the particles and blocks that use them (gc2d spec
// sections 2.1-2.3; docs/scene-format.md "Shapes"), and the start-overlap tests of polygon
// particles against disks, polygons and walls. Part of the one validate() pass (io/validate.hpp).
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "model/generate.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

/// Shape definitions (names, kinds, ranges, modes, convexity), shape references of particles
/// and blocks with "did you mean", disk radii, the mass model of polygons, and the lattice
/// spacing of polygon blocks. A clockwise `polygon` corner list is not an error: the generator
/// reverses it, and a warning naming file:line is appended to `warnings`.
void checkShapes(const model::SceneDef& scene, Diagnostics& diags, std::vector<std::string>& warnings);

/// World corners [m] of particle p: position + R(angle) * body corners (counter-clockwise).
std::vector<Vec2> worldCorners(const model::InitialParticles& init, const model::InitialParticle& p);

/// Depth [m] by which a disk (centre c, radius r) overlaps a convex counter-clockwise polygon:
/// r - distance to the boundary outside, r + distance to the boundary when c is inside; <= 0
/// when they do not overlap.
Real diskPolygonOverlap(Vec2 c, Real r, const std::vector<Vec2>& polygon);

/// Whether segment [a, b] enters the interior of a convex counter-clockwise polygon (a wall
/// crossing it or ending inside it). Touching an edge or a corner is not entering.
bool segmentEntersPolygon(Vec2 a, Vec2 b, const std::vector<Vec2>& polygon);

}  // namespace granulab::io
