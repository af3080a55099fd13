// SPDX-License-Identifier: MIT
// Def-level checks of the scene machines (walls' kinds and drivers, drums, sources, inlets,
// outlets, boundaries, gravity schedule, law changes); called by io::checkDemDef.
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

void checkMachineDefs(const model::SceneDef& scene, Diagnostics& diags,
                      const std::vector<std::string>& materialNames);

}  // namespace granulab::io
