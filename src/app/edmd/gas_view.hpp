// SPDX-License-Identifier: MIT
// What the edmd outputs read of the gas, whichever engine runs it (app/edmd/serial_gas.hpp, one
// process; app/edmd/parallel_gas.hpp, MPI ranks): the particles at the current time in id order,
// their energies, and the checkpoint that does not depend on the number of ranks (edmd spec 3.4
// and 3.8; issue 15). Both engines fill the same view, so series rows, snapshots and final.csv
// are computed by one code path and agree bit for bit for the same state.
#pragma once
#include <array>
#include <cstdint>
#include <iosfwd>
#include <vector>

#include "edmd/engine.hpp"

namespace granulab::app {

/// Every particle at the current time, in id order (filled on the root rank only).
template <int D>
struct GasView {
    Real time = -1;                         ///< [s] the state it shows (-1: not filled)
    std::uint64_t events = 0;               ///< events executed at that state (all ranks)
    std::vector<edmd::VecD<D>> x, v;        ///< [m] wrapped into the box on periodic axes; [m/s]
    std::vector<edmd::Vec3> omega;          ///< [rad/s] (rough spheres; zero otherwise)
    std::vector<Real> radius, mass;         ///< [m] current radius; [kg]
    std::vector<std::uint32_t> collisions;  ///< collisions of each particle since t = 0

    std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(radius.size()); }
    void resize(std::uint32_t n) {
        x.resize(n);
        v.resize(n);
        omega.resize(n);
        radius.resize(n);
        mass.resize(n);
        collisions.resize(n);
    }
    /// Particle i from a record extrapolated to the current time (ParallelEngine::gatherNow).
    void setFromRecord(std::uint32_t i, const edmd::ParticleRecord& r, Real growthRate, Real now) {
        for (int d = 0; d < D; ++d) {
            x[i][d] = r.x[d];
            v[i][d] = r.v[d];
        }
        omega[i] = edmd::Vec3{{r.omega[0], r.omega[1], r.omega[2]}};
        radius[i] = r.radius0 + growthRate * now;
        mass[i] = r.mass;
        collisions[i] = r.counter;
    }
};

/// Energies [J] and momentum [kg m/s] of a view: sums in id order, so that the serial and the
/// parallel engine give the same bits for the same state.
struct GasEnergies {
    Real kinetic = 0, rotational = 0, potential = 0;
    std::array<Real, 3> momentum{};
};

template <int D>
GasEnergies gasEnergies(const GasView<D>& view, const edmd::EngineConfig& config);

/// The engine state of an edmd checkpoint: the summed globals, the grid it ran on and every
/// particle's record (events as scheduled), sorted by id; written by one rank or by the root of
/// many, and read by any number of ranks (a run checkpointed on 4 ranks resumes on 1, 2 or 3).
struct GasCheckpoint {
    edmd::EngineGlobals globals;
    std::array<int, 3> cells{1, 1, 1};
    std::vector<edmd::ParticleRecord> records;
};

void writeGasCheckpoint(std::ostream& out, int dimension, const GasCheckpoint& state);
/// Throws std::runtime_error (with what to do) for another dimension or an older format.
GasCheckpoint readGasCheckpoint(std::istream& in, int dimension);

}  // namespace granulab::app
