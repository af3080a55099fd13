// SPDX-License-Identifier: MIT
// Initial states of a hard-sphere gas (edmd spec 4.2, checklist item 18): particles on a simple
// cubic (square) lattice or placed at random without overlap, radii constant or uniform in a
// range, Maxwell velocities at temperature T0 with zero total momentum. Pure functions of the
// specification and the seed (same input, same state on every machine).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "edmd/kinematics.hpp"

namespace granulab::edmd {

enum class Placement : std::uint8_t { Lattice, Random };

struct InitialStateSpec {
    std::array<Real, 3> box{1, 1, 1};                ///< [m]
    std::array<bool, 3> periodic{true, true, true};  ///< false: walls at 0 and box (keep a radius away)
    std::uint64_t count = 0;
    Real radius = 0;     ///< [m] radius (lower bound when radiusMax > radius)
    Real radiusMax = 0;  ///< [m] radii uniform in [radius, radiusMax] when larger than radius
    Real mass = 1;       ///< [kg] mass of a particle of radius `radius`; others scale as (r/radius)^D
    Placement placement = Placement::Lattice;
    Real temperature = 1;  ///< [J] T0 = m <v_x^2> (k_B = 1); the sample is rescaled to exactly T0
    std::uint64_t seed = 1;
};

template <int D>
struct GasState {
    std::vector<VecD<D>> x, v;       ///< [m], [m/s]
    std::vector<Real> radius, mass;  ///< [m], [kg]
};

/// Builds the state; throws std::invalid_argument with a clear reason when the particles do not
/// fit (lattice spacing below a diameter, random placement failing to find room).
template <int D>
GasState<D> makeInitialState(const InitialStateSpec& spec);

/// The standard gas of the tests and benchmarks: `count` particles of radius 1 and mass 1 at
/// T = 1 on the lattice (spec 4.2 steps 1-2) in a periodic cube of edge unitLatticeEdge [m] holding
/// them at volume fraction nu.
template <int D>
GasState<D> unitLatticeGas(std::uint64_t count, Real nu, std::uint64_t seed);
/// [m] edge of the cube of unitLatticeGas.
Real unitLatticeEdge(int dim, std::uint64_t count, Real nu);

/// Volume (2D: area) of a D-ball of radius a [m^D].
inline Real ballVolume(int dim, Real a) noexcept {
    return dim == 2 ? kPi * a * a : 4.0 / 3.0 * kPi * a * a * a;
}

}  // namespace granulab::edmd
