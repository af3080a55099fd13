// SPDX-License-Identifier: MIT
// Command-line overrides of scene values (`--set key=value`, docs/scene-format.md "Command-line overrides"):
// parsed here and applied to the parsed TOML tree before any section is read.
#pragma once

#include <string>

#include "core/error.hpp"

namespace granulab::io {

/// One `--set key=value` override.
struct Override {
    std::string key;    ///< dotted path, arrays indexed as name[k]: "contact[0].kn"
    std::string value;  ///< TOML value text; a bare word is taken as a string
};

/// Parses `key=value`; throws SceneError on a malformed override.
Override parseOverride(const std::string& text);

}  // namespace granulab::io
