// SPDX-License-Identifier: MIT
// Def-level checks of a dem scene (DESIGN.md "one validate(SceneDef)"): ranges, names and
// references of every [dem], [[material]], [[wall]], [[spring]], [[shape]] and [output] key,
// reported with file:line, key and the allowed range. The engine's own set-up checks (contact
// laws, particle generation, start overlaps, time step) follow in dem::prepareScene.
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

/// Adds every problem to `diags` (does not throw); shape warnings go to `warnings`.
void checkDemDef(const model::SceneDef& scene, Diagnostics& diags, std::vector<std::string>& warnings);

}  // namespace granulab::io
