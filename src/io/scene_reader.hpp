// SPDX-License-Identifier: MIT
// Native TOML scene reader (docs/scene-format.md): text -> model::SceneDef. Only fills the
// structs and reports syntax, type and unknown-key errors with file:line; range and
// consistency checks are in io/validate.hpp.
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

/// One `--set key=value` override.
struct Override {
    std::string key;    ///< dotted path, arrays indexed as name[k]: "contact[0].kn"
    std::string value;  ///< TOML value text; a bare word is taken as a string
};

/// Parses `key=value`; throws SceneError on a malformed override.
Override parseOverride(const std::string& text);

/// Reads a scene file, applies overrides, and fills a SceneDef. Throws SceneError listing every
/// problem found (syntax, types, unknown keys with a "did you mean" hint).
model::SceneDef readScene(const std::string& path, const std::vector<Override>& overrides = {});

/// Same from a string (tests); `path` is only used in messages.
model::SceneDef readSceneText(const std::string& text, const std::string& path,
                              const std::vector<Override>& overrides = {});

}  // namespace granulab::io
