// SPDX-License-Identifier: MIT
// Writes a model::SceneDef of the 2D dem engine back as native TOML scene text
// (docs/scene-format.md): every dem section ([run], [dem] and [[dem.damping]], [[material]],
// [[contact]], [[shape]], [[particle]], [[block]], [[heap]], [[wall]], [[spring]], the machines
// [[drum]] to [[change]], [fluid], [attraction], [output]). Used by `granulab convert` (cfddem
// folders and gsi files to TOML) and by `--set` on those inputs (app/convert.hpp).
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
/// Throws std::invalid_argument for a scene of another engine or dimension.
std::string sceneToToml(const model::SceneDef& scene, const std::string& tomlPath,
                        const std::vector<std::string>& header = {});

/// `v` as TOML number text, the shortest that reads back exactly (-0 as -0.0).
std::string tomlNumber(double v);

/// `s` as a TOML basic string (quoted, escaped); throws std::invalid_argument if it is not UTF-8.
std::string tomlString(const std::string& s);

}  // namespace granulab::io
