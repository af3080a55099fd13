// SPDX-License-Identifier: MIT
// series.csv and final.csv writers.
#include "io/csv_writers.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace granulab::io {

SeriesWriter::SeriesWriter(const std::string& path, std::vector<std::string> columns, double resumeTime)
    : m_columns(columns.size()) {
    std::string kept;
    if (resumeTime >= 0) {
        std::ifstream in(path);
        std::string line;
        bool header = true;
        while (std::getline(in, line)) {
            if (header) {
                header = false;
                continue;
            }
            const double t = std::strtod(line.c_str(), nullptr);
            if (t <= resumeTime) kept += line + "\n";
        }
    }
    m_file = std::fopen(path.c_str(), "w");
    if (!m_file) throw std::runtime_error("cannot write " + path);
    std::string header;
    for (std::size_t k = 0; k < columns.size(); ++k) header += (k ? "," : "") + columns[k];
    std::fputs((header + "\n" + kept).c_str(), m_file);
}

SeriesWriter::~SeriesWriter() {
    if (m_file) std::fclose(m_file);
}

void SeriesWriter::row(const std::vector<double>& values) {
    std::string line;
    for (std::size_t k = 0; k < values.size() && k < m_columns; ++k) line += fmt::format("{}{:.17g}", k ? "," : "", values[k]);
    line += "\n";
    std::fputs(line.c_str(), m_file);
}

void SeriesWriter::flush() { std::fflush(m_file); }

namespace {
/// `shapes` == nullptr: polygons are written with corners 0.
void finalCsv(const std::string& path, const model::ParticleStore& s, const model::ShapePool* shapes,
              const std::vector<std::string>& materialNames, model::MassModel massModel) {
    std::vector<std::size_t> order(s.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.id[a] < s.id[b]; });
    const char* round = massModel == model::MassModel::Sphere ? "sphere" : "disk";
    const bool hasShapes = s.shape.size() == s.size();
    if (shapes != nullptr && hasShapes)
        for (std::size_t i = 0; i < s.size(); ++i)
            if (s.shape[i] != model::kDiskShape && s.shape[i] >= shapes->size())
                throw std::invalid_argument(fmt::format("{}: particle {} refers to shape {}, the pool holds {}", path,
                                                        s.id[i], s.shape[i], shapes->size()));
    // Streamed row by row (a 1e6-particle file is ~200 MB), then renamed into place.
    const std::string tmp = path + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f) throw std::runtime_error("cannot write " + tmp);
    fmt::print(f, "id,shape,x,y,vx,vy,angle,omega,radius,mass,material,corners\n");
    for (const std::size_t i : order) {
        const bool polygon = hasShapes && s.shape[i] != model::kDiskShape;
        const std::uint32_t corners = polygon && shapes != nullptr ? shapes->count[s.shape[i]] : 0;
        fmt::print(f, "{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{},{}\n", s.id[i],
                   polygon ? "polygon" : round, s.x[i], s.y[i], s.vx[i], s.vy[i], s.angle[i], s.omega[i], s.radius[i],
                   s.mass[i], s.material[i] < materialNames.size() ? materialNames[s.material[i]] : "?", corners);
    }
    const bool ok = std::ferror(f) == 0;
    if (std::fclose(f) != 0 || !ok) throw std::runtime_error("write failed: " + tmp);
    std::filesystem::rename(tmp, path);
}
}  // namespace

void writeFinalCsv(const std::string& path, const model::ParticleStore& s, const model::ShapePool& shapes,
                   const std::vector<std::string>& materialNames, model::MassModel massModel) {
    finalCsv(path, s, &shapes, materialNames, massModel);
}

void writeFileAtomically(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw std::runtime_error("cannot write " + tmp);
        out << text;
        if (!out) throw std::runtime_error("write failed: " + tmp);
    }
    std::filesystem::rename(tmp, path);
}

}  // namespace granulab::io
