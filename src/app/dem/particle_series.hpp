// SPDX-License-Identifier: MIT
// The cfddem seed's nine per-particle time series (spec 6.6, Tab. 4.1) as an optional output
// (output.particle_series): CSV/r_x.csv, r_y.csv, phi.csv, v_x.csv, v_y.csv, omega.csv, a_x.csv,
// a_y.csv, alpha.csv in the run folder, one row per particle at every series.csv row. Long format
// (`time,id,<quantity>`) with stable ids, so that particles entering and leaving through inlets
// and outlets need no special case (the spec's [R]); scripts/plot_particle_series.py draws the
// nine diagrams. Accelerations are those of the last force evaluation (F/m, torque/I).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "io/csv_writers.hpp"
#include "model/particle_store.hpp"

namespace granulab::app {

class ParticleSeries {
public:
    /// Creates dir/CSV/ and its nine files (a resumed run keeps the rows up to resumeTime).
    ParticleSeries(const std::string& dir, double resumeTime);
    void write(double time, const model::ParticleStore& s);
    void flush();

private:
    std::vector<std::unique_ptr<io::SeriesWriter>> m_files;
};

}  // namespace granulab::app
