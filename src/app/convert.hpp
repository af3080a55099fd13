// SPDX-License-Identifier: MIT
// The cfddem seed's input files on the command line (io/cfddem_files.hpp; docs/scene-format.md
// "The cfddem seed's input files"): `granulab convert DIR scene.toml` writes the native scene of a
// folder holding conditions.txt, boundary.txt and startvalue(s).txt, and `granulab run DIR` /
// `granulab info DIR` read such a folder directly (app::readScene dispatches here).
#pragma once
#include <string>
#include <vector>

#include "io/scene_override.hpp"
#include "model/scene_def.hpp"

namespace granulab::app {

struct ConvertOptions {
    std::string dir;         ///< the input: a cfddem folder of the three files, a .gsi or a .toml scene
    std::string out;         ///< the scene to write: .toml (from a folder or gsi) or .gsi (from TOML)
    bool overwrite = false;  ///< replace an existing file
    bool quiet = false;
};

/// Writes options.dir as options.out (refused when it exists, unless overwrite): a cfddem folder or
/// a gsi scene as native TOML (io/scene_toml_writer.hpp), a TOML scene as gsi (io/gsi_writer.hpp;
/// only scenes made of gc2d's elements). Bad input or a scene gsi cannot express throws
/// SceneError (exit status 2). Returns the exit status.
int convertCommand(const ConvertOptions& options);

/// True when the scene path `path` names a folder meant as cfddem input: it holds at least one of
/// the three files (a missing one is then reported as such). Other folders are left to
/// io::readScene ("is a directory").
bool isCfddemInput(const std::string& path);

/// The scene of a cfddem folder. Without overrides: io::readCfddemFolder. With overrides: the
/// folder's scene as TOML text, read again with the overrides (io::readSceneText), every location
/// that did not come from a --set pointing back into the three files; SceneDef::path is
/// DIR/conditions.txt either way.
model::SceneDef readCfddemScene(const std::string& dir, const std::vector<io::Override>& overrides);

/// The scene of a gc2d gsi file (io/gsi_scene.hpp), with overrides as for a cfddem folder.
model::SceneDef readGsiScene(const std::string& path, const std::vector<io::Override>& overrides);

/// `scene` with `overrides` applied to its TOML form (io::sceneToToml, read again with them);
/// every location that did not come from a --set points back into the scene's own files.
model::SceneDef withOverrides(model::SceneDef scene, const std::vector<io::Override>& overrides);

}  // namespace granulab::app
