// SPDX-License-Identifier: MIT
// Kinetic-theory reference formulas (edmd spec sections 4.3-4.6, 5.3, 5.5, 5.6, 6 and 9).
//
// Why: everything here is a closed form from the spec, written for general D where the spec
// gives the general form (f_E, l_E, EOS, lambda_cl, lambda_sh, M1(0)) so that the 2D and 3D
// special cases printed in the spec are checks, not inputs. The only numerical method is the
// Riemann zeta function for Eq. 5.48 (Euler-Maclaurin with 8 Bernoulli terms after 16 summands).
#include "edmd/kinetic_theory.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granulab::edmd {

namespace {

int checkedDim(int dim) {
    if (dim != 2 && dim != 3) {
        throw std::invalid_argument("kinetic theory: dimension must be 2 or 3, got " + std::to_string(dim));
    }
    return dim;
}

Real sq(Real x) noexcept {
    return x * x;
}

}  // namespace

// ---- geometry ------------------------------------------------------------------------------

Real unitBallVolume(int dim) {
    // pi^(D/2)/(D/2)! with x! = Gamma(1 + x) (edmd section 6 conventions)
    const Real D = checkedDim(dim);
    return std::pow(kPi, D / 2) / std::tgamma(1 + D / 2);
}

Real volumeFraction(int dim, Real n, Real a, Real boxLength) {
    // edmd Eqs. 4.2-4.4
    return n * std::pow(a / boxLength, dim) * unitBallVolume(dim);
}

Real boxLengthFor(int dim, Real n, Real nu, Real a) {
    return a * std::pow(n * unitBallVolume(dim) / nu, 1.0 / checkedDim(dim));
}

Real opticalDepth(int dim, Real n, Real nu) {
    // edmd Eq. 4.9: l_opt = nu L/(2a), independent of a
    return nu * boxLengthFor(dim, n, nu, 1.0) / 2;
}

// ---- contact value and EOS -----------------------------------------------------------------

Real contactValue(int dim, Real nu) {
    // edmd Eq. 4.52: Henderson (2D), Carnahan-Starling (3D)
    if (checkedDim(dim) == 2) return (1 - 7 * nu / 16) / sq(1 - nu);
    return (1 - nu / 2) / (sq(1 - nu) * (1 - nu));
}

Real compressibilityFactor(int dim, Real nu, Real eps) {
    // edmd Eq. 4.44 (A.36): 1 + (1+eps) 2^(D-2) nu g_2a
    return 1 + (1 + eps) * std::pow(2.0, checkedDim(dim) - 2) * nu * contactValue(dim, nu);
}

Real reducedPressure(int dim, Real nu, Real eps) {
    return compressibilityFactor(dim, nu, eps) - 1;  // edmd Eq. 4.63
}

Real pressure(int dim, Real n, Real volume, Real T, Real nu, Real eps) {
    return n * T / volume * compressibilityFactor(dim, nu, eps);  // edmd Eqs. 4.43-4.44
}

Real hendersonEosCorrected2d(Real nu) {
    return 1 + 2 * nu * ((1 - 7 * nu / 16) / sq(1 - nu) - std::pow(nu, 3) / (64 * sq(sq(1 - nu))));
}

Real virialEos3d(Real nu, int order) {
    if (order < 0 || order > 5) {
        throw std::invalid_argument("virialEos3d: order must be 0..5, got " + std::to_string(order));
    }
    static constexpr std::array<Real, 6> kB{1, 4, 10, 18.36, 28.2, 39.5};  // edmd 4.4 virial series
    Real sum = 0, p = 1;
    for (int k = 0; k <= order; ++k, p *= nu) sum += kB[static_cast<std::size_t>(k)] * p;
    return sum;
}

Real carnahanStarlingSeries3d(Real nu, int order) {
    if (order < 0) throw std::invalid_argument("carnahanStarlingSeries3d: order must be >= 0");
    Real sum = 1, p = 1;
    for (int k = 1; k <= order; ++k) {
        p *= nu;
        sum += Real(k * k + 3 * k) * p;
    }
    return sum;
}

Real freeVolumeReducedPressure(Real nu, Real c0, Real nuMax) {
    return c0 / (nuMax - nu) - 1;  // edmd Eq. 4.67
}

// ---- Enskog kinetics -----------------------------------------------------------------------

