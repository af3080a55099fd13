// SPDX-License-Identifier: MIT
// `granulab run`: reads a scene, builds the engine of its run.engine through the engine table
// and runs it in the one run loop (app/run_loop.hpp); writes the outputs of the user contract
// (DESIGN.md), checkpoints and resumes. Refuses (SceneError, exit 2) an output folder that holds
// another run's outputs unless `overwrite`, and with output.gc2d one that holds the lock
// <basename>.glk unless `ignoreLock` (gc2d spec 9.1); SIGINT/SIGTERM stop it cleanly (exit 130/143).
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
    /// output.gc2d: run although the folder holds the lock <basename>.glk (gc2d's -l, spec 9.6)
    bool ignoreLock = false;
    bool quiet = false;
};

int runCommand(const RunOptions& options);

/// Default output folder for a scene path: out/<stem> (a cfddem folder: out/<folder name>).
std::string defaultOutDir(const std::string& scenePath);

}  // namespace granulab::app
