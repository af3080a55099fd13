// SPDX-License-Identifier: MIT
// Validation of [[shape]] tables and of the particles and blocks that use them (gc2d spec
// sections 2.1-2.3; docs/scene-format.md "Shapes"),. Part of the
// Def-level checks of the dem engine (io/validate_dem.hpp).
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

/// Shape definitions (names, kinds, ranges, modes, convexity), shape references of particles
/// and blocks with "did you mean", disk radii, the mass model of polygons, and the lattice
/// spacing of polygon blocks. A clockwise `polygon` corner list is not an error: the generator
/// reverses it, and a warning naming file:line is appended to `warnings`.
void checkShapes(const model::SceneDef& scene, Diagnostics& diags, std::vector<std::string>& warnings);

}  // namespace granulab::io
