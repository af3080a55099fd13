// SPDX-License-Identifier: MIT
// `granulab run`: read + validate a scene, run the engine, write the outputs of the user
// contract (DESIGN.md), checkpoint and resume.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "io/scene_reader.hpp"

namespace granulab::app {

/// Exit statuses of the command line.
enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2, kExitUnstable = 3 };

struct RunOptions {
    std::string scene;
    std::string outDir;      ///< default: out/<scene file stem>
    std::vector<io::Override> overrides;
    std::string resumeDir;   ///< continue from resumeDir/checkpoint.bin
    bool quiet = false;
};

int runCommand(const RunOptions& options);

/// Default output folder for a scene path: out/<stem>.
std::string defaultOutDir(const std::string& scenePath);

/// Peak resident memory of this process [bytes] (VmHWM of /proc/self/status; 0 if unknown).
std::size_t peakRssBytes();

}  // namespace granulab::app
