// SPDX-License-Identifier: MIT
// The engine table: the only place that names engines (docs/architecture.md "Adding an
// engine"). `granulab run`, `info` and `analyze` look an engine up here by run.engine (or by the
// engine recorded in summary.json) and call its row; nothing else compares engine names.
#pragma once
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/analyze.hpp"
#include "app/simulation.hpp"
#include "app/simulation_options.hpp"
#include "io/scene_reader.hpp"
#include "model/scene_def.hpp"

namespace granulab::app {

struct EngineEntry {
    std::string name;         ///< value of run.engine
    std::string description;  ///< one line for help texts
    /// The engine's sections of the scene file and their reader (io/<engine>_sections.hpp).
    io::SceneSections (*sections)();
    /// Checks the scene (every problem at once, SceneError) and builds the engine's adapter.
    std::unique_ptr<Simulation> (*build)(const model::SceneDef& scene, const SimulationOptions& options);
    /// `granulab info SCENE`: prints what the scene contains; returns the exit status.
    int (*info)(const std::string& scenePath, const model::SceneDef& scene);
    /// `granulab analyze DIR` of a finished run (nullptr: no analyses yet, see analyzeLater).
    int (*analyze)(const AnalyzeOptions& options, const nlohmann::json& summary);
    std::string analyzeLater;  ///< what to tell a user whose engine has no analyses yet
    /// Runs on several MPI ranks (`mpirun -np P granulab run`; app/simulation.hpp says what its
    /// adapter must then do); otherwise such a run is refused with exit status 2.
    bool severalRanks = false;
};

const std::vector<EngineEntry>& engineTable();

/// The row of `name`; nullptr if no engine has that name.
const EngineEntry* findEngine(const std::string& name);

/// The row of the scene's run.engine; SceneError at run.engine listing the engines otherwise.
const EngineEntry& engineOf(const model::SceneDef& scene);

/// "dem, edmd" (for messages).
std::string engineNamesText();

/// The scene-section readers of every engine in the table, in table order.
std::vector<io::SceneSections> sceneSections();

/// Generator scripts as scenes (io/gsi_script.hpp): whether they may run (--allow-script) and
/// their arguments (-P). Set once by main before any scene is read.
struct ScriptPolicy {
    bool allowed = false;
    std::vector<std::string> args;
};
void setScriptPolicy(ScriptPolicy policy);

/// Reads a scene file with the sections of every engine in the table; SceneError lists every
/// problem. readSceneText: the same from a string (`path` names it in messages, and a path ending
/// in .gsi or .gsi.gz makes the text gc2d's gsi). A generator script (io/gsi_script.hpp) runs
/// under the ScriptPolicy.
model::SceneDef readScene(const std::string& path, const std::vector<io::Override>& overrides);
model::SceneDef readSceneText(const std::string& text, const std::string& path,
                              const std::vector<io::Override>& overrides = {});

}  // namespace granulab::app