Real enskogCollisionFrequency(int dim, Real nu, Real T, Real m, Real a) {
    // edmd Eq. 4.33 (A.26): D 2^(D-1)/(sqrt(pi) a) nu g_2a sqrt(T/m)
    const Real D = checkedDim(dim);
    return D * std::pow(2.0, D - 1) / (std::sqrt(kPi) * a) * nu * contactValue(dim, nu) * std::sqrt(T / m);
}

Real enskogCollisionTime(int dim, Real nu, Real T, Real m, Real a) {
    return 1 / enskogCollisionFrequency(dim, nu, T, m, a);
}

Real meanSpeedThesis(int dim, Real T, Real m) {
    return std::sqrt(std::pow(2.0, checkedDim(dim)) / kPi) * std::sqrt(T / m);  // edmd Eq. 4.37
}

Real meanSpeedExact(int dim, Real T, Real m) {
    // Maxwell in D dimensions: sqrt(2T/m) Gamma((D+1)/2)/Gamma(D/2) (edmd section 9, erratum 3)
    const Real D = checkedDim(dim);
    return std::sqrt(2 * T / m) * std::tgamma((D + 1) / 2) / std::tgamma(D / 2);
}

Real meanFreePath(int dim, Real nu, Real a) {
    // edmd Eq. 4.38: a/(2^((D-2)/2) D nu g_2a)
    const Real D = checkedDim(dim);
    return a / (std::pow(2.0, (D - 2) / 2) * D * nu * contactValue(dim, nu));
}

Real meanFreePathExact(int dim, Real nu, Real a) {
    return meanSpeedExact(dim, 1, 1) / enskogCollisionFrequency(dim, nu, 1, 1, a);
}

// ---- Haff's law ----------------------------------------------------------------------------

Real lambdaFromEps(Real eps) {
    return 1 - eps * eps;
}  // edmd Eq. 4.7
Real epsFromLambda(Real lambda) {
    return std::sqrt(1 - lambda);
}

Real haffTau(int dim, Real lambda, Real t, Real tE) {
    return lambda * t / (2 * checkedDim(dim) * tE);  // edmd Eq. 4.57
}

Real haffTime(int dim, Real lambda, Real tau, Real tE) {
    return 2 * checkedDim(dim) * tE * tau / lambda;
}

Real haffTemperature(Real T0, Real tau) {
    return T0 / sq(1 + tau);
}  // edmd Eqs. 4.58-4.61

Real haffCollisionFrequency(Real fE0, Real tau) {
    return fE0 / (1 + tau);
}  // edmd Eq. 4.62

Real haffCoolingRate(int dim, Real lambda, Real nu, Real T, Real m, Real a) {
    // edmd Eqs. 4.54-4.55: dT/dt = -(lambda/D) f_E(T) T
    return -lambda / checkedDim(dim) * enskogCollisionFrequency(dim, nu, T, m, a) * T;
}

// ---- thresholds ----------------------------------------------------------------------------

Real collapseRestitution(Real lOpt) {
    return sq(std::tan(kPi / 4 * (1 - 1 / lOpt)));
}  // edmd Eq. 4.8

Real clusteringLambda(int dim, Real lOpt) {
    // edmd Eqs. 4.70-4.72, B.25
    const Real D = checkedDim(dim);
    return sq(D + 2) / (D * (D - 1) * std::pow(2.0, 2 * D - 1)) * std::pow(kPi, 3) / sq(lOpt);
}

Real shearLambda(int dim, Real lOpt) {
    // edmd Eqs. 4.73-4.75, B.28
    const Real D = checkedDim(dim);
    return (D + 2) / sq(D) * std::pow(kPi, 3) / (std::pow(2.0, 2 * D - 2) * sq(lOpt));
}

Real tcElasticFraction(Real tc, Real tE) {
    return 1 - std::exp(-2 * tc / tE);
}  // edmd Eq. 4.12

// ---- crossover times -----------------------------------------------------------------------

