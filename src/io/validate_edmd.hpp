// SPDX-License-Identifier: MIT
// Def-level checks of an event-driven gas scene ([edmd], edmd spec sections 2 and 4): every
// range, the box/count/volume-fraction triangle and the output intervals, reported with
// file:line. The engine's set-up follows in edmd::resolveScene.
#pragma once
#include "core/error.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

/// Adds every problem to `diags` (does not throw).
void checkEdmdDef(const model::SceneDef& scene, Diagnostics& diags);

}  // namespace granulab::io
