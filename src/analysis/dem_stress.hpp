// SPDX-License-Identifier: MIT
// Coarse-grained stress tensor of a DEM snapshot on a grid of rectangular test areas (gc2d spec
// section 7 items 7-8, Sec. 2.3.4, Eq. 2.52) and its principal axes.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/dem_grid.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

struct StressParams {
    /// Areas holding fewer grains are counted in a note (spec 7 item 7: rule of thumb 100-200).
    std::size_t minGrains = 100;
};

/// Principal values of a symmetric 2x2 stress (compressive-positive) and the major axis' angle.
struct PrincipalStress {
    Real major = 0;  ///< [N/m] larger principal value
    Real minor = 0;  ///< [N/m] smaller principal value
    /// [deg] in (-90, 90]: angle from the vertical (+z) to the major axis, positive when the axis
    /// leans toward +x (the axis is (sin psi, cos psi)). 0 for an isotropic tensor.
    Real psi = 0;
};
PrincipalStress principalStress(Real sxx, Real szz, Real sxz);

/// Stress per test area, compressive-positive (the thesis' plots: -sigma of Eq. 2.52), in N/m.
struct StressGrid {
    TestAreaGrid grid;
    std::vector<Real> sigmaXx, sigmaZz, sigmaXz;  ///< [N/m]; z is the vertical (y) axis
    std::vector<Real> major, minor;               ///< [N/m] principal values
    std::vector<Real> psi;                        ///< [deg] major axis vs vertical (PrincipalStress)
    std::vector<Real> hullArea;                   ///< [m^2] V: hull of the force application points
    std::vector<std::size_t> grains, forces;      ///< grains with centroid inside, forces on them
    std::vector<std::string> notes;
};

/// Stress on every area of `grid` (spec 7 item 7, Eq. 2.52): the grains whose centre lies in the
/// (half-open) rectangle, and every force acting on them (a grain pair contributes F to a if a is
/// inside and -F to b if b is inside, both at the contact point; a wall contact its force on a),
/// lever arms x from the area's centre, sigma_ij = 1/(2V) sum (x_i F_j + x_j F_i) with V the convex-
/// hull area of the application points; reported as -sigma. Gravity is not a contact and is not
/// summed. Areas with V = 0 (fewer than 3 non-collinear points) get NaN fields (noted).
/// Throws std::invalid_argument for a bad grid or a contact naming a grain id not in `grains`.
/// Cost O(N x areas per grain + contacts).
StressGrid stressGrid(const GrainFrame& grains, const ContactFrame& contacts, const TestAreaGrid& grid,
                      const StressParams& params = {});

/// Table "stress": x, z [m] (area centre), sigma_xx, sigma_zz, sigma_xz, sigma_major, sigma_minor
/// [N/m], psi [deg], V [m^2], grains, forces [1]; notes: grid geometry and the stress notes.
Table stressTable(const StressGrid& stress);

}  // namespace granulab::analysis
