// SPDX-License-Identifier: MIT
// final.csv, the one per-particle result file of every engine (DESIGN.md "Contract"; README
// "Outputs"). The contract's columns come first, in this order: id, shape, position (x, y[, z]),
// velocity (vx, vy[, vz]), angle (engines that track orientation), angular velocity (omega in
// 2D; omega_x, omega_y, omega_z in 3D), size (radius [m]; polygons: circumradius). The engine's
// extra columns follow (dem: mass, material, corners; edmd: mass, collisions). New columns are
// appended, so readers of older files keep working. Reals carry 17 significant digits.
#pragma once
#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/types.hpp"
#include "io/atomic_file.hpp"

namespace granulab::io {

struct FinalCsvLayout {
    int dim = 2;                      ///< 2 or 3: position, velocity and angular velocity columns
    bool angle = true;                ///< the engine tracks orientation (2D angle [rad])
    std::vector<std::string> extras;  ///< engine columns after the contract's
};

/// The contract's values of one particle (SI units; unused components ignored).
struct FinalCsvParticle {
    std::uint64_t id = 0;
    std::string_view shape;     ///< disk, sphere or polygon
    Real x[3] = {0, 0, 0};      ///< [m]
    Real v[3] = {0, 0, 0};      ///< [m/s]
    Real angle = 0;             ///< [rad]
    Real omega[3] = {0, 0, 0};  ///< [rad/s]; 2D uses omega[2]
    Real radius = 0;            ///< [m]
};

/// Streams final.csv row by row (a 1e6-particle file is ~200 MB) into an AtomicFile.
class FinalCsvWriter {
public:
    FinalCsvWriter(const std::string& path, FinalCsvLayout layout);

    /// Starts a row with the contract's columns; add the extras in layout order, then endRow().
    void row(const FinalCsvParticle& p);
    void extra(Real value) { fmt::format_to(std::back_inserter(m_line), ",{:.17g}", value); }
    void extra(std::uint64_t value) { fmt::format_to(std::back_inserter(m_line), ",{}", value); }
    void extra(std::string_view text) { fmt::format_to(std::back_inserter(m_line), ",{}", text); }
    void endRow();
    void commit() { m_file.commit(); }

private:
    FinalCsvLayout m_layout;
    AtomicFile m_file;
    fmt::memory_buffer m_line;
};

}  // namespace granulab::io
