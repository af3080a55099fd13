// SPDX-License-Identifier: MIT
// The result of an analysis as a table of named columns with units, plus notes (fitted
// parameters, warnings). Pure data: io/analysis_table.cpp writes it as CSV ("name [unit]" header
// cells, notes as leading "# " lines), scripts/plot_analysis.py plots it.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace granulab::analysis {

struct Column {
    std::string name;  ///< quantity, e.g. "x/d", "sigma_zz"
    std::string unit;  ///< e.g. "m", "N/m", "1" for a pure number
    std::vector<double> values;
};

struct Table {
    std::string name;                ///< file stem, e.g. "floor_pressure"
    std::vector<std::string> notes;  ///< "key = value [unit]" lines and warnings, written as "# " lines
    std::vector<Column> columns;     ///< all of equal length

    Column& add(std::string columnName, std::string unit) {
        columns.push_back({std::move(columnName), std::move(unit), {}});
        return columns.back();
    }
    std::size_t rows() const noexcept { return columns.empty() ? 0 : columns.front().values.size(); }
};

}  // namespace granulab::analysis
