// SPDX-License-Identifier: MIT
// The dem engine's row of the engine table (app/engine_table.cpp): building its Simulation
// adapter and `granulab info` (gc2d and cfddem specs; docs/physics/contact-laws.md).
#pragma once
#include <memory>
#include <string>
#include <vector>

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

/// The in-run analyses (`output.analyses`) of snapshot `index` of the run in `dir`, just written:
/// the same tables as `granulab analyze DIR what... --at T`. `summary` holds what the files lack
/// ("walls", "gravity_magnitude"). Never throws: returns one line per analysis that could not run
/// (no grains yet, no contact file at this snapshot, ...), for the run's warnings.
std::vector<std::string> demAnalyzeSnapshot(const std::string& dir, int index,
                                            const std::vector<std::string>& what,
                                            const nlohmann::json& summary);

}  // namespace granulab::app
