// SPDX-License-Identifier: MIT
// Readers of [fluid] and [attraction] (docs/scene-format.md; cfddem spec 5): syntax, type and
// unknown-key errors only; io/validate_fluid.cpp checks ranges and the field files.
#pragma once
#include "io/toml_table_reader.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

void readFluidSections(TableReader& root, model::SceneDef& scene);

}  // namespace granulab::io
