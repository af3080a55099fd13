// SPDX-License-Identifier: MIT
// Kinetic-theory reference formulas for freely cooling hard disks (D = 2) and spheres (D = 3):
// volume fraction, contact value, Enskog collision frequency, mean free path, equation of state,
// Haff's law, instability thresholds, crossover times and cluster-moment estimates
// (edmd spec sections 4.3-4.6, 5.3, 5.5, 5.6, 6 and errata 3, 6, 7 of section 9).
//
// Units: the spec sets m = a = k_B = 1; these functions take mass m [kg], radius a [m] and
// temperature T [J] (k_B = 1, T = 2<E>/D) explicitly. Every function that takes `dim` throws
// std::invalid_argument unless dim is 2 or 3. All functions are pure and thread-safe.
#pragma once
#include <span>
#include <string>

#include "core/types.hpp"

namespace granulab::edmd {

// ---- geometry (edmd 4.1, A.12) -------------------------------------------------------------

/// Volume of the unit D-ball, pi^(D/2)/(D/2)! (pi in 2D, 4 pi/3 in 3D).
Real unitBallVolume(int dim);
/// Volume fraction nu = N (a/L)^D pi^(D/2)/(D/2)! of n particles of radius a [m] in a periodic
/// box of edge boxLength [m] (edmd Eqs. 4.2-4.4). Dimensionless.
Real volumeFraction(int dim, Real n, Real a, Real boxLength);
/// Inverse of volumeFraction: box edge L [m] holding n particles of radius a at volume fraction nu.
Real boxLengthFor(int dim, Real n, Real nu, Real a);
/// Optical depth l_opt = nu L/(2a) = sqrt(N nu pi/4) (2D), (N nu^2 pi/6)^(1/3) (3D)
/// (edmd Eq. 4.9). Dimensionless.
Real opticalDepth(int dim, Real n, Real nu);

// ---- contact value and equation of state (edmd 4.4-4.5) ------------------------------------

/// Contact value of the pair correlation g_2a(nu): Henderson (1 - 7nu/16)/(1 - nu)^2 in 2D,
/// Carnahan-Starling (1 - nu/2)/(1 - nu)^3 in 3D (edmd Eq. 4.52). Precondition 0 <= nu < 1.
Real contactValue(int dim, Real nu);
/// Compressibility factor P V/(N T) = 1 + (1 + eps) 2^(D-2) nu g_2a(nu) of the inelastic
/// hard-sphere gas (edmd Eq. 4.44; A.36). eps = 1 gives the elastic EOS (Eq. 4.45).
Real compressibilityFactor(int dim, Real nu, Real eps = 1);
/// Reduced pressure P_red = P V/(N T) - 1 (edmd Eq. 4.63) from compressibilityFactor.
Real reducedPressure(int dim, Real nu, Real eps = 1);
/// Pressure P [J/m^D] = (n T/volume) PV/(NT) of n particles at temperature T [J] in volume
/// [m^D] (edmd Eqs. 4.43-4.44).
Real pressure(int dim, Real n, Real volume, Real T, Real nu, Real eps = 1);
/// Henderson 2D EOS with the nu^3 correction term, P V/(N T) =
/// 1 + 2 nu [(1 - 7nu/16)/(1 - nu)^2 - (1/64) nu^3/(1 - nu)^4] (edmd section 4.4, Eqs. 4.47-4.52).
Real hendersonEosCorrected2d(Real nu);
/// 3D virial series P V/(N T) = 1 + 4nu + 10nu^2 + 18.36nu^3 + 28.2nu^4 + 39.5nu^5, truncated
/// after the nu^order term, 0 <= order <= 5 (edmd section 4.4, Eqs. 4.47-4.52).
Real virialEos3d(Real nu, int order = 5);
/// Resummed 3D series 1 + sum_{n=1}^{order} (n^2 + 3n) nu^n whose infinite sum is
/// Carnahan-Starling (edmd section 4.4, Eqs. 4.47-4.52). order >= 0.
Real carnahanStarlingSeries3d(Real nu, int order);
/// High-density free-volume fit P_red = c0/(nuMax - nu) - 1 (edmd Eq. 4.67); defaults are the
/// thesis fit c0' = 1.65, nu_max = 0.683 (3D, N = 8000). Precondition nu < nuMax.
Real freeVolumeReducedPressure(Real nu, Real c0 = 1.65, Real nuMax = 0.683);

// ---- Enskog kinetics (edmd 4.4, A.1) --------------------------------------------------------

/// Enskog collision frequency per particle f_E = D 2^(D-1)/(sqrt(pi) a) nu g_2a sqrt(T/m) [1/s]
/// (edmd Eq. 4.33; A.26). f_E = (2/N) dC/dt.
Real enskogCollisionFrequency(int dim, Real nu, Real T, Real m, Real a);
/// Enskog collision time t_E = 1/f_E [s] (edmd Eq. 4.34).
Real enskogCollisionTime(int dim, Real nu, Real T, Real m, Real a);
/// Mean speed with the thesis prefactor, v_bar = sqrt(2^D/pi) sqrt(T/m) [m/s] (edmd Eq. 4.37).
/// Exact in 3D only; 10 % low in 2D (edmd section 9, erratum 3). Use it to reproduce Fig. 5.6.
Real meanSpeedThesis(int dim, Real T, Real m);
/// Exact Maxwell mean speed: sqrt(pi T/(2m)) in 2D, sqrt(8 T/(pi m)) in 3D [m/s]
/// (edmd section 9, erratum 3).
Real meanSpeedExact(int dim, Real T, Real m);
/// Mean free path with the thesis mean speed, l_E = v_bar/f_E = a/(2^((D-2)/2) D nu g_2a) [m]
/// (edmd Eq. 4.38). Independent of T and m.
Real meanFreePath(int dim, Real nu, Real a);
/// Mean free path with the exact mean speed, meanSpeedExact/f_E [m] (erratum 3; 2D: +11 %).
Real meanFreePathExact(int dim, Real nu, Real a);

// ---- homogeneous cooling, Haff's law (edmd 4.4 Eqs. 4.54-4.62, A.3) ------------------------

/// lambda = 1 - eps^2 (edmd Eq. 4.7).
Real lambdaFromEps(Real eps);
/// eps = sqrt(1 - lambda), inverse of lambdaFromEps. Precondition 0 <= lambda <= 1.
Real epsFromLambda(Real lambda);
/// Scaled time tau = lambda t/(2 D t_E), t [s], tE = initial Enskog time [s] (edmd Eq. 4.57).
Real haffTau(int dim, Real lambda, Real t, Real tE);
/// Inverse of haffTau: t = 2 D t_E tau/lambda [s]. Precondition lambda > 0.
Real haffTime(int dim, Real lambda, Real tau, Real tE);
/// Haff's law T(tau) = T0/(1 + tau)^2 [J]; the same factor applies to E and P (edmd Eqs. 4.58-4.61).
Real haffTemperature(Real T0, Real tau);
/// f_E(tau) = f_E(0)/(1 + tau) [1/s]; v_bar scales alike, l_E stays constant (edmd Eq. 4.62).
Real haffCollisionFrequency(Real fE0, Real tau);
/// Homogeneous cooling rate dT/dt = -(lambda/D) f_E(T) T [J/s] (edmd Eqs. 4.54-4.55, A.44-A.45
/// with the sqrt(pi m) a reading of erratum 7).
Real haffCoolingRate(int dim, Real lambda, Real nu, Real T, Real m, Real a);

// ---- collapse and instability thresholds (edmd 4.3, 4.6, Appendix B) -----------------------

/// Critical restitution for inelastic collapse eps_ic = tan^2(pi/4 (1 - 1/l_opt)) (edmd Eq. 4.8);
/// collapse is possible for eps < eps_ic. Precondition lOpt >= 1.
Real collapseRestitution(Real lOpt);
/// Clustering threshold lambda_cl = (D+2)^2/(D (D-1) 2^(2D-1)) pi^3/l_opt^2
/// (edmd Eqs. 4.70-4.72, B.25): pi^3/l^2 (2D), 25 pi^3/(192 l^2) (3D).
Real clusteringLambda(int dim, Real lOpt);
/// Shear-instability threshold lambda_sh = (D+2)/D^2 pi^3/(2^(2D-2) l_opt^2)
/// (edmd Eqs. 4.73-4.75, B.28): pi^3/(4 l^2) (2D), 5 pi^3/(144 l^2) (3D).
Real shearLambda(int dim, Real lOpt);
/// Fraction of collisions made elastic by the TC rule, c_e = 1 - exp(-2 t_c/t_E) (edmd Eq. 4.12).
Real tcElasticFraction(Real tc, Real tE);

// ---- cooling regimes and crossover times (edmd 5.3 Eqs. 5.2-5.7; 5.5 Eq. 5.15) -------------

/// Growth-regime time scale t_grw = (2/D) t_E [s] (edmd Eq. 5.2).
Real growthTime(int dim, Real tE);
/// Saturation time scale t_sat = 2 D t_E/lambda_cl [s] (edmd Eq. 5.3).
Real saturationTime(int dim, Real tE, Real lambdaCl);
/// Homogeneous-to-cluster crossover t_hc = 2 D^3 t_E/lambda^2 [s] (edmd Eq. 5.4).
Real homogeneousClusterTime(int dim, Real lambda, Real tE);
/// tau_hc = D^2/lambda (edmd Eq. 5.6).
Real homogeneousClusterTau(int dim, Real lambda);
/// Cluster-to-saturation crossover t_cs = 2 D^3 t_E/lambda_cl^2 [s] (edmd Eq. 5.5).
Real clusterSaturationTime(int dim, Real lambdaCl, Real tE);
/// tau_cs = D^2 lambda/lambda_cl^2 (edmd Eq. 5.7).
Real clusterSaturationTau(int dim, Real lambda, Real lambdaCl);
/// Growth-regime energy E_grw(t) = E0/(1 + t/t_grw)^alpha (edmd Eq. 5.2; alpha ~ 1, 3D fit 1.1).
Real growthEnergy(Real E0, Real t, Real tGrw, Real alpha = 1);
/// Saturation energy E_sat(t) = E0/(1 + t/t_sat)^2 (edmd Eq. 5.3).
Real saturationEnergy(Real E0, Real t, Real tSat);
/// Fit of the peak time of M'_2 (3D, N = 512000, nu = 0.25):
/// tau_p = tau0 + cTau (1 - lambda)^2/lambda (edmd Eq. 5.15; tau0 = 0.24 +- 0.02, c = 40 +- 5).
Real peakTauFit(Real lambda, Real tau0 = 0.24, Real cTau = 40);

// ---- cluster statistics (edmd 5.5 Eq. 5.19, 5.6 Eqs. 5.20-5.52) -----------------------------

/// Initial mean cluster size M1(0) ~ 1 + D 2^(D-1) nu g_2a delta/(2a): 4 nu g (2D), 12 nu g (3D)
/// times delta/(2a) (edmd Eqs. 5.16-5.19; assumes nu << 1 and only 1- and 2-clusters).
Real initialMeanClusterSize(int dim, Real nu, Real deltaOver2a = 0.1);
/// Percolation exponent theta below the threshold: 1 (2D), 3/2 (3D) (edmd Eqs. 5.20-5.21).
Real percolationTheta(int dim);
/// Percolation exponent vartheta at the threshold: 187/91 (2D), 2.2 (3D) (edmd Eqs. 5.22-5.23).
Real percolationVartheta(int dim);
/// Low-density cut-off of the initial distribution, w = -ln(8 nu delta/2a) (2D),
/// -ln(24 sqrt2 nu delta/2a) (3D) (edmd Eq. 5.47); withContactValue multiplies the argument of
/// the logarithm by g_2a(nu) (the spec's "2.17 if g_2a is included").
Real initialCutoff(int dim, Real nu, Real deltaOver2a = 0.1, bool withContactValue = false);
/// Initial moments for w >> 1: M1 ~ 1 + (1/2) e^-w (2D), 1 + (1/2)(sqrt2/2) e^-w (3D); M2 with
/// 3/2 in place of 1/2 (edmd Eqs. 5.44-5.45). k must be 1 or 2.
Real initialMomentLargeCutoff(int dim, int k, Real w);
/// Scaling for w << 1: M_k(0) ~ w^(theta - k - 1), prefactor 1 (edmd Eq. 5.46). k >= 1.
Real initialMomentSmallCutoff(int dim, int k, Real w);
/// Riemann zeta(s) for real s > 1, by Euler-Maclaurin summation (relative error ~1e-15).
/// Throws std::invalid_argument for s <= 1.
Real riemannZeta(Real s);
/// Mean cluster size at percolation M1 <~ zeta(vartheta - 1)/zeta(vartheta): 11.77 (2D),
/// 3.75 (3D) (edmd Eq. 5.48).
Real percolationMeanClusterSize(int dim);
/// Scaling of M2 at percolation, N^(3 - vartheta) (edmd Eq. 5.49).
Real percolationSecondMoment(int dim, Real n);
/// Late-time M1 ~ 1/(1 - q_x) (edmd Eq. 5.50). Precondition qx < 1.
Real lateMeanClusterSize(Real qx);
/// Late-time M2 ~ q_x^2 N/(1 - q_x) (edmd Eq. 5.51). Precondition qx < 1.
Real lateSecondMoment(Real qx, Real n);
/// Largest-cluster fraction q_x = 1 - sqrt(lambdaStar/lambda) of the population model, 0 for
/// lambda <= lambdaStar (edmd Eq. 5.41 in the one-parameter form of Fig. 5.22).
Real largestClusterFraction(Real lambda, Real lambdaStar);

// ---- reference curves for a run (edmd 5.1-5.3; checklist item 31) --------------------------

/// The setup a set of reference curves describes. n is a Real so 5e5 can be written directly.
struct ReferenceSetup {
    int dim = 3;
    Real n = 512000;       ///< number of particles
    Real nu = 0.25;        ///< volume fraction
    Real eps = 0.5;        ///< normal restitution, 0 <= eps < 1 (tau is undefined for eps = 1)
    Real m = 1;            ///< [kg] particle mass
    Real a = 1;            ///< [m] particle radius
    Real T0 = 1;           ///< [J] initial granular temperature
    Real alphaGrowth = 1;  ///< exponent alpha of E_grw (Eq. 5.2; 3D fit 1.1)
};

/// Scalar thresholds of a setup, for a JSON summary. Times [s], frequency [1/s].
struct ReferenceThresholds {
    Real g2a = 0;        ///< contact value (Eq. 4.52)
    Real boxLength = 0;  ///< [m] L from n, nu, a (Eqs. 4.2-4.4)
    Real lOpt = 0;       ///< optical depth (Eq. 4.9)
    Real lambda = 0;     ///< 1 - eps^2 (Eq. 4.7)
    Real lambdaCl = 0;   ///< clustering threshold (Eq. 4.70)
    Real lambdaSh = 0;   ///< shear threshold (Eq. 4.73)
    Real epsIc = 0;      ///< collapse restitution (Eq. 4.8)
    Real epsCl = 0;      ///< sqrt(1 - lambda_cl)
    Real tE = 0;         ///< [s] initial Enskog time 1/f_E(0)
    Real fE0 = 0;        ///< [1/s] initial Enskog collision frequency (Eq. 4.33)
    Real lE = 0;         ///< [m] mean free path, thesis convention (Eq. 4.38)
    Real tauHc = 0;      ///< D^2/lambda (Eq. 5.6)
    Real tauCs = 0;      ///< D^2 lambda/lambda_cl^2 (Eq. 5.7)
    Real tauPFit = 0;    ///< 0.24 + 40 (1 - lambda)^2/lambda (Eq. 5.15; fitted in 3D only)
    Real tGrw = 0;       ///< [s] (2/D) t_E (Eq. 5.2)
    Real tSat = 0;       ///< [s] 2 D t_E/lambda_cl (Eq. 5.3)
};

/// Thresholds of a setup. Throws std::invalid_argument for dim not 2/3, n <= 0,
/// nu outside (0, 1), eps outside [0, 1), m, a or T0 <= 0.
ReferenceThresholds referenceThresholds(const ReferenceSetup& setup);

/// Reference curves as CSV text, one row per tau, header
/// "tau,t,T_haff,E_haff,f_E_haff,l_E,P_haff,E_grw,E_sat": t [s] = haffTime, T_haff [J] (Haff),
/// E_haff = D T_haff/2 [J] (mean kinetic energy per particle), f_E_haff [1/s], l_E [m]
/// (thesis convention, constant), P_haff [J/m^D] (Eq. 4.44 at T_haff), E_grw and E_sat [J]
/// (Eqs. 5.2-5.3 in unscaled t). Numbers in %.10g. Same preconditions as referenceThresholds.
std::string referenceCurvesCsv(const ReferenceSetup& setup, std::span<const Real> tau);

}  // namespace granulab::edmd
