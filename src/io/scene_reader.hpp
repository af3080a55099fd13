// SPDX-License-Identifier: MIT
// Native TOML scene reader (docs/scene-format.md): text -> model::SceneDef. Reads [run] and
// [output] and hands the running engine's sections to that engine's reader (a SceneSections row,
// e.g. io/dem_sections.hpp); reports syntax, type and unknown-key errors with file:line. Range
// and consistency checks are in io/validate_<engine>.hpp and the engine's set-up.
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/scene_override.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

class TableReader;  // io/toml_table_reader.hpp

/// The sections one engine reads from a scene file; the engine table (app/) lists one per engine.
struct SceneSections {
    std::string engine;                 ///< value of run.engine, e.g. "dem"
    std::vector<std::string> sections;  ///< top-level keys it owns, e.g. {"dem", "material", ...}
    std::string required;               ///< section that must be present when this engine runs
    std::string requiredHint;           ///< what it needs at least, e.g. "needs at least dt"
    bool needsEndTime = true;           ///< run.end_time is required (edmd may end by tau or collisions)
    /// Reads its sections from the root table into `scene` (through root.node(section), so that
    /// they count as known keys); called only when this engine runs.
    void (*read)(TableReader& root, model::SceneDef& scene) = nullptr;
};

/// Reads a scene file, applies overrides, and fills a SceneDef: [run], [output] and the sections
/// of the engine named by run.engine, one of `engines`. A section of another engine is an error.
/// Throws SceneError listing every problem found (syntax, types, unknown keys with a "did you
/// mean" hint).
model::SceneDef readScene(const std::string& path, const std::vector<Override>& overrides,
                          const std::vector<SceneSections>& engines);

/// Same from a string (tests); `path` is only used in messages.
model::SceneDef readSceneText(const std::string& text, const std::string& path,
                              const std::vector<Override>& overrides,
                              const std::vector<SceneSections>& engines);

}  // namespace granulab::io
