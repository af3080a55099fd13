// SPDX-License-Identifier: MIT
// The CSV form of an analysis::Table (docs/plots.md "Table format"): the notes as leading "# "
// lines, one header line of "name [unit]" cells, then the rows with 10 significant digits ("nan"
// for missing values). scripts/plot_analysis.py reads it; so do numpy and pandas (comment="#").
#pragma once
#include <string>

#include "analysis/table.hpp"

namespace granulab::io {

/// The table as CSV text; throws std::invalid_argument when its columns differ in length.
std::string tableCsv(const analysis::Table& table);

/// Writes tableCsv(table) to `path` through AtomicFile (creating the folder).
void writeTableCsv(const std::string& path, const analysis::Table& table);

}  // namespace granulab::io
