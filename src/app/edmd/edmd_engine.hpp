// SPDX-License-Identifier: MIT
// The edmd engine's row of the engine table (app/engine_table.cpp): building its Simulation
// adapter, `granulab info` and `granulab analyze` (edmd spec sections 2, 4, 5).
#pragma once
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/analyze.hpp"
#include "app/simulation.hpp"
#include "edmd/scene_setup.hpp"
#include "model/scene_def.hpp"

namespace granulab::app {

struct SimulationOptions;

/// io::checkEdmdDef + edmd::resolveScene: every scene problem, as SceneError.
edmd::Setup checkAndResolveEdmd(const model::SceneDef& scene);

std::unique_ptr<Simulation> makeEdmdSimulation(const model::SceneDef& scene,
                                               const SimulationOptions& options);

/// `granulab info` of an edmd scene: the resolved set-up and the kinetic-theory scales and
/// thresholds of edmd spec 4.3-4.6.
int edmdInfo(const std::string& scenePath, const model::SceneDef& scene);

/// `granulab analyze` of an edmd output folder whose summary.json is `summary` (edmd spec 5.2).
int edmdAnalyze(const AnalyzeOptions& options, const nlohmann::json& summary);

}  // namespace granulab::app
