// SPDX-License-Identifier: MIT
// Writes a model::SceneDef back as native TOML scene text (docs/scene-format.md): the subset of
// the dem engine's Defs that the cfddem seed's input files produce (io/cfddem_files.hpp: [run],
// [dem], [[material]], [[contact]], [[particle]], [[boundary]], [[inlet]], [fluid], [attraction],
// [output]). Used by `granulab convert` and by `granulab run DIR --set ...` (app/convert.hpp).
// Every number is written as the shortest decimal text that reads back as the same double (fmt's
// "{}", round-trip exact like {:.17g} but 0.3 stays 0.3), so the round trip is exact; each key
// carries its unit in a comment. Keys at their default are mostly left out.
#pragma once
#include <string>
#include <vector>

#include "model/scene_def.hpp"

namespace granulab::io {

/// The TOML text of `scene`, to be written at `tomlPath`: relative paths of `scene` (fluid.fields,
/// relative to the folder of scene.path) are rewritten relative to the folder of `tomlPath`, or
/// made absolute when no relative path leads there. `header` lines become `# ` comments at the top.
/// Throws std::invalid_argument for a scene with Defs outside the subset above (blocks, walls,
/// shapes, other machines, another engine).
std::string sceneToToml(const model::SceneDef& scene, const std::string& tomlPath,
                        const std::vector<std::string>& header = {});

/// `v` as TOML number text, the shortest that reads back exactly (-0 as -0.0).
std::string tomlNumber(double v);

/// `s` as a TOML basic string (quoted, escaped); throws std::invalid_argument if it is not UTF-8.
std::string tomlString(const std::string& s);

}  // namespace granulab::io