Real growthTime(int dim, Real tE) {
    return 2 * tE / checkedDim(dim);
}  // edmd Eq. 5.2
Real saturationTime(int dim, Real tE, Real lambdaCl) {
    return 2 * checkedDim(dim) * tE / lambdaCl;  // edmd Eq. 5.3
}
Real homogeneousClusterTime(int dim, Real lambda, Real tE) {
    const Real D = checkedDim(dim);
    return 2 * D * D * D * tE / sq(lambda);  // edmd Eq. 5.4: t_hom^2/t_grw
}
Real homogeneousClusterTau(int dim, Real lambda) {
    return sq(checkedDim(dim)) / lambda;
}  // Eq. 5.6
Real clusterSaturationTime(int dim, Real lambdaCl, Real tE) {
    const Real D = checkedDim(dim);
    return 2 * D * D * D * tE / sq(lambdaCl);  // edmd Eq. 5.5: t_sat^2/t_grw
}
Real clusterSaturationTau(int dim, Real lambda, Real lambdaCl) {
    return sq(checkedDim(dim)) * lambda / sq(lambdaCl);  // edmd Eq. 5.7
}
Real growthEnergy(Real E0, Real t, Real tGrw, Real alpha) {
    return E0 / std::pow(1 + t / tGrw, alpha);
}
Real saturationEnergy(Real E0, Real t, Real tSat) {
    return E0 / sq(1 + t / tSat);
}
Real peakTauFit(Real lambda, Real tau0, Real cTau) {
    return tau0 + cTau * sq(1 - lambda) / lambda;
}

// ---- cluster statistics --------------------------------------------------------------------

Real initialMeanClusterSize(int dim, Real nu, Real deltaOver2a) {
    // edmd Eq. 5.19: 1 + D 2^(D-1) nu g_2a delta/2a (4 in 2D, 12 in 3D)
    const Real D = checkedDim(dim);
    return 1 + D * std::pow(2.0, D - 1) * nu * contactValue(dim, nu) * deltaOver2a;
}

Real percolationTheta(int dim) {
    return checkedDim(dim) == 2 ? 1.0 : 1.5;
}  // Eq. 5.21
Real percolationVartheta(int dim) {
    return checkedDim(dim) == 2 ? 187.0 / 91.0 : 2.2;
}  // Eq. 5.23

Real initialCutoff(int dim, Real nu, Real deltaOver2a, bool withContactValue) {
    // edmd Eq. 5.47
    const Real pre = checkedDim(dim) == 2 ? 8.0 : 24 * std::sqrt(2.0);
    const Real g = withContactValue ? contactValue(dim, nu) : 1.0;
    return -std::log(pre * nu * deltaOver2a * g);
}

Real initialMomentLargeCutoff(int dim, int k, Real w) {
    // edmd Eqs. 5.44-5.45
    if (k != 1 && k != 2) throw std::invalid_argument("initialMomentLargeCutoff: k must be 1 or 2");
    const Real geom = checkedDim(dim) == 2 ? 1.0 : std::sqrt(2.0) / 2;
    const Real coeff = k == 1 ? 0.5 : 1.5;
    return 1 + coeff * geom * std::exp(-w);
}

Real initialMomentSmallCutoff(int dim, int k, Real w) {
    if (k < 1) throw std::invalid_argument("initialMomentSmallCutoff: k must be >= 1");
    return std::pow(w, percolationTheta(dim) - k - 1);  // edmd Eq. 5.46
}

Real riemannZeta(Real s) {
    if (!(s > 1)) throw std::invalid_argument("riemannZeta: s must be > 1, got " + fmt::format("{}", s));
    // Euler-Maclaurin: sum_{n<N} n^-s + N^(1-s)/(s-1) + N^-s/2
    //                  + sum_k B_2k/(2k)! s (s+1) ... (s+2k-2) N^(-s-2k+1)
    constexpr int kN = 16;
    static constexpr std::array<Real, 8> kB2k{1.0 / 6,  -1.0 / 30,     1.0 / 42, -1.0 / 30,
                                              5.0 / 66, -691.0 / 2730, 7.0 / 6,  -3617.0 / 510};
    Real sum = 0;
    for (int n = 1; n < kN; ++n) sum += std::pow(Real(n), -s);
    const Real N = kN;
    sum += std::pow(N, 1 - s) / (s - 1) + std::pow(N, -s) / 2;
    Real rising = s;                   // s (s+1) ... (s+2k-2)
    Real factorial = 2;                // (2k)!
    Real power = std::pow(N, -s - 1);  // N^(-s-2k+1)
    for (int k = 1; k <= static_cast<int>(kB2k.size()); ++k) {
        sum += kB2k[static_cast<std::size_t>(k - 1)] / factorial * rising * power;
        rising *= (s + 2 * k - 1) * (s + 2 * k);
        factorial *= Real(2 * k + 1) * Real(2 * k + 2);
        power /= N * N;
    }
    return sum;
}

