// SPDX-License-Identifier: MIT
// The dem engine's row of the engine table (app/engine_table.cpp): building its Simulation
// adapter and `granulab info` (gc2d and cfddem specs; docs/physics/contact-laws.md).
#pragma once
#include <memory>
#include <string>

#include "app/analyze.hpp"
#include "app/simulation.hpp"
#include "dem/scene_setup.hpp"
#include "model/scene_def.hpp"

namespace granulab::app {

struct SimulationOptions;

/// io::checkDemDef + dem::prepareScene: every scene problem at once, as SceneError.
dem::PreparedScene checkAndPrepareDem(const model::SceneDef& scene);

std::unique_ptr<Simulation> makeDemSimulation(const model::SceneDef& scene, const SimulationOptions& options);

/// `granulab info` of a dem scene: particles, materials, laws, contact time, advised dt, memory.
int demInfo(const std::string& scenePath, const model::SceneDef& scene);

/// `granulab analyze DIR [what...]` of a dem run (gc2d spec section 7): reads the snapshots'
/// particles, walls and contact files and writes DIR/analysis/snapshot_NNNNNN/<table>.csv.
int demAnalyze(const AnalyzeOptions& options, const nlohmann::json& summary);

}  // namespace granulab::app
