// SPDX-License-Identifier: MIT
// series.csv and the final.csv of a particle store.
#include "io/csv_writers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/final_csv.hpp"

namespace granulab::io {

namespace {

std::vector<std::string> splitCells(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
        cells.push_back(line.substr(start, comma - start));
    cells.push_back(line.substr(start));
    return cells;
}

/// A row written under the header `from` in the layout `to`: cells matched by column name, `nan`
/// for a column the old layout lacked (a scene edited between checkpoint and resume added a
/// moving wall, say), columns that are gone dropped.
std::string remapRow(const std::string& line, const std::vector<std::string>& from,
                     const std::vector<std::string>& to) {
    const std::vector<std::string> cells = splitCells(line);
    std::string out;
    for (std::size_t k = 0; k < to.size(); ++k) {
        const auto it = std::find(from.begin(), from.end(), to[k]);
        const auto at = static_cast<std::size_t>(it - from.begin());
        out += (k ? "," : "") + (it != from.end() && at < cells.size() ? cells[at] : std::string("nan"));
    }
    return out;
}

}  // namespace

SeriesWriter::SeriesWriter(const std::string& path, std::vector<std::string> columns, double resumeTime)
    : m_columns(columns.size()) {
    std::string header;
    for (std::size_t k = 0; k < columns.size(); ++k) header += (k ? "," : "") + columns[k];
    std::string kept;
    if (resumeTime >= 0) {
        std::ifstream in(path);
        std::string line;
        std::vector<std::string> oldColumns;
        bool first = true;
        while (std::getline(in, line)) {
            if (first) {
                first = false;
                if (line != header) oldColumns = splitCells(line);
                continue;
            }
            const double t = std::strtod(line.c_str(), nullptr);
            if (t > resumeTime) continue;
            kept += (oldColumns.empty() ? line : remapRow(line, oldColumns, columns)) + "\n";
        }
    }
    writeFileAtomically(path, header + "\n" + kept);  // a kill here leaves the old or the new file
    m_file = std::fopen(path.c_str(), "a");
    if (!m_file) throw std::runtime_error("cannot write " + path);
}

SeriesWriter::~SeriesWriter() {
    if (m_file) std::fclose(m_file);
}

void SeriesWriter::row(const std::vector<double>& values) {
    std::string line;
    for (std::size_t k = 0; k < values.size() && k < m_columns; ++k)
        line += fmt::format("{}{:.17g}", k ? "," : "", values[k]);
    line += "\n";
    std::fputs(line.c_str(), m_file);
}

void SeriesWriter::flush() {
    std::fflush(m_file);
}

void writeFinalCsv(const std::string& path, const model::ParticleStore& s, const model::ShapePool& shapes,
                   const std::vector<std::string>& materialNames, model::MassModel massModel,
                   const std::vector<FinalExtraColumn>& extra) {
    std::vector<std::size_t> order(s.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.id[a] < s.id[b]; });
    const char* round = massModel == model::MassModel::Sphere ? "sphere" : "disk";
    const bool hasShapes = s.shape.size() == s.size();
    if (hasShapes)
        for (std::size_t i = 0; i < s.size(); ++i)
            if (s.shape[i] != model::kDiskShape && s.shape[i] >= shapes.size())
                throw std::invalid_argument(
                    fmt::format("{}: particle {} refers to shape {}, the pool holds {}", path, s.id[i],
                                s.shape[i], shapes.size()));
    FinalCsvLayout layout{2, true, {"mass", "material", "corners"}};
    for (const auto& c : extra) {
        if (c.values.size() != s.size())
            throw std::invalid_argument(fmt::format("{}: column {} has {} values for {} particles", path,
                                                    c.name, c.values.size(), s.size()));
        layout.extras.push_back(c.name);
    }
    FinalCsvWriter out(path, layout);
    for (const std::size_t i : order) {
        const bool polygon = hasShapes && s.shape[i] != model::kDiskShape;
        FinalCsvParticle p;
        p.id = s.id[i];
        p.shape = polygon ? "polygon" : round;
        p.x[0] = s.x[i];
        p.x[1] = s.y[i];
        p.v[0] = s.vx[i];
        p.v[1] = s.vy[i];
        p.angle = s.angle[i];
        p.omega[2] = s.omega[i];
        p.radius = s.radius[i];
        out.row(p);
        out.extra(s.mass[i]);
        out.extra(
            std::string_view(s.material[i] < materialNames.size() ? materialNames[s.material[i]] : "?"));
        out.extra(std::uint64_t{polygon ? shapes.count[s.shape[i]] : 0u});
        for (const auto& c : extra) out.extra(c.values[i]);
        out.endRow();
    }
    out.commit();
}

}  // namespace granulab::io
