// SPDX-License-Identifier: MIT
// Def-level checks of [fluid] and [attraction] (cfddem spec 5; docs/scene-format.md): ranges,
// consistency with the mass model and the grain shapes, reported with file:line. The field files
// themselves are checked when they are opened (io/flow_fields.hpp).
#pragma once
#include "core/error.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

void checkFluidDef(const model::SceneDef& scene, Diagnostics& diags);

}  // namespace granulab::io
