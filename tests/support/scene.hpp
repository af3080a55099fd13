// SPDX-License-Identifier: MIT
// Test helpers: read a scene (docs/scene-format.md) through the real reader with the sections of
// every engine (io/dem_sections.hpp, io/edmd_sections.hpp), as the commands do.
#pragma once
#include <string>
#include <vector>

#include "app/engine_table.hpp"
#include "io/scene_reader.hpp"

namespace granulab::test {

/// The section readers of every engine, from the engine table.
inline std::vector<io::SceneSections> sceneSections() {
    return app::sceneSections();
}

inline model::SceneDef readSceneText(const std::string& text, const std::string& path = "test.toml",
                                     const std::vector<io::Override>& overrides = {}) {
    return io::readSceneText(text, path, overrides, sceneSections());
}

inline model::SceneDef readScene(const std::string& path, const std::vector<io::Override>& overrides = {}) {
    return io::readScene(path, overrides, sceneSections());
}

}  // namespace granulab::test
