// SPDX-License-Identifier: MIT
// Readers of the scene machines' sections (docs/scene-format.md "[[drum]]" to "[[change]]"; gc2d
// spec 6.2-6.7, cfddem spec 4): syntax, type and unknown-key errors only; io/validate_machines.cpp
// checks ranges and references.
#pragma once
#include <string>

#include "io/toml_table_reader.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

/// Reads [[drum]], [[source]], [[inlet]], [[outlet]], [[boundary]], [gravity], [size_scaling] and
/// [[change]].
void readMachineSections(TableReader& root, model::SceneDef& scene);

/// A radius: a number or a size-distribution table (defined in io/dem_sections.cpp).
void readSize(TableReader& parent, const std::string& key, model::SizeDistDef& size);

}  // namespace granulab::io
