// SPDX-License-Identifier: MIT
// CSV writer of analysis tables (io/analysis_table.hpp).
#include "io/analysis_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace granulab::io {

std::string tableCsv(const analysis::Table& table) {
    std::string out;
    for (const std::string& note : table.notes) out += "# " + note + "\n";
    const std::size_t rows = table.rows();
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
        const analysis::Column& col = table.columns[c];
        if (col.values.size() != rows)
            throw std::invalid_argument(fmt::format("table {}: column '{}' has {} values, the first has {}",
                                                    table.name, col.name, col.values.size(), rows));
        out += fmt::format("{}{} [{}]", c ? "," : "", col.name, col.unit.empty() ? "1" : col.unit);
    }
    out += "\n";
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t c = 0; c < table.columns.size(); ++c) {
            const double v = table.columns[c].values[r];
            if (c) out += ',';
            out += std::isnan(v) ? std::string("nan") : fmt::format("{:.10g}", v);
        }
        out += "\n";
    }
    return out;
}

void writeTableCsv(const std::string& path, const analysis::Table& table) {
    writeFileAtomically(path, tableCsv(table));
}

}  // namespace granulab::io
