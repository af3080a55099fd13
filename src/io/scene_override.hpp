// SPDX-License-Identifier: MIT
// Command-line overrides of scene values (`--set key=value`, docs/scene-format.md "Command-line overrides"):
// parsed here and applied to the parsed TOML tree before any section is read.
#pragma once

#include <string>
#include <vector>

#include "core/error.hpp"

namespace granulab::io {

/// One `--set key=value` override.
struct Override {
    std::string key;    ///< dotted path, arrays indexed as name[k]: "contact[0].kn"
    std::string value;  ///< TOML value text; a bare word is taken as a string
};

/// Parses `key=value`; throws SceneError on a malformed override (no '=', an empty key or value,
/// an empty path segment such as "dem..dt", an unclosed or non-numeric [index]).
Override parseOverride(const std::string& text);

/// `error` with every diagnostic about an overridden key (the key itself or one inside it)
/// located at its `--set key=value` instead of the scene line of its section.
SceneError attributeToOverrides(const SceneError& error, const std::vector<Override>& overrides);

/// Runs fn(); a SceneError leaving it names the `--set` of the keys it concerns.
template <class Fn>
auto withOverrideLocations(const std::vector<Override>& overrides, Fn&& fn) {
    try {
        return fn();
    } catch (const SceneError& e) {
        if (overrides.empty()) throw;
        throw attributeToOverrides(e, overrides);
    }
}

}  // namespace granulab::io
