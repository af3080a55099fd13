// SPDX-License-Identifier: MIT
// Material names of a scene in table order: the material id of a particle or wall is its index
// here (docs/scene-format.md "[[material]]").
#pragma once
#include <string>
#include <vector>

#include "model/scene_def.hpp"

namespace granulab::model {

inline std::vector<std::string> materialNames(const SceneDef& scene) {
    std::vector<std::string> names;
    for (const auto& m : scene.materials) names.push_back(m.name);
    return names;
}

}  // namespace granulab::model
