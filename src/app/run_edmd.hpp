// SPDX-License-Identifier: MIT
// `granulab run` for event-driven gases (run.engine = "edmd"; edmd spec sections 2, 4, 5).
#pragma once
#include "app/run.hpp"
#include "io/validate_edmd.hpp"

namespace granulab::app {

/// Validates the [edmd] scene, runs it and writes the outputs (summary.json, series.csv,
/// final.csv, snapshots, analysis files, theory.csv, checkpoint.bin). Returns the exit status.
int runEdmdCommand(const RunOptions& options, const model::SceneDef& scene);

}  // namespace granulab::app
