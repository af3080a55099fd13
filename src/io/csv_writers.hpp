// SPDX-License-Identifier: MIT
// CSV outputs of the user contract (DESIGN.md "Contract"): series.csv (one row per output
// time) and final.csv (one row per particle). Numbers are written with 17 significant digits,
// so a resumed run can be compared byte for byte.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "model/mass_model.hpp"
#include "model/particle_store.hpp"
#include "model/shape_pool.hpp"

namespace granulab::io {

/// Appends rows to series.csv; the header is fixed at construction.
class SeriesWriter {
public:
    /// Opens `path`. If `resumeTime` >= 0 the existing file is kept up to rows with
    /// time <= resumeTime (a resumed run continues it; rows of a different header are rewritten
    /// in the new one, columns matched by name, `nan` where the old one had none); otherwise it
    /// is truncated.
    SeriesWriter(const std::string& path, std::vector<std::string> columns, double resumeTime = -1);
    ~SeriesWriter();
    SeriesWriter(const SeriesWriter&) = delete;
    SeriesWriter& operator=(const SeriesWriter&) = delete;

    void row(const std::vector<double>& values);
    void flush();

private:
    std::FILE* m_file = nullptr;
    std::size_t m_columns = 0;
};

/// final.csv of a 2D particle store (io/final_csv.hpp): id, shape, x, y, vx, vy, angle, omega,
/// radius, then mass, material, corners; sorted by id.
/// shape is `disk` or `sphere` for round particles (after `massModel`, dem.mass_model) and
/// `polygon` for particles whose shape is in `shapes`; corners is the polygon's corner count, 0
/// for round particles. New columns go at the end, so readers of older files keep working.
/// A shape index outside `shapes` throws std::invalid_argument.
/// `extra`: further columns (name, one value per slot), appended after corners (e.g. the fluid
/// velocity at each particle of a [fluid] run).
struct FinalExtraColumn {
    std::string name;
    std::vector<Real> values;  ///< by slot
};
void writeFinalCsv(const std::string& path, const model::ParticleStore& s, const model::ShapePool& shapes,
                   const std::vector<std::string>& materialNames, model::MassModel massModel,
                   const std::vector<FinalExtraColumn>& extra = {});

}  // namespace granulab::io
