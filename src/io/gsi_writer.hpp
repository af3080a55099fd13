// SPDX-License-Identifier: MIT
// A model::SceneDef written as gc2d gsi text (gc2d spec 9.2-9.3; docs/coming-from-gc2d.md
// "Converting"): the inverse of io/gsi_scene.hpp's mapping, for scenes made only of what gsi can
// say (the gc2d contact law, gear, sort-and-sweep, the areal grain material, convex polygon walls
// and particles, GENERATE_BLOCK grains, DROPSOURCEs, DRAG springs, variable g, HEAT_ scaling).
// Reading the text back with io/gsi_scene.hpp gives the same Defs, numbers included: every
// number is written as the shortest text that reads back as the same double. Used by
// `granulab convert scene.toml scene.gsi`.
#pragma once
#include <string>

#include "model/scene_def.hpp"

namespace granulab::io {

/// The gsi text of `scene` with `identification` as line 2. Throws std::invalid_argument listing
/// every element gsi cannot express (one per line), so the user sees them all at once.
std::string sceneToGsi(const model::SceneDef& scene, const std::string& identification = "");

/// `v` as gsi number text: the shortest decimal that reads back as the same double.
std::string gsiNumber(double v);

}  // namespace granulab::io
