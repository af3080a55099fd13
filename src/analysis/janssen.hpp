// SPDX-License-Identifier: MIT
// Janssen theory of silo stresses in 2D (gc2d spec section 7 item 9, section 8.3, Ch. 3): closed
// forms for straight, stepped, slanted and parabolic silos, the general numerical integration of
// Eq. 3.11/3.12 for any half-width r(z), least-squares fits of k and mu_j to measured profiles,
// and the depth profile of a stress grid. Depth z [m] downward from the free surface; rho [kg/m^2]
// is the effective bulk areal density (rho_rel x grain areal density), g [m/s^2]; stresses in N/m.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "analysis/dem_stress.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// Silo half-width r(z) [m].
struct SiloShape {
    enum class Kind { Straight, Stepped, Slanted, Parabolic, General };
    Kind kind = Kind::Straight;
    Real r = 0;           ///< [m] straight
    Real r1 = 0, r2 = 0;  ///< [m] stepped: r1 above the step, r2 below (r1 > r2)
    Real h0 = 0;          ///< [m] stepped: depth of the step
    Real a = 0,
         b = 0;  ///< slanted r = a z + b (a [1], b [m]); parabolic r = sqrt((b - z)/a) (a [1/m], b [m])
    std::function<Real(Real)> radius;  ///< general: r(z) [m]
    std::function<Real(Real)> slope;   ///< general: r'(z) [1]; empty: central differences
    std::vector<Real> breakpoints;     ///< general: depths [m] where r or r' jumps (r' = 0 across a step)

    Real halfWidth(Real z) const;       ///< r(z) [m] for every kind
    Real halfWidthSlope(Real z) const;  ///< r'(z) [1] (one-sided at breakpoints, from below)
};
SiloShape straightSilo(Real r);
SiloShape steppedSilo(Real r1, Real r2, Real h0);  ///< throws unless r1 > r2 > 0, h0 > 0
SiloShape slantedSilo(Real a, Real b);             ///< throws unless b > 0
SiloShape parabolicSilo(Real a, Real b);           ///< throws unless a > 0, b > 0
SiloShape generalSilo(std::function<Real(Real)> radius, std::function<Real(Real)> slope = {},
                      std::vector<Real> breakpoints = {});

struct JanssenParams {
    Real k = 0;     ///< sigma_xx / sigma_zz [1]
    Real mu = 0;    ///< wall friction mu_j [1]
    Real rho = 0;   ///< [kg/m^2]
    Real g = 9.81;  ///< [m/s^2]
};

/// sigma_zz(z) [N/m] from the closed form of the shape (spec 8.3): straight
/// rho g r/(k mu) (1 - exp(-k mu z/r)); stepped the straight form with r1 above h0 and its
/// continuation below (sigma_xx / k of Eq. 3.15); slanted the corrected Eq. 3.17/3.18
/// alpha rho g/(C + alpha a) [(b + a z) - (b + a z)^(-C/(alpha a)) b^((C + alpha a)/(alpha a))],
/// alpha = (1 + a^2)^(3/2), C = mu (a^2 + k) (a = 0: straight); parabolic exp(-mu xi) rho g
/// int_0^z exp(mu xi) with the closed-form xi of spec 8.3 and the integral by composite
/// Gauss-Legendre (1e-12); general: janssenNumeric. NaN where r(z) <= 0 (past a tip or vertex).
/// Throws std::invalid_argument unless k, mu, rho, g > 0 and z >= 0.
Real janssenSigmaZz(const SiloShape& shape, const JanssenParams& p, Real z);
/// sigma_xx(z) = k sigma_zz(z) [N/m]; the stepped silo uses the printed Eq. 3.15 (identical).
Real janssenSigmaXx(const SiloShape& shape, const JanssenParams& p, Real z);

/// xi(z) of Eq. 3.12 for the parabolic silo [1]: the spec's antiderivative
/// (1 - 4kab + 4kaz - 2k)/sqrt(4ab - 4az + 1) minus its value at z = 0.
Real parabolicXi(Real k, Real a, Real b, Real z);
/// Near-surface equivalent straight radius of the parabolic silo [m]:
/// r_P = k (1 + 4ab)^(3/2) / (2a (1 + 4kab)).
Real parabolicEffectiveRadius(Real k, Real a, Real b);

/// sigma_zz at each depth of ascending `z` by integrating Eq. 3.11/3.12 as the ODE
/// d sigma/dz = rho g - mu xi'(z) sigma, sigma(0) = 0, xi' = (r'^2 + k)/(r (1 + r'^2)^(3/2)), with
/// classical RK4 of at most `step` [m], restarted at the shape's breakpoints (a step in r adds
/// nothing to xi). Uses shape.halfWidth / halfWidthSlope, so it cross-checks every closed form.
std::vector<Real> janssenNumeric(const SiloShape& shape, const JanssenParams& p, const std::vector<Real>& z,
                                 Real step = 1e-4);

/// Least-squares fit of k and mu_j to measured sigma_xx(z) and sigma_zz(z) [N/m] at depths z [m]
/// (both profiles together). Residuals (sigma_xx,i - k sigma_zz(z_i))/s_xx and
/// (sigma_zz,i - sigma_zz(z_i))/s_zz with s = the root mean square of each measured profile, so
/// both profiles weigh equally whatever their magnitude; NaN samples are skipped. Levenberg-
/// Marquardt in (ln k, ln mu) (keeps both positive) with a central-difference Jacobian.
struct JanssenFit {
    Real k = 0, mu = 0;
    Real rms = 0;  ///< root mean square of the weighted residuals [1]
    std::size_t iterations = 0;
    bool converged = false;
};
/// Throws std::invalid_argument for mismatched lengths, fewer than 3 finite samples, rho or g <= 0,
/// or a start with k or mu <= 0.
JanssenFit fitJanssen(const SiloShape& shape, const std::vector<Real>& z, const std::vector<Real>& sigmaXx,
                      const std::vector<Real>& sigmaZz, Real rho, Real g, Real kStart = 0.3,
                      Real muStart = 0.3);

/// Stress grid rows as depth profiles: depth z = surfaceY - (row centre y) [m], sigma_xx and
/// sigma_zz averaged over the row's areas with finite stress; rows without any are dropped. Also
/// k = sigma_xx/sigma_zz over all areas with finite stress and sigma_zz != 0 (spec 7 item 9).
struct DepthProfile {
    std::vector<Real> z, sigmaXx, sigmaZz;  ///< ascending z
    std::vector<std::size_t> areas;         ///< areas averaged per row
    Real kMean = 0, kStd = 0;               ///< NaN when no area qualifies
};
DepthProfile depthProfile(const StressGrid& stress, Real surfaceY);

/// Table "janssen": z [m], sigma_xx, sigma_zz, sigma_xx_theory, sigma_zz_theory [N/m]; notes
/// "k = ...", "mu_j = ...", "rho = ... [kg/m^2]", "g = ... [m/s^2]", the fit's rms and the grid's
/// "k_areas = mean +- std".
Table janssenTable(const DepthProfile& profile, const SiloShape& shape, const JanssenFit& fit, Real rho,
                   Real g);

}  // namespace granulab::analysis
