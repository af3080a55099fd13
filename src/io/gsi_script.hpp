// SPDX-License-Identifier: MIT
// gc2d's input filters for generator scripts (gc2d spec 9.1, 9.8; docs/coming-from-gc2d.md
// "Generator scripts"): `foo.gsi.pl` is run with perl, and any other executable scene file (a
// Python generator, `foo.gsi.py`) is run directly; its standard output is read as gsi, so error
// messages name lines of the generated gsi ("foo.gsi.py (output)":line), as gc2d's do. A script
// runs only when the user allows it (`--allow-script`): a scene file must not run code unasked.
// Extra arguments (gc2d's -P "string") become the script's argv, split at blanks.
#pragma once
#include <string>
#include <vector>

#include "model/scene_def.hpp"

namespace granulab::io {

/// True for a scene path that names a generator: ends in .gsi.pl, .gsi.py or .gsi.sh, or is
/// another executable regular file that is not a .toml, .gsi or .gsi.gz scene.
bool isGsiScript(const std::string& path);

/// Runs the generator at `path` with `args` and reads its output as a gsi scene. Throws SceneError
/// (exit status 2) when `allowed` is false (the message names --allow-script), when the script
/// cannot run or exits with a failure (its status and the end of its error output), or for
/// errors in the generated gsi.
model::SceneDef readGsiScript(const std::string& path, const std::vector<std::string>& args, bool allowed);

/// `-P "a b c"`: the words of a gc2d parameter string.
std::vector<std::string> splitScriptArgs(const std::string& text);

}  // namespace granulab::io
