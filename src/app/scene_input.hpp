// SPDX-License-Identifier: MIT
// Scene input of the commands: io::readScene with the sections of every engine
// (docs/scene-format.md; io/dem_sections.hpp, io/edmd_sections.hpp). Transitional: the engine
// table of app/ will list the rows.
#pragma once
#include <string>
#include <vector>

#include "io/scene_reader.hpp"
#include "model/scene_def.hpp"

namespace granulab::app {

/// Reads a scene file with every engine's sections; throws SceneError (exit status 2).
model::SceneDef readScene(const std::string& path, const std::vector<io::Override>& overrides = {});

/// Same from a string (tests); `path` is only used in messages.
model::SceneDef readSceneText(const std::string& text, const std::string& path,
                              const std::vector<io::Override>& overrides = {});

}  // namespace granulab::app
