// SPDX-License-Identifier: MIT
// The one run loop of every engine (docs/architecture.md "The run loop"): advances the
// Simulation from output stop to output stop, fires series rows, snapshots, checkpoints and
// progress on their time or count schedules, resumes through the one checkpoint container and
// ends with final.csv and summary.json.
#pragma once
#include <string>

#include "app/simulation.hpp"
#include "model/scene_def.hpp"

namespace granulab::app {

struct RunContext {
    std::string engine;  ///< name of the engine table row (checkpoint and summary.json)
    std::string scenePath;
    std::string dir;            ///< output folder (exists)
    std::string resumeDir;      ///< empty: a fresh run
    std::string resumeCommand;  ///< the command line that resumes this run from `dir`
    bool quiet = false;
    double startWall = 0;  ///< [s] wallSeconds() when the command started
};

/// Runs `sim` to the end of its plan; returns the exit status (0, 3 when it became unstable,
/// 128 + signal when SIGINT/SIGTERM stopped it; core/interrupt.hpp). Bad input (a foreign or
/// damaged checkpoint, an end already reached) throws SceneError.
int runSimulation(Simulation& sim, const model::SceneDef& scene, const RunContext& context);

}  // namespace granulab::app
