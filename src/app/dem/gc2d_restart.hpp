// SPDX-License-Identifier: MIT
// gc2d's restart files of a DEM run (gc2d spec 9.1, 9.4; docs/coming-from-gc2d.md "Restart
// files"): the gso (the complete state in gsi syntax: every grain a PARTICLE with its body-frame
// CORNERS, COM, ANGLE, VELOCITY, OMEGA, the Gear predictor's ACCELERATION, OMEGA_DOT, PC_TRANS3-5,
// PC_ROT3-5, and its ID; walls with their current corners; GENERAL with TIME t t_end) and the gco
// (every contact with a history: Particles, Summ_Friction = k_t xi, Old_Area). Renamed to foo.gsi
// and foo.gci they restart the run where it stood (io/gsi_scene.hpp reads both).
#pragma once
#include <string>

#include "dem/world.hpp"
#include "io/gc2d_ids.hpp"
#include "model/scene_def.hpp"

namespace granulab::app {

/// The state of `world` as the Defs a gsi holds (io/gsi_writer.hpp writes them), with `scene`'s
/// settings; `contacts` receives the gco's contacts. Throws std::invalid_argument for what gsi
/// cannot hold (disks).
model::SceneDef gc2dStateOf(const model::SceneDef& scene, const dem::World& world,
                            std::vector<model::RememberedContactDef>& contacts);

/// Writes `gsoPath` and `gcoPath` (atomically) with the identification line gc2d writes
/// ("date time --- host --- user"). Throws std::invalid_argument (gsi cannot hold the scene) or
/// std::runtime_error (a file).
void writeGc2dRestart(const std::string& gsoPath, const std::string& gcoPath, const model::SceneDef& scene,
                      const dem::World& world);

}  // namespace granulab::app
