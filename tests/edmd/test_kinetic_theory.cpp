// SPDX-License-Identifier: MIT
// Kinetic-theory reference formulas (edmd spec sections 4.3-4.6, 5.3, 5.5, 5.6, 6, 9): every
// precomputed number of the spec (table of section 4.6 to the printed precision, kinetic numbers
// at nu = 0.25, AT-15 tau_p, M1(0), w of Eq. 5.47, zeta ratios of Eq. 5.48), special cases
// against the general-D forms, Haff's law against a numerical integration of the cooling rate,
// and the reference-curve CSV.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "edmd/kinetic_theory.hpp"

using namespace granulab;
using namespace granulab::edmd;

namespace {

/// Half a unit in the last printed digit of `printed` ("1.58e-3", "0.99921", "1121").
Real halfLastDigit(const std::string& printed) {
    const auto e = printed.find_first_of("eE");
    const std::string mantissa = printed.substr(0, e);
    const int exponent = e == std::string::npos ? 0 : std::stoi(printed.substr(e + 1));
    const auto dot = mantissa.find('.');
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
    return 0.5 * std::pow(10.0, exponent - decimals);
}

/// value, rounded to the precision of `printed`, equals `printed` (ties allowed).
void expectPrinted(Real value, const std::string& printed, const std::string& what) {
    const Real ref = std::stod(printed);
    EXPECT_LE(std::abs(value - ref), halfLastDigit(printed) * (1 + 1e-9))
        << what << ": computed " << value << ", spec prints " << printed;
}

/// Classic RK4 integration of dT/dt = rate(T) from 0 to t in n steps.
template <class F>
Real integrateRk4(F rate, Real T0, Real t, int n) {
    Real T = T0;
    const Real h = t / n;
    for (int i = 0; i < n; ++i) {
        const Real k1 = rate(T), k2 = rate(T + 0.5 * h * k1), k3 = rate(T + 0.5 * h * k2),
                   k4 = rate(T + h * k3);
        T += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return T;
}

}  // namespace

TEST(KineticTheory, HalfLastDigitHelper) {
    EXPECT_DOUBLE_EQ(halfLastDigit("1.58e-3"), 0.5e-5);
    EXPECT_DOUBLE_EQ(halfLastDigit("0.99921"), 0.5e-5);
    EXPECT_DOUBLE_EQ(halfLastDigit("1121"), 0.5);
    EXPECT_DOUBLE_EQ(halfLastDigit("204.7"), 0.05);
}

// edmd section 4.6 "Precomputed numbers": all 7 rows, all columns, to the printed precision.
TEST(KineticTheory, SpecTableOfSection46) {
    struct Row {
        int dim;
        Real n, nu;
        std::string g2a, La, lOpt, lambdaCl, epsCl, lambdaSh, epsIc;
    };
    const std::vector<Row> rows = {
        {2, 1e5, 0.25, "1.5833", "1121", "140.1", "1.58e-3", "0.99921", "3.9e-4", "0.978"},
        {2, 1e4, 0.25, "1.5833", "354.5", "44.3", "1.58e-2", "0.9921", "3.9e-3", "0.932"},
        {3, 512000, 0.25, "2.0741", "204.7", "25.6", "6.17e-3", "0.99691", "1.64e-3", "0.884"},
        {3, 8000, 0.25, "2.0741", "51.2", "6.40", "9.9e-2", "0.949", "2.6e-2", "0.609"},
        {3, 512000, 0.031, "1.0820", "410.5", "6.36", "1.0e-1", "0.949", "2.7e-2", "0.607"},
        {2, 5e5, 0.3, "1.7730", "2288", "343", "2.6e-4", "0.99987", "6.6e-5", "0.991"},
        {3, 2e6, 0.25, "2.0741", "322.4", "40.3", "2.5e-3", "0.99876", "6.6e-4", "0.925"},
    };
    for (const Row& r : rows) {
        const std::string tag =
            "D=" + std::to_string(r.dim) + " N=" + std::to_string(r.n) + " nu=" + std::to_string(r.nu);
        const Real lOpt = opticalDepth(r.dim, r.n, r.nu);
        const Real lambdaCl = clusteringLambda(r.dim, lOpt);
        expectPrinted(contactValue(r.dim, r.nu), r.g2a, tag + " g_2a");
        expectPrinted(boxLengthFor(r.dim, r.n, r.nu, 1.0), r.La, tag + " L/a");
        expectPrinted(lOpt, r.lOpt, tag + " l_opt");
        expectPrinted(lambdaCl, r.lambdaCl, tag + " lambda_cl");
        expectPrinted(epsFromLambda(lambdaCl), r.epsCl, tag + " eps_cl");
        expectPrinted(shearLambda(r.dim, lOpt), r.lambdaSh, tag + " lambda_sh");
        expectPrinted(collapseRestitution(lOpt), r.epsIc, tag + " eps_ic");
    }
}

// edmd section 4.6 "Kinetic numbers at nu = 0.25, m = a = T = 1" (also AT-7, AT-8).
TEST(KineticTheory, KineticNumbersAtQuarterPacking) {
    expectPrinted(enskogCollisionFrequency(2, 0.25, 1, 1, 1), "0.8933", "f_E 2D");
    expectPrinted(enskogCollisionFrequency(3, 0.25, 1, 1, 1), "3.5105", "f_E 3D");
    expectPrinted(enskogCollisionTime(2, 0.25, 1, 1, 1), "1.1194", "t_E 2D");
    expectPrinted(enskogCollisionTime(3, 0.25, 1, 1, 1), "0.2849", "t_E 3D");
    expectPrinted(meanFreePath(2, 0.25, 1), "1.263", "l_E 2D");
    expectPrinted(meanFreePath(3, 0.25, 1), "0.4546", "l_E 3D");
    expectPrinted(reducedPressure(2, 0.25), "0.7917", "P_red 2D");
    expectPrinted(reducedPressure(3, 0.25), "2.0741", "P_red 3D");
    // l_E = v_bar/f_E with the thesis mean speed (Eq. 4.38), and 2D closed form a/(2 nu g)
    for (int D : {2, 3}) {
        EXPECT_NEAR(meanFreePath(D, 0.25, 1),
                    meanSpeedThesis(D, 1, 1) / enskogCollisionFrequency(D, 0.25, 1, 1, 1), 1e-14);
    }
    EXPECT_NEAR(meanFreePath(2, 0.25, 1), 1 / (2 * 0.25 * contactValue(2, 0.25)), 1e-14);
    EXPECT_NEAR(meanFreePath(3, 0.01, 1) * contactValue(3, 0.01), 1 / (3 * std::sqrt(2.0) * 0.01),
                1e-12);  // 4.39
}

TEST(KineticTheory, ScalingWithMassRadiusTemperature) {
    // f_E ~ sqrt(T/m)/a, l_E ~ a, t_E = 1/f_E
    const Real f1 = enskogCollisionFrequency(3, 0.2, 1, 1, 1);
    EXPECT_NEAR(enskogCollisionFrequency(3, 0.2, 4, 1, 1), 2 * f1, 1e-12);
    EXPECT_NEAR(enskogCollisionFrequency(3, 0.2, 1, 4, 1), f1 / 2, 1e-12);
    EXPECT_NEAR(enskogCollisionFrequency(3, 0.2, 1, 1, 2), f1 / 2, 1e-12);
    EXPECT_NEAR(enskogCollisionTime(3, 0.2, 9, 1, 1), 1 / (3 * f1), 1e-12);
    EXPECT_NEAR(meanFreePath(2, 0.2, 3), 3 * meanFreePath(2, 0.2, 1), 1e-12);
    EXPECT_THROW(enskogCollisionFrequency(4, 0.2, 1, 1, 1), std::invalid_argument);
    EXPECT_THROW(contactValue(1, 0.2), std::invalid_argument);
}

// Eq. 4.33 = n x cross-section x <|v_rel|> x g with the exact Maxwell relative speed
// (2D cross-section 4a, 3D pi (2a)^2; <|v_rel|> = sqrt2 x exact mean speed).
TEST(KineticTheory, CollisionFrequencyIsDensityTimesCrossSectionTimesRelativeSpeed) {
    const Real nu = 0.17, T = 2.5, m = 1.7, a = 0.6;
    for (int D : {2, 3}) {
        const Real n = nu / (unitBallVolume(D) * std::pow(a, D));
        const Real sigma = D == 2 ? 4 * a : kPi * 4 * a * a;
        const Real vRel = std::sqrt(2.0) * meanSpeedExact(D, T, m);
        EXPECT_NEAR(enskogCollisionFrequency(D, nu, T, m, a), n * sigma * vRel * contactValue(D, nu), 1e-12)
            << D;
    }
}

TEST(KineticTheory, MeanSpeedConventions) {
    // erratum 3: thesis prefactor exact in 3D, 2D exact sqrt(pi/2) = 1.2533 vs thesis 1.1284
    EXPECT_NEAR(meanSpeedExact(3, 1, 1), std::sqrt(8 / kPi), 1e-14);
    EXPECT_NEAR(meanSpeedThesis(3, 1, 1), meanSpeedExact(3, 1, 1), 1e-14);
    EXPECT_NEAR(meanSpeedExact(2, 1, 1), std::sqrt(kPi / 2), 1e-14);
    expectPrinted(meanSpeedExact(2, 1, 1), "1.2533", "2D exact mean speed");
    expectPrinted(meanSpeedThesis(2, 1, 1), "1.1284", "2D thesis mean speed");
    EXPECT_NEAR(meanSpeedExact(2, 4, 1), 2 * std::sqrt(kPi / 2), 1e-14);
    EXPECT_NEAR(meanFreePathExact(2, 0.25, 1) / meanFreePath(2, 0.25, 1),
                std::sqrt(kPi / 2) / std::sqrt(4 / kPi), 1e-14);
    EXPECT_NEAR(meanFreePathExact(3, 0.25, 1), meanFreePath(3, 0.25, 1), 1e-14);
    // 2D mean speed of a Maxwellian by direct quadrature: int_0^inf v (v/T) exp(-v^2/2T) dv
    Real sum = 0;
    const Real dv = 1e-4;
    for (int i = 0; i < 200000; ++i) {
        const Real v = (i + 0.5) * dv;
        sum += v * v * std::exp(-v * v / 2) * dv;
    }
    EXPECT_NEAR(meanSpeedExact(2, 1, 1), sum, 1e-8);
}

TEST(KineticTheory, VolumeFractionAndBox) {
    EXPECT_NEAR(volumeFraction(2, 100, 1, 20), 100 * kPi / 400, 1e-14);
    EXPECT_NEAR(volumeFraction(3, 100, 1, 20), 100 * 4 * kPi / 3 / 8000, 1e-14);
    EXPECT_NEAR(unitBallVolume(3), 4 * kPi / 3, 1e-14);
    for (int D : {2, 3}) {
        const Real L = boxLengthFor(D, 12345, 0.3, 0.7);
        EXPECT_NEAR(volumeFraction(D, 12345, 0.7, L), 0.3, 1e-13);
        EXPECT_NEAR(opticalDepth(D, 12345, 0.3), 0.3 * L / (2 * 0.7), 1e-10);
    }
    EXPECT_NEAR(opticalDepth(2, 1e5, 0.25), std::sqrt(1e5 * 0.25 * kPi / 4), 1e-10);          // Eq. 4.9
    EXPECT_NEAR(opticalDepth(3, 512000, 0.25), std::cbrt(512000 * 0.0625 * kPi / 6), 1e-10);  // Eq. 4.9
    // thesis check, 3D L/2a = 100, nu = 0.25 -> l_opt = 25, lambda_cl ~ 6e-3
    const Real n = 0.25 / volumeFraction(3, 1, 1, 200);  // N with L = 200 a at nu = 0.25
    EXPECT_NEAR(opticalDepth(3, n, 0.25), 25, 1e-9);
    EXPECT_NEAR(clusteringLambda(3, 25), 6e-3, 0.5e-3);
}

TEST(KineticTheory, EquationOfStateForms) {
    for (Real nu : {0.05, 0.25, 0.45}) {
        // Carnahan-Starling closed form (Eq. 4.48) and Henderson (Eq. 4.52)
        EXPECT_NEAR(compressibilityFactor(3, nu), 1 + 4 * nu * (1 - nu / 2) / std::pow(1 - nu, 3), 1e-13);
        EXPECT_NEAR(compressibilityFactor(2, nu), 1 + 2 * nu * (1 - 7 * nu / 16) / std::pow(1 - nu, 2),
                    1e-13);
        EXPECT_NEAR(carnahanStarlingSeries3d(nu, 400), compressibilityFactor(3, nu), 1e-10);
        // nu^3 correction of the 2D Henderson EOS (Eqs. 4.47-4.52)
        EXPECT_NEAR(hendersonEosCorrected2d(nu) - compressibilityFactor(2, nu),
                    -2 * nu * std::pow(nu, 3) / (64 * std::pow(1 - nu, 4)), 1e-14);
        // inelastic EOS: 1 + (1+eps) 2^(D-2) nu g (Eq. 4.44)
        EXPECT_NEAR(compressibilityFactor(2, nu, 0.5), 1 + 1.5 * nu * contactValue(2, nu), 1e-14);
        EXPECT_NEAR(compressibilityFactor(3, nu, 0.5), 1 + 3 * nu * contactValue(3, nu), 1e-14);
    }
    // the 2D correction is small at nu = 0.25
    EXPECT_NEAR(hendersonEosCorrected2d(0.25), 1.7917, 1e-3);
    // virial coefficients: exact terms
    EXPECT_DOUBLE_EQ(virialEos3d(0.1, 0), 1);
    EXPECT_NEAR(virialEos3d(0.1, 2), 1 + 0.4 + 0.1, 1e-15);
    EXPECT_NEAR(virialEos3d(0.1, 5), 1 + 0.4 + 0.1 + 0.01836 + 0.00282 + 0.000395, 1e-15);
    EXPECT_NEAR(virialEos3d(0.1, 5), compressibilityFactor(3, 0.1), 1e-3);
    EXPECT_THROW(virialEos3d(0.1, 6), std::invalid_argument);
    EXPECT_NEAR(carnahanStarlingSeries3d(0.1, 3), 1 + 0.4 + 0.1 + 0.018, 1e-15);
    // dilute limit P V = N T, pressure from N, V, T
    EXPECT_NEAR(compressibilityFactor(3, 1e-12), 1, 1e-10);
    EXPECT_NEAR(pressure(3, 1000, 2000, 2, 0.25), 1.0 * (1 + 4 * 0.25 * contactValue(3, 0.25)), 1e-13);
    // free-volume form with the thesis fit (Eq. 4.67)
    EXPECT_NEAR(freeVolumeReducedPressure(0.6), 1.65 / 0.083 - 1, 1e-12);
    EXPECT_NEAR(freeVolumeReducedPressure(0.6, 2, 0.7), 19, 1e-12);
}

// edmd Eqs. 4.54-4.62: T(tau) = T0/(1 + tau)^2 is the solution of dT/dt = -(lambda/D) f_E(T) T.
TEST(KineticTheory, HaffLawMatchesIntegratedCoolingRate) {
    const Real m = 1.3, a = 0.8, T0 = 2.2;
    for (int D : {2, 3}) {
        for (Real eps : {0.3, 0.9}) {
            const Real nu = 0.25, lambda = lambdaFromEps(eps);
            const Real tE = enskogCollisionTime(D, nu, T0, m, a);
            for (Real t : {0.1 * tE, 3 * tE, 40 * tE, 2000 * tE}) {
                const Real Tnum = integrateRk4(
                    [&](Real T) { return haffCoolingRate(D, lambda, nu, T, m, a); }, T0, t, 20000);
                const Real tau = haffTau(D, lambda, t, tE);
                EXPECT_NEAR(Tnum / haffTemperature(T0, tau), 1, 1e-9)
                    << "D=" << D << " eps=" << eps << " t=" << t;
                // f_E(tau) = f_E(0)/(1+tau) is f_E at the Haff temperature (Eq. 4.62)
                EXPECT_NEAR(haffCollisionFrequency(1 / tE, tau), enskogCollisionFrequency(D, nu, Tnum, m, a),
                            1e-8 / tE);
            }
            EXPECT_NEAR(haffTime(D, lambda, haffTau(D, lambda, 7.5, tE), tE), 7.5, 1e-12);
        }
    }
    // a wrong law (exponent 1) would not match
    EXPECT_GT(std::abs(haffTemperature(1, 1) - 0.5), 0.2);
    EXPECT_DOUBLE_EQ(haffTemperature(1, 1), 0.25);
}

TEST(KineticTheory, ThresholdSpecialCasesAndLimits) {
    for (Real l : {6.4, 25.6, 140.1}) {
        EXPECT_NEAR(clusteringLambda(2, l), std::pow(kPi, 3) / (l * l), 1e-14);             // Eq. 4.71
        EXPECT_NEAR(clusteringLambda(3, l), 25 * std::pow(kPi, 3) / (192 * l * l), 1e-14);  // Eq. 4.72
        EXPECT_NEAR(shearLambda(2, l), std::pow(kPi, 3) / (4 * l * l), 1e-14);              // Eq. 4.74
        EXPECT_NEAR(shearLambda(3, l), 5 * std::pow(kPi, 3) / (144 * l * l), 1e-14);        // Eq. 4.75
        EXPECT_LT(shearLambda(3, l), clusteringLambda(3, l));  // the shear instability comes first
    }
    // eps_ic ~ 1 - pi/l_opt, lambda_ic ~ 2 pi/l_opt for l_opt >> 1 (Eqs. 4.10-4.11)
    EXPECT_NEAR(collapseRestitution(1e4), 1 - kPi / 1e4, 1e-7);
    EXPECT_NEAR(lambdaFromEps(collapseRestitution(1e4)), 2 * kPi / 1e4, 1e-3 * 2 * kPi / 1e4);
    EXPECT_NEAR(collapseRestitution(1), 0, 1e-15);
    EXPECT_NEAR(epsFromLambda(lambdaFromEps(0.37)), 0.37, 1e-15);
    // TC elastic fraction (Eq. 4.12): ~2 t_c/t_E for t_c << t_E
    EXPECT_NEAR(tcElasticFraction(1e-5, 1), 2e-5, 1e-9);
    EXPECT_NEAR(tcElasticFraction(1, 2), 1 - std::exp(-1.0), 1e-15);
}

TEST(KineticTheory, CrossoverTimes) {
    const Real tE = 0.2849, lambda = 0.91, lambdaCl = 6.17e-3;
    for (int D : {2, 3}) {
        const Real tHom = 2 * D * tE / lambda;
        const Real tGrw = growthTime(D, tE), tSat = saturationTime(D, tE, lambdaCl);
        EXPECT_NEAR(tGrw, 2 * tE / D, 1e-15);
        EXPECT_NEAR(homogeneousClusterTime(D, lambda, tE), tHom * tHom / tGrw, 1e-9);   // Eq. 5.4
        EXPECT_NEAR(clusterSaturationTime(D, lambdaCl, tE), tSat * tSat / tGrw, 1e-6);  // Eq. 5.5
        EXPECT_NEAR(haffTau(D, lambda, homogeneousClusterTime(D, lambda, tE), tE),
                    homogeneousClusterTau(D, lambda), 1e-12);
        EXPECT_NEAR(homogeneousClusterTau(D, lambda), D * D / lambda, 1e-15);  // Eq. 5.6
        EXPECT_NEAR(haffTau(D, lambda, clusterSaturationTime(D, lambdaCl, tE), tE),
                    clusterSaturationTau(D, lambda, lambdaCl), 1e-6);  // Eq. 5.7
        // t_hc is where the late Haff asymptote E0 (t/t_hom)^-2 meets the growth law E0 t_grw/t
        const Real thc = homogeneousClusterTime(D, lambda, tE);
        EXPECT_NEAR(std::pow(thc / tHom, -2.0), tGrw / thc, 1e-12);
    }
    EXPECT_NEAR(growthEnergy(2, 3, 3), 1, 1e-15);
    EXPECT_NEAR(growthEnergy(2, 3, 3, 1.1), 2 / std::pow(2.0, 1.1), 1e-15);
    EXPECT_NEAR(saturationEnergy(2, 3, 3), 0.5, 1e-15);
    // 3D clustering onset tau_hc ~ 10..10^2 for the thesis eps (section 5.5)
    EXPECT_NEAR(homogeneousClusterTau(3, lambdaFromEps(0.9)), 47.37, 0.01);
}

// AT-15: tau_p = 0.24 + 40 eps^4/lambda (Eq. 5.15).
TEST(KineticTheory, PeakTauFitAt15) {
    const std::vector<std::pair<Real, std::string>> cases = {{0.2, "0.31"}, {0.3, "0.60"}, {0.5, "3.6"},
                                                             {0.6, "8.3"},  {0.75, "29"},  {0.9, "138"}};
    for (const auto& [eps, printed] : cases) {
        const Real lambda = lambdaFromEps(eps);
        expectPrinted(peakTauFit(lambda), printed, "tau_p at eps " + std::to_string(eps));
        EXPECT_NEAR(peakTauFit(lambda), 0.24 + 40 * std::pow(eps, 4) / lambda, 1e-12);
    }
}

TEST(KineticTheory, InitialClusterMoments) {
    // Eq. 5.19 at nu = 0.25, delta/2a = 0.1 (section 5.5 [I])
    expectPrinted(initialMeanClusterSize(2, 0.25), "1.158", "M1(0) 2D");
    expectPrinted(initialMeanClusterSize(3, 0.25), "1.622", "M1(0) 3D");
    EXPECT_NEAR(initialMeanClusterSize(3, 0.031) - 1, 12 * 0.031 * contactValue(3, 0.031) * 0.1, 1e-15);
    // Eq. 5.47 at 3D nu = 0.031: w = 2.25, 2.17 with g_2a (section 5.6 [I], AT-20)
    expectPrinted(initialCutoff(3, 0.031), "2.25", "w 3D");
    expectPrinted(initialCutoff(3, 0.031, 0.1, true), "2.17", "w 3D with g_2a");
    EXPECT_NEAR(initialCutoff(2, 0.02), -std::log(8 * 0.02 * 0.1), 1e-14);
    // Eqs. 5.44-5.46
    EXPECT_NEAR(initialMomentLargeCutoff(2, 1, 3), 1 + 0.5 * std::exp(-3.0), 1e-15);
    EXPECT_NEAR(initialMomentLargeCutoff(3, 2, 3), 1 + 1.5 * std::sqrt(0.5) * std::exp(-3.0), 1e-15);
    EXPECT_THROW(initialMomentLargeCutoff(3, 3, 3), std::invalid_argument);
    EXPECT_NEAR(initialMomentSmallCutoff(2, 2, 0.1), 100, 1e-10);
    EXPECT_NEAR(initialMomentSmallCutoff(3, 1, 0.01), 10, 1e-10);
    EXPECT_DOUBLE_EQ(percolationTheta(2), 1);
    EXPECT_DOUBLE_EQ(percolationTheta(3), 1.5);
}

TEST(KineticTheory, RiemannZeta) {
    EXPECT_NEAR(riemannZeta(2), kPi * kPi / 6, 1e-14);
    EXPECT_NEAR(riemannZeta(4), std::pow(kPi, 4) / 90, 1e-14);
    EXPECT_NEAR(riemannZeta(3), 1.2020569031595942, 1e-14);
    EXPECT_NEAR(riemannZeta(1.5), 2.6123753486854883, 1e-13);
    // near the pole: zeta(1+x) = 1/x + gamma - gamma_1 x + O(x^2), gamma_1 = -0.0728158455
    const Real s = 1 + 1e-4, x = s - 1;  // x exactly representable as s - 1
    EXPECT_NEAR(riemannZeta(s), 1 / x + 0.5772156649015329 + 0.0728158454836767 * x, 1e-9);
    EXPECT_NEAR(riemannZeta(40), 1, 1e-12);
    EXPECT_THROW(riemannZeta(1), std::invalid_argument);
}

// Eq. 5.48: M1 at percolation = zeta(vartheta-1)/zeta(vartheta) = 11.77 (2D), 3.75 (3D).
TEST(KineticTheory, PercolationMoments) {
    expectPrinted(percolationMeanClusterSize(2), "11.77", "zeta ratio 2D");
    expectPrinted(percolationMeanClusterSize(3), "3.75", "zeta ratio 3D");
    EXPECT_NEAR(percolationVartheta(2), 187.0 / 91.0, 1e-15);
    EXPECT_NEAR(percolationSecondMoment(3, 1e6), std::pow(1e6, 0.8), 1e-6);
    // late-time moments and q_x (Eqs. 5.41, 5.50-5.51)
    EXPECT_NEAR(lateMeanClusterSize(0.9), 10, 1e-12);
    EXPECT_NEAR(lateSecondMoment(0.5, 1000), 500, 1e-12);
    EXPECT_DOUBLE_EQ(largestClusterFraction(0.01, 0.02), 0);
    EXPECT_NEAR(largestClusterFraction(0.08, 0.02), 0.5, 1e-15);
    EXPECT_NEAR(largestClusterFraction(0.98, 0.02), 1 - std::sqrt(0.02 / 0.98), 1e-15);
}

TEST(KineticTheory, ReferenceThresholdsStandard3dSetup) {
    ReferenceSetup s;  // 3D, N = 512000, nu = 0.25, eps = 0.5
    const ReferenceThresholds r = referenceThresholds(s);
    expectPrinted(r.g2a, "2.0741", "g_2a");
    expectPrinted(r.boxLength, "204.7", "L");
    expectPrinted(r.lOpt, "25.6", "l_opt");
    expectPrinted(r.lambdaCl, "6.17e-3", "lambda_cl");
    expectPrinted(r.lambdaSh, "1.64e-3", "lambda_sh");
    expectPrinted(r.epsIc, "0.884", "eps_ic");
    expectPrinted(r.epsCl, "0.99691", "eps_cl");
    expectPrinted(r.fE0, "3.5105", "f_E(0)");
    expectPrinted(r.tE, "0.2849", "t_E");
    expectPrinted(r.lE, "0.4546", "l_E");
    EXPECT_DOUBLE_EQ(r.lambda, 0.75);
    EXPECT_NEAR(r.tauHc, 12, 1e-12);
    EXPECT_NEAR(r.tauCs, 9 * 0.75 / (r.lambdaCl * r.lambdaCl), 1e-6);
    expectPrinted(r.tauPFit, "3.6", "tau_p");
    EXPECT_NEAR(r.tGrw, 2 * r.tE / 3, 1e-15);
    EXPECT_NEAR(r.tSat, 6 * r.tE / r.lambdaCl, 1e-9);
    // m, a, T enter as in the formulas
    s.T0 = 4;
    s.m = 1;
    s.a = 2;
    EXPECT_NEAR(referenceThresholds(s).fE0, r.fE0, 1e-12);  // sqrt(T)/a unchanged
    EXPECT_NEAR(referenceThresholds(s).boxLength, 2 * r.boxLength, 1e-9);
    s.eps = 1;
    EXPECT_THROW(referenceThresholds(s), std::invalid_argument);
    s.eps = 0.5;
    s.nu = 0;
    EXPECT_THROW(referenceThresholds(s), std::invalid_argument);
}

TEST(KineticTheory, ReferenceCurvesCsv) {
    ReferenceSetup s;
    s.dim = 2;
    s.n = 1e5;
    s.nu = 0.25;
    s.eps = 0.6;
    s.T0 = 2;
    const std::vector<Real> tau = {0, 1, 9, 1000};
    const std::string csv = referenceCurvesCsv(s, tau);
    std::istringstream in(csv);
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(line, "tau,t,T_haff,E_haff,f_E_haff,l_E,P_haff,E_grw,E_sat");
    const ReferenceThresholds r = referenceThresholds(s);
    const Real volume = r.boxLength * r.boxLength;
    std::size_t row = 0;
    while (std::getline(in, line)) {
        ASSERT_LT(row, tau.size());
        std::vector<Real> v;
        std::istringstream ls(line);
        std::string cell;
        while (std::getline(ls, cell, ',')) v.push_back(std::stod(cell));
        ASSERT_EQ(v.size(), 9u) << line;
        const Real ta = tau[row], t = haffTime(2, r.lambda, ta, r.tE);
        const Real T = 2 / ((1 + ta) * (1 + ta));
        auto near = [](Real got, Real want) { EXPECT_NEAR(got, want, 1e-9 * std::max(1.0, std::abs(want))); };
        near(v[0], ta);
        near(v[1], t);
        near(v[2], T);
        near(v[3], T);  // E = D T/2 = T in 2D
        near(v[4], r.fE0 / (1 + ta));
        near(v[5], meanFreePath(2, 0.25, 1));
        near(v[6], 1e5 * T / volume * (1 + 1.6 * 0.25 * r.g2a));
        near(v[7], 2 / (1 + t / r.tGrw));
        near(v[8], 2 / ((1 + t / r.tSat) * (1 + t / r.tSat)));
        ++row;
    }
    EXPECT_EQ(row, tau.size());
    s.eps = 1;
    EXPECT_THROW(referenceCurvesCsv(s, tau), std::invalid_argument);
}
