// SPDX-License-Identifier: MIT
// Janssen silo theory (gc2d spec section 8.3): closed forms against the numerical integration of
// Eq. 3.11/3.12, fits of k and mu_j on the Fig. 3.7 reference curves, and the spec's derived
// numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/janssen.hpp"

namespace granulab {
namespace {

using analysis::JanssenParams;
using analysis::SiloShape;

constexpr Real kG = 9.81;

/// The Fig. 3.7 shapes: height 1 m, maximum half-width 0.1 m.
std::vector<std::pair<std::string, SiloShape>> figureShapes() {
    return {{"straight", analysis::straightSilo(0.1)},
            {"stepped h0 = 50 mm", analysis::steppedSilo(0.1, 0.05, 0.05)},
            {"stepped h0 = 500 mm", analysis::steppedSilo(0.1, 0.05, 0.5)},
            {"slanted", analysis::slantedSilo(-0.1, 0.1)},
            {"parabolic", analysis::parabolicSilo(100, 1)}};
}

/// 49 depths 0.02 .. 0.98 m (the slanted tip and the parabola's vertex are at 1 m).
std::vector<Real> depths() {
    std::vector<Real> z;
    for (int i = 1; i < 50; ++i) z.push_back(0.02 * i);
    return z;
}

TEST(Janssen, ClosedFormsMatchNumericalIntegration) {
    for (const auto& [name, shape] : figureShapes())
        for (const Real mu : {0.1, 0.4, 0.7}) {
            const JanssenParams p{2.0 / 3.0, mu, 5000, kG};
            const std::vector<Real> z = depths();
            const std::vector<Real> numeric = analysis::janssenNumeric(shape, p, z);
            // The same integration with r(z) as a plain function and numerical slopes.
            const SiloShape general = analysis::generalSilo(
                [&shape](Real zz) { return shape.halfWidth(zz); }, {},
                shape.kind == SiloShape::Kind::Stepped ? std::vector<Real>{shape.h0} : std::vector<Real>{});
            const std::vector<Real> numericGeneral = analysis::janssenNumeric(general, p, z);
            Real scale = 0;
            for (const Real v : numeric) scale = std::max(scale, v);
            for (std::size_t i = 0; i < z.size(); ++i) {
                const Real closed = analysis::janssenSigmaZz(shape, p, z[i]);
                EXPECT_NEAR(closed / scale, numeric[i] / scale, 1e-6)
                    << name << " mu " << mu << " z " << z[i];
                EXPECT_NEAR(numericGeneral[i] / scale, numeric[i] / scale, 1e-6) << name << " z " << z[i];
                EXPECT_NEAR(analysis::janssenSigmaXx(shape, p, z[i]), p.k * closed, 1e-9 * scale) << name;
            }
        }
}

TEST(Janssen, ParabolicXiIsTheAntiderivative) {
    const Real k = 0.86, a = 100, b = 0.46;
    for (const Real z : {0.0, 0.1, 0.3, 0.45}) {
        const Real h = 1e-6, r = std::sqrt((b - z) / a), dr = -1 / (2 * a * r);
        const Real integrand = (dr * dr + k) / (r * std::pow(1 + dr * dr, 1.5));
        const Real derivative =
            (analysis::parabolicXi(k, a, b, z + h) - analysis::parabolicXi(k, a, b, std::max(0.0, z - h))) /
            (z + h - std::max(0.0, z - h));
        EXPECT_NEAR(derivative / integrand, 1, 1e-5) << "z " << z;
    }
    EXPECT_EQ(analysis::parabolicXi(k, a, b, 0), 0);
}

TEST(Janssen, FitRecoversKAndMuFromFarStart) {
    for (const auto& [name, shape] : figureShapes())
        for (const Real mu : {0.1, 0.4, 0.7}) {
            const JanssenParams p{2.0 / 3.0, mu, 5000, kG};
            std::vector<Real> z = depths(), sxx, szz;
            for (const Real zz : z) {
                sxx.push_back(analysis::janssenSigmaXx(shape, p, zz));
                szz.push_back(analysis::janssenSigmaZz(shape, p, zz));
            }
            for (const auto& [k0, mu0] : {std::pair{0.2, 1.5}, std::pair{2.0, 0.03}}) {
                const analysis::JanssenFit fit = analysis::fitJanssen(shape, z, sxx, szz, 5000, kG, k0, mu0);
                EXPECT_NEAR(fit.k / p.k, 1, 0.01) << name << " mu " << mu << " start " << k0;
                EXPECT_NEAR(fit.mu / mu, 1, 0.01) << name << " mu " << mu << " start " << k0;
                EXPECT_TRUE(fit.converged) << name;
            }
        }
}

TEST(Janssen, SpecDerivedNumbers) {
    // Stepped silo (spec 8.3): rho = 0.78 x 5000, k = 0.64, mu_j = 0.33, r1 = 40 mm, r2 = 20 mm, h0 = 250 mm.
    const SiloShape stepped = analysis::steppedSilo(0.04, 0.02, 0.25);
    const JanssenParams p{0.64, 0.33, 0.78 * 5000, kG};
    EXPECT_NEAR(analysis::janssenSigmaXx(stepped, p, 0.25) / 1000, 3.40, 0.005);
    EXPECT_NEAR(p.rho * kG * 0.02 / p.mu / 1000, 2.32, 0.005);
    EXPECT_NEAR(analysis::janssenSigmaXx(stepped, p, 0.30) / 1000, 2.96, 0.005);
    EXPECT_NEAR(analysis::janssenSigmaXx(stepped, p, 0.50) / 1000, 2.40, 0.005);
    // Slanted silo a = -0.1087, b = 65 mm: maxima of sigma_zz.
    const SiloShape slanted = analysis::slantedSilo(-0.1087, 0.065);
    const auto maximum = [](const SiloShape& s, const JanssenParams& q, Real zEnd, Real& zMax) {
        Real best = 0;
        for (Real z = 0; z < zEnd; z += 1e-4) {
            const Real v = analysis::janssenSigmaZz(s, q, z);
            if (v > best) {
                best = v;
                zMax = z;
            }
        }
        return best;
    };
    Real zMax = 0;
    Real peak = maximum(slanted, {0.77, 0.30, 1, 1}, 0.59, zMax);
    EXPECT_NEAR(zMax, 0.29, 0.005);
    EXPECT_NEAR(peak, 0.144, 0.0005);  // in units of rho g m
    peak = maximum(slanted, {0.76, 0.37, 1, 1}, 0.59, zMax);
    EXPECT_NEAR(zMax, 0.27, 0.005);
    EXPECT_NEAR(peak, 0.127, 0.0005);
    // Parabolic silo a = 100 1/m, b = 0.46 m.
    EXPECT_NEAR(analysis::parabolicEffectiveRadius(0.86, 100, 0.46), 0.0679, 0.00005);
    const SiloShape parabola = analysis::parabolicSilo(100, 0.46);
    maximum(parabola, {0.86, 0.30, 1, 1}, 0.46, zMax);
    EXPECT_NEAR(zMax, 0.31, 0.005);
    maximum(parabola, {0.89, 0.47, 1, 1}, 0.46, zMax);
    EXPECT_NEAR(zMax, 0.26, 0.005);
}

TEST(Janssen, DepthProfileAndTable) {
    // A 3 x 4 stress grid filled with the straight-silo theory (surface at y = 1 m).
    const SiloShape shape = analysis::straightSilo(0.1);
    const JanssenParams p{0.64, 0.33, 3900, kG};
    analysis::StressGrid s;
    s.grid = {0, 0.6, 0.1, 0.1, 0.1, 0.1, 3, 4};
    for (std::size_t k = 0; k < s.grid.count(); ++k) {
        const Real z = 1 - s.grid.centre(k).y;
        s.sigmaXx.push_back(analysis::janssenSigmaXx(shape, p, z) * (k % 3 == 1 ? 1.1 : 0.95));
        s.sigmaZz.push_back(analysis::janssenSigmaZz(shape, p, z));
    }
    s.sigmaXx[0] = std::nan("");  // one empty area in the bottom row
    const analysis::DepthProfile pr = analysis::depthProfile(s, 1.0);
    ASSERT_EQ(pr.z.size(), 4u);
    EXPECT_NEAR(pr.z.front(), 0.05, 1e-12);
    EXPECT_NEAR(pr.z.back(), 0.35, 1e-12);
    EXPECT_EQ(pr.areas.back(), 2u);
    EXPECT_NEAR(pr.sigmaXx[0], analysis::janssenSigmaXx(shape, p, 0.05) * (2 * 0.95 + 1.1) / 3, 1e-9);
    EXPECT_NEAR(pr.kMean, 0.64 * (7 * 0.95 + 4 * 1.1) / 11, 1e-12);
    const analysis::JanssenFit fit{0.64, 0.33, 0, 3, true};
    const analysis::Table t = analysis::janssenTable(pr, shape, fit, 3900, kG);
    EXPECT_EQ(t.name, "janssen");
    ASSERT_EQ(t.columns.size(), 5u);
    EXPECT_EQ(t.columns[3].name, "sigma_xx_theory");
    EXPECT_EQ(t.columns[4].name, "sigma_zz_theory");
    EXPECT_EQ(t.notes[0], "k = 0.64");
    EXPECT_EQ(t.notes[1], "mu_j = 0.33");
    EXPECT_NEAR(t.columns[4].values[2], analysis::janssenSigmaZz(shape, p, 0.25), 1e-9);
}

TEST(Janssen, RejectsNonsense) {
    EXPECT_THROW(analysis::steppedSilo(0.02, 0.04, 0.1), std::invalid_argument);
    EXPECT_THROW(analysis::straightSilo(0), std::invalid_argument);
    EXPECT_THROW(analysis::janssenSigmaZz(analysis::straightSilo(0.1), {0, 0.3, 1, kG}, 0.1),
                 std::invalid_argument);
    EXPECT_THROW(analysis::fitJanssen(analysis::straightSilo(0.1), {0.1, 0.2}, {1, 2}, {1, 2}, 1, kG),
                 std::invalid_argument);
    EXPECT_TRUE(
        std::isnan(analysis::janssenSigmaZz(analysis::slantedSilo(-0.1, 0.1), {0.6, 0.3, 1, kG}, 1.5)));
}

}  // namespace
}  // namespace granulab
