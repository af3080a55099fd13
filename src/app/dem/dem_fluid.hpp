// SPDX-License-Identifier: MIT
// The dem adapter's set-up of [fluid] and [attraction] (cfddem spec 5): the opened field files
// handed to the engine, and the checks that need both the fields and the generated particles.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/scene_setup.hpp"
#include "dem/world.hpp"
#include "io/csv_writers.hpp"
#include "io/flow_fields.hpp"
#include "io/vtk_writer.hpp"
#include "model/scene_def.hpp"

namespace granulab::app {

/// Moves the field source into `prepared` and checks that the field of t = 0 covers every
/// initial particle and every inlet (within fluid.check_margin), and that an all-pairs
/// attraction is affordable. Problems go to `diags`.
void prepareDemFluid(const model::SceneDef& scene, io::OpenedFields fields, dem::PreparedScene& prepared,
                     Diagnostics& diags);

/// series.csv columns of the fluid (appended after the others): particles outside the field,
/// total drag [N], largest particle Reynolds number, index of the current field (0-based), and
/// the smallest voidage for di_felice.
std::vector<std::string> fluidSeriesColumns(const model::SceneDef& scene);
void appendFluidSeriesRow(const model::SceneDef& scene, const dem::World& world, std::vector<double>& row);
/// final.csv columns fluid_ux, fluid_uy [m/s]: the fluid velocity at each particle (empty without
/// [fluid] or before the first field is loaded).
std::vector<io::FinalExtraColumn> fluidFinalColumns(const dem::World& world);
/// The flow at every particle's centre for a VTK snapshot (io::FluidAtParticles; empty without
/// [fluid]; NaN outside the field's mesh, or before the first field is loaded).
io::FluidAtParticles fluidSnapshotArrays(const dem::World& world);
/// summary.json "fluid": the fields, their loads, the interpolation, the drag law.
nlohmann::json fluidSummary(const model::SceneDef& scene, const dem::World& world, const std::string& note);

}  // namespace granulab::app