Real percolationMeanClusterSize(int dim) {
    const Real v = percolationVartheta(dim);
    return riemannZeta(v - 1) / riemannZeta(v);  // edmd Eq. 5.48
}

Real percolationSecondMoment(int dim, Real n) {
    return std::pow(n, 3 - percolationVartheta(dim));
}  // 5.49

Real lateMeanClusterSize(Real qx) {
    return 1 / (1 - qx);
}  // edmd Eq. 5.50
Real lateSecondMoment(Real qx, Real n) {
    return qx * qx * n / (1 - qx);
}  // edmd Eq. 5.51

Real largestClusterFraction(Real lambda, Real lambdaStar) {
    if (lambda <= lambdaStar) return 0;
    return 1 - std::sqrt(lambdaStar / lambda);  // edmd Eq. 5.41, form of Fig. 5.22
}

// ---- reference curves ----------------------------------------------------------------------

namespace {

void validateSetup(const ReferenceSetup& s) {
    checkedDim(s.dim);
    auto fail = [](const std::string& what) { throw std::invalid_argument("reference curves: " + what); };
    if (!(s.n > 0)) fail(fmt::format("n must be > 0, got {}", s.n));
    if (!(s.nu > 0 && s.nu < 1)) fail(fmt::format("nu must be in (0, 1), got {}", s.nu));
    if (!(s.eps >= 0 && s.eps < 1)) fail(fmt::format("eps must be in [0, 1), got {}", s.eps));
    if (!(s.m > 0)) fail(fmt::format("m must be > 0, got {}", s.m));
    if (!(s.a > 0)) fail(fmt::format("a must be > 0, got {}", s.a));
    if (!(s.T0 > 0)) fail(fmt::format("T0 must be > 0, got {}", s.T0));
}

}  // namespace

ReferenceThresholds referenceThresholds(const ReferenceSetup& s) {
    validateSetup(s);
    ReferenceThresholds r;
    r.g2a = contactValue(s.dim, s.nu);
    r.boxLength = boxLengthFor(s.dim, s.n, s.nu, s.a);
    r.lOpt = opticalDepth(s.dim, s.n, s.nu);
    r.lambda = lambdaFromEps(s.eps);
    r.lambdaCl = clusteringLambda(s.dim, r.lOpt);
    r.lambdaSh = shearLambda(s.dim, r.lOpt);
    r.epsIc = collapseRestitution(r.lOpt);
    r.epsCl = epsFromLambda(r.lambdaCl);
    r.fE0 = enskogCollisionFrequency(s.dim, s.nu, s.T0, s.m, s.a);
    r.tE = 1 / r.fE0;
    r.lE = meanFreePath(s.dim, s.nu, s.a);
    r.tauHc = homogeneousClusterTau(s.dim, r.lambda);
    r.tauCs = clusterSaturationTau(s.dim, r.lambda, r.lambdaCl);
    r.tauPFit = peakTauFit(r.lambda);
    r.tGrw = growthTime(s.dim, r.tE);
    r.tSat = saturationTime(s.dim, r.tE, r.lambdaCl);
    return r;
}

std::string referenceCurvesCsv(const ReferenceSetup& s, std::span<const Real> tau) {
    const ReferenceThresholds r = referenceThresholds(s);
    const Real D = s.dim;
    const Real volume = std::pow(r.boxLength, D);
    const Real E0 = D * s.T0 / 2;  // mean kinetic energy per particle, T = 2E/D
    std::string out = "tau,t,T_haff,E_haff,f_E_haff,l_E,P_haff,E_grw,E_sat\n";
    for (const Real ta : tau) {
        const Real t = haffTime(s.dim, r.lambda, ta, r.tE);
        const Real T = haffTemperature(s.T0, ta);
        const Real E = D * T / 2;
        const Real fE = haffCollisionFrequency(r.fE0, ta);
        const Real P = pressure(s.dim, s.n, volume, T, s.nu, s.eps);
        const Real Egrw = growthEnergy(E0, t, r.tGrw, s.alphaGrowth);
        const Real Esat = saturationEnergy(E0, t, r.tSat);
        out += fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", ta, t,
                           T, E, fE, r.lE, P, Egrw, Esat);
    }
    return out;
}

}  // namespace granulab::edmd
