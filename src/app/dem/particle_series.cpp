// SPDX-License-Identifier: MIT
// The nine per-particle CSV series of the cfddem seed (app/dem/particle_series.hpp; spec 6.6).
#include "app/dem/particle_series.hpp"

#include <filesystem>

namespace granulab::app {

namespace {
/// File names of spec Tab. 4.1, in the order write() fills them.
const char* const kQuantities[] = {"r_x", "r_y", "phi", "v_x", "v_y", "omega", "a_x", "a_y", "alpha"};
}  // namespace

ParticleSeries::ParticleSeries(const std::string& dir, double resumeTime) {
    const std::string folder = dir + "/CSV";
    std::filesystem::create_directories(folder);
    for (const char* q : kQuantities)
        m_files.push_back(std::make_unique<io::SeriesWriter>(
            folder + "/" + q + ".csv", std::vector<std::string>{"time", "id", q}, resumeTime));
}

void ParticleSeries::write(double time, const model::ParticleStore& s) {
    std::vector<double> row(3);
    row[0] = time;
    for (std::size_t i = 0; i < s.size(); ++i) {
        row[1] = static_cast<double>(s.id[i]);
        const double values[9] = {s.x[i],
                                  s.y[i],
                                  s.angle[i],
                                  s.vx[i],
                                  s.vy[i],
                                  s.omega[i],
                                  s.fx[i] * s.invMass[i],
                                  s.fy[i] * s.invMass[i],
                                  s.torque[i] * s.invInertia[i]};
        for (std::size_t q = 0; q < 9; ++q) {
            row[2] = values[q];
            m_files[q]->row(row);
        }
    }
}

void ParticleSeries::flush() {
    for (auto& f : m_files) f->flush();
}

}  // namespace granulab::app
