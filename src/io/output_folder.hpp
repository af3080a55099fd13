// SPDX-License-Identifier: MIT
// An output folder belongs to one run (issue 11 item 13): which entries of a folder are the
// outputs of an earlier granulab run, and removing exactly those for `granulab run --overwrite`
// (never a file granulab does not write).
#pragma once
#include <string>
#include <vector>

namespace granulab::io {

/// The entries of `dir` that a granulab run (or `render`/`analyze` of it) writes: summary.json,
/// series.csv, final.csv, checkpoint.bin, snapshots.pvd, theory.csv, gc2d's files (*.ggf, *.gff,
/// *.gpf, *.gtf, *.gpl, *.glk, *.ps, *.gso, *.gco), their ".tmp" leftovers, and the folders vtk/,
/// png/ and analysis/. Sorted; empty when `dir` does not exist or holds none.
std::vector<std::string> runOutputsIn(const std::string& dir);

/// Removes those entries: the files, and inside the folders only files of granulab's kinds
/// (.vtp, .png, .csv, .json, .tmp); a folder goes when it is then empty. Other files stay.
/// Throws std::runtime_error naming an entry it cannot remove.
void removeRunOutputs(const std::string& dir);

}  // namespace granulab::io
