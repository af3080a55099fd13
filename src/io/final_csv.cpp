// SPDX-License-Identifier: MIT
// final.csv writer (io/final_csv.hpp).
#include "io/final_csv.hpp"

#include <iterator>

namespace granulab::io {

FinalCsvWriter::FinalCsvWriter(const std::string& path, FinalCsvLayout layout)
    : m_layout(std::move(layout)), m_file(path) {
    static const char* const kAxis[3] = {"x", "y", "z"};
    const int D = m_layout.dim;
    std::string header = "id,shape";
    for (int d = 0; d < D; ++d) header += std::string(",") + kAxis[d];
    for (int d = 0; d < D; ++d) header += std::string(",v") + kAxis[d];
    if (m_layout.angle) header += ",angle";
    if (D == 2)
        header += ",omega";
    else
        header += ",omega_x,omega_y,omega_z";
    header += ",radius";
    for (const auto& e : m_layout.extras) header += "," + e;
    m_file.write(header + "\n");
}

void FinalCsvWriter::row(const FinalCsvParticle& p) {
    m_line.clear();
    auto out = std::back_inserter(m_line);
    fmt::format_to(out, "{},{}", p.id, p.shape);
    const int D = m_layout.dim;
    for (int d = 0; d < D; ++d) fmt::format_to(out, ",{:.17g}", p.x[d]);
    for (int d = 0; d < D; ++d) fmt::format_to(out, ",{:.17g}", p.v[d]);
    if (m_layout.angle) fmt::format_to(out, ",{:.17g}", p.angle);
    if (D == 2)
        fmt::format_to(out, ",{:.17g}", p.omega[2]);
    else
        fmt::format_to(out, ",{:.17g},{:.17g},{:.17g}", p.omega[0], p.omega[1], p.omega[2]);
    fmt::format_to(out, ",{:.17g}", p.radius);
}

void FinalCsvWriter::endRow() {
    m_line.push_back('\n');
    m_file.stream().write(m_line.data(), static_cast<std::streamsize>(m_line.size()));
}

}  // namespace granulab::io
