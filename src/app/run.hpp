// SPDX-License-Identifier: MIT
// `granulab run`: reads a scene, builds the engine of its run.engine through the engine table
// and runs it in the one run loop (app/run_loop.hpp); writes the outputs of the user contract
// (DESIGN.md), checkpoints and resumes. Refuses (SceneError, exit 2) an output folder that holds
// another run's outputs unless `overwrite`; SIGINT/SIGTERM stop it cleanly (exit 130/143).
#pragma once
#include <string>
#include <vector>

#include "app/exit_codes.hpp"
#include "io/scene_reader.hpp"

namespace granulab::app {

struct RunOptions {
    std::string scene;
    std::string outDir;  ///< default: out/<scene file stem>
    std::vector<io::Override> overrides;
    std::string resumeDir;   ///< continue from resumeDir/checkpoint.bin
    bool overwrite = false;  ///< remove an earlier run's outputs from the output folder first
    bool quiet = false;
};

int runCommand(const RunOptions& options);

/// Default output folder for a scene path: out/<stem> (a cfddem folder: out/<folder name>).
std::string defaultOutDir(const std::string& scenePath);

}  // namespace granulab::app
