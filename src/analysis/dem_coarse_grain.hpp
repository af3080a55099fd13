// SPDX-License-Identifier: MIT
// Continuum coarse-graining of a DEM snapshot (the method of Goldhirsch 2010, Weinhart et al.
// 2012, as in MercuryDPM; gc2d spec section 7 items 7-8 give the test-area alternative): density,
// momentum, velocity, kinetic and contact stress as smooth fields at arbitrary points.
//
// Fields at r [m], phi the kernel [1/m^2], sums over grains i and contacts k:
//   rho(r) = sum m_i phi(r - r_i)                         [kg/m^2]
//   j(r)   = sum m_i v_i phi(r - r_i)                      [kg/(m s)],  v(r) = j / rho  [m/s]
//   sigma^k(r) = sum m_i v'_i v'_i phi(r - r_i), v'_i = v_i - v(r)   [N/m]
//   sigma^c(r): compressive-positive contact stress [N/m]. Contact k acts at c_k with force F on a
//   (centre r_a) and -F on b (centre r_b); branch vectors b_a = c_k - r_a, b_b = c_k - r_b:
//     sigma^c_ab(r) = - sum_k [ F_a b_a,b I_a(r) - F_a b_b,b I_b(r) ],
//     I_x(r) = int_0^1 phi(r - r_x - s b_x) ds  (the line from the grain centre to the contact).
//   A wall contact has only the a term. Derivation: d/ds phi(r - r_a - s b_a) = -div_r(b_a phi), so
//   F phi(r - r_a) - F phi(r - c) = div(F (x) b_a I_a); the phi(r - c) terms of a and b cancel.
//   Hence the momentum balance (statics, d/dx_b = divergence over the second index):
//     d_b sigma^c_ab(r) = - f^c_a(r) + f^w_a(r),
//     f^c(r) = sum_i F^c_i phi(r - r_i) (contact force density on the grains)       [N/m^2]
//     f^w(r) = sum_wall contacts F_k phi(r - c_k) (force density the walls exert at their
//              contact points, the boundary term of Weinhart et al. 2012)          [N/m^2]
//   For round grains c_k lies on the centre line, b_a - b_b = r_b - r_a is the usual branch vector,
//   and sigma^c = -sum_k F (x) (r_b - r_a)-line integral, the Goldhirsch form with f_ij (x) r_ij.
//   For polygons sigma^c need not be symmetric (the column index is the branch direction).
//
// Kernels (both normalised: int phi dA = 1 in 2D):
//   Gaussian, width w: phi = exp(-r^2 / (2 w^2)) / (2 pi w^2 (1 - exp(-9/2))), cut off at r = 3w
//     (the denominator renormalises the truncated kernel; the jump at the cutoff, 1.1 % of the
//     peak, is handled exactly by splitting the line integrals there).
//   Lucy, support c: phi = 5/(pi c^2) (1 + 3 r/c) (1 - r/c)^3 for r < c, 0 beyond; its integral
//     2 pi int_0^c r phi dr = 10 int_0^1 s (1 + 3s)(1 - s)^3 ds = 10 (1/2 - 3/2 + 8/5 - 1/2) = 1.
// Width rule: w ~ d/2 for the Gaussian (c ~ 2 d for Lucy, whose standard deviation is ~c/4),
//   d the mean grain diameter. Weinhart et al. (2012, 2016) find the fields nearly independent of
//   w for d/4 <= w <= d: below d/4 the single-particle layering and the discreteness of the
//   contacts show through, above ~d the averaging smears real gradients (walls, shear bands) over
//   several layers. Use larger w for noisy snapshots and to reach 100-200 grains per kernel.
// Line integrals: split at the closest approach to r and at the kernel's cutoff, then Gauss-
//   Legendre with `quadraturePoints` nodes per piece; each piece's integrand is smooth, so 16
//   nodes give ~1e-12 relative accuracy.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

enum class CoarseKernel { Gaussian, Lucy };

struct CoarseGrainParams {
    CoarseKernel kernel = CoarseKernel::Gaussian;
    Real width = 0;                     ///< [m] Gaussian: w (cutoff 3w); Lucy: support c
    std::size_t quadraturePoints = 16;  ///< Gauss-Legendre nodes per smooth piece of a line integral
};

/// Kernel value phi(r) [1/m^2] at distance r [m]; support radius [m] (3w or c).
Real kernelValue(const CoarseGrainParams& params, Real r);
Real kernelCutoff(const CoarseGrainParams& params);

/// Fields at each of `points` (all vectors have one value per point); z is the vertical (y) axis.
struct CoarseGrainFields {
    std::vector<Vec2> points;              ///< [m]
    std::vector<Real> rho;                 ///< [kg/m^2]
    std::vector<Real> jx, jz;              ///< [kg/(m s)] momentum density
    std::vector<Real> vx, vz;              ///< [m/s] j / rho (NaN where rho = 0)
    std::vector<Real> kxx, kxz, kzz;       ///< [N/m] kinetic stress (0 where rho = 0)
    std::vector<Real> cxx, cxz, czx, czz;  ///< [N/m] contact stress, compressive-positive
    std::vector<Real> fcx, fcz;            ///< [N/m^2] contact force density on the grains f^c
    std::vector<Real> fwx, fwz;            ///< [N/m^2] wall force density at the wall contacts f^w
    std::vector<std::string> notes;
};

/// Coarse-grained fields of the snapshot at `points`. Cost O((N + contacts) x points within the
/// cutoff), with the points binned in cells of the cutoff size. Throws std::invalid_argument for
/// width <= 0, quadraturePoints = 0 or a contact naming an unknown grain id.
CoarseGrainFields coarseGrain(const GrainFrame& grains, const ContactFrame& contacts,
                              const std::vector<Vec2>& points, const CoarseGrainParams& params);

/// The points of a regular nx x ny grid from (x0, y0) with spacing dx, dy [m], x fastest.
std::vector<Vec2> gridPoints(Vec2 origin, Real dx, Real dy, std::size_t nx, std::size_t ny);

/// Table "coarse_grain": x, z [m], rho [kg/m^2], v_x, v_z [m/s], sigmak_xx, sigmak_xz, sigmak_zz,
/// sigmac_xx, sigmac_xz, sigmac_zx, sigmac_zz, sigma_xx, sigma_zz [N/m] (total = kinetic +
/// contact); notes: kernel and width.
Table coarseGrainTable(const CoarseGrainFields& fields, const CoarseGrainParams& params);

}  // namespace granulab::analysis
