// SPDX-License-Identifier: MIT
// Scene input of the commands (app/scene_input.hpp; docs/scene-format.md): the engines' section
// readers passed to io::readScene.
#include "app/scene_input.hpp"

#include "io/dem_sections.hpp"
#include "io/edmd_sections.hpp"

namespace granulab::app {

namespace {

std::vector<io::SceneSections> engineSections() {
    return {io::demSceneSections(), io::edmdSceneSections()};
}

}  // namespace

model::SceneDef readScene(const std::string& path, const std::vector<io::Override>& overrides) {
    return io::readScene(path, overrides, engineSections());
}

model::SceneDef readSceneText(const std::string& text, const std::string& path,
                              const std::vector<io::Override>& overrides) {
    return io::readSceneText(text, path, overrides, engineSections());
}

}  // namespace granulab::app
