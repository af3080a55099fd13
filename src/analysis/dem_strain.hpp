// SPDX-License-Identifier: MIT
// Displacement, strain and plane-strain elastic constants of a pile on the stress grid (gc2d spec
// section 7 item 10, Sec. 4.3.3, Eq. 4.2-4.5 and 4.11).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/dem_stress.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// Per test area of the stress grid (z = vertical y). Displacement u = x(reference, g ~ 0) -
/// x(loaded, g = 9.81): the negative of the physical displacement (spec 7 item 10), so u_xx, u_zz
/// are compressive-positive strains like the compressive-positive stresses.
struct StrainGrid {
    TestAreaGrid grid;
    std::vector<Real> ux, uz;    ///< [m] mean over the grains whose loaded centre is in the area
    std::vector<Real> uxx, uzz;  ///< [1] central differences; NaN on the grid's rim
    std::vector<Real> nu;        ///< [1] Eq. 4.2-4.4
    std::vector<Real> E;         ///< [N/m] Eq. 4.5
    std::vector<Real> K;         ///< [N/m] Eq. 4.11
    std::vector<std::size_t> grains;
    Real nuMean = 0, nuStd = 0, EMean = 0, EStd = 0, KMean = 0, KStd = 0;  ///< over finite values
    std::vector<std::string> notes;
};

/// Strain and elastic constants. Grains are matched by id (loaded grains missing in the reference
/// are skipped and counted in a note). u_xx(i, j) = (u_x(i+1, j) - u_x(i-1, j)) / (2 sx),
/// u_zz(i, j) = (u_z(i, j+1) - u_z(i, j-1)) / (2 sy) (quadratic terms neglected); then, with the
/// loaded state's compressive stress,
///   nu = (s_zz u_xx - s_xx u_zz) / ((u_xx - u_zz)(s_xx + s_zz))       (Eq. 4.2-4.4)
///   E  = s_xx (1 + nu)(1 - 2 nu) / (u_xx (1 - nu) + nu u_zz)         (Eq. 4.5)
///   K  = E / (2 (1 + nu)(1 - 2 nu))                                   (Eq. 4.11)
/// Values are NaN where an input is NaN or a denominator vanishes. Throws std::invalid_argument if
/// the stress grid's vectors do not match its grid.
StrainGrid strainGrid(const GrainFrame& reference, const GrainFrame& loaded, const StressGrid& stress);

/// Table "elastic": x, z [m], u_x, u_z [m], u_xx, u_zz [1], sigma_xx, sigma_zz [N/m], nu [1],
/// E, K [N/m]; notes "nu_avg = m +- s", "E_avg = ...", "K_avg = ..." and the strain notes.
Table strainTable(const StrainGrid& strain, const StressGrid& stress);

}  // namespace granulab::analysis
