// SPDX-License-Identifier: MIT
// Continuum coarse-graining (Goldhirsch 2010, Weinhart et al. 2012): kernel normalisation, the
// momentum balance div sigma^c = -f^c + f^w on random contact sets, and the contact virial.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "analysis/dem_coarse_grain.hpp"
#include "analysis/quadrature.hpp"
#include "dem_lattice.hpp"

namespace granulab {
namespace {

using analysis::CoarseGrainParams;
using analysis::CoarseKernel;

TEST(DemCoarseGrain, KernelsIntegrateToOne) {
    const analysis::GaussLegendre q = analysis::gaussLegendre(20);
    for (const CoarseKernel kind : {CoarseKernel::Gaussian, CoarseKernel::Lucy}) {
        const CoarseGrainParams p{kind, 0.7e-3, 16};
        const Real R = analysis::kernelCutoff(p);
        Real sum = 0;  // 2 pi int_0^R r phi(r) dr, 50 panels
        for (int m = 0; m < 50; ++m)
            for (std::size_t g = 0; g < q.node.size(); ++g) {
                const Real r = R * (m + q.node[g]) / 50;
                sum += q.weight[g] * 2 * kPi * r * analysis::kernelValue(p, r) * R / 50;
            }
        EXPECT_NEAR(sum, 1, 1e-12);
        EXPECT_EQ(analysis::kernelValue(p, R * 1.0001), 0);
    }
}

TEST(DemCoarseGrain, GaussLegendreIsExactForPolynomials) {
    const analysis::GaussLegendre q = analysis::gaussLegendre(5);
    Real s = 0;
    for (std::size_t g = 0; g < 5; ++g) s += q.weight[g] * std::pow(q.node[g], 9);
    EXPECT_NEAR(s, 0.1, 1e-15);
    EXPECT_THROW(analysis::gaussLegendre(0), std::invalid_argument);
}

/// Random grains in [0, 1 cm]^2 with random contacts (contact points off the centre line, as for
/// polygons) and random wall contacts.
void randomContacts(analysis::GrainFrame& f, analysis::ContactFrame& c, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> u(0, 1e-2), unit(-1, 1), mid(0.3, 0.7);
    for (int i = 0; i < 40; ++i) test::addDisk(f, u(rng), u(rng), 1e-3, 1e-3);
    for (int k = 0; k < 120; ++k) {
        const auto a = static_cast<std::size_t>(rng() % 40), b = static_cast<std::size_t>(rng() % 40);
        if (a == b) continue;
        const Vec2 pa{f.x[a], f.y[a]}, pb{f.x[b], f.y[b]};
        const Vec2 p = pa + (pb - pa) * mid(rng) + Vec2{unit(rng), unit(rng)} * 3e-4;
        test::addContact(c, f.id[a], f.id[b], -1, p, (pb - pa) / norm(pb - pa), {unit(rng), unit(rng)});
    }
    for (int k = 0; k < 20; ++k) {
        const auto a = static_cast<std::size_t>(rng() % 40);
        const Vec2 p{f.x[a] + 1e-3 * unit(rng), f.y[a] + 1e-3 * unit(rng)};
        test::addContact(c, f.id[a], -1, 0, p, {0, -1}, {unit(rng), unit(rng)});
    }
}

/// d_b sigma_ab at p by central differences of step h = hRel w against -f^c + f^w. Truncation
/// error h^2/6 sigma''' ~ (h/w)^2 sigma/w, rounding ~ 1e-16 sigma/h: for hRel in [1e-6, 1e-4] both
/// are below 1e-8 of the force-density scale sum |F| phi(0), so 1e-6 of it is a safe bound. The
/// truncated Gaussian makes the line integrals' gradients jump on the cutoff circles around the
/// centres and contact points; a stencil straddling one is wrong by O(1), which hRel = 1e-6 makes
/// improbable (~1e-5 per point) for the Gaussian cases.
void expectMomentumBalance(const CoarseGrainParams& p, unsigned seed, Real hRel = 1e-4) {
    analysis::GrainFrame f;
    analysis::ContactFrame c;
    randomContacts(f, c, seed);
    std::mt19937 rng(seed + 100);
    std::uniform_real_distribution<Real> u(0, 1e-2);
    const Real h = hRel * p.width;
    std::vector<Vec2> pts;
    for (int k = 0; k < 60; ++k) {
        const Vec2 r{u(rng), u(rng)};
        for (const Vec2 d : {Vec2{0, 0}, Vec2{h, 0}, Vec2{-h, 0}, Vec2{0, h}, Vec2{0, -h}})
            pts.push_back(r + d);
    }
    const analysis::CoarseGrainFields fl = analysis::coarseGrain(f, c, pts, p);
    Real scale = 0;
    for (std::size_t k = 0; k < c.size(); ++k) scale += std::hypot(c.fx[k], c.fy[k]);
    scale *= analysis::kernelValue(p, 0);
    for (std::size_t k = 0; k < pts.size(); k += 5) {
        const Real divX =
            (fl.cxx[k + 1] - fl.cxx[k + 2]) / (2 * h) + (fl.cxz[k + 3] - fl.cxz[k + 4]) / (2 * h);
        const Real divZ =
            (fl.czx[k + 1] - fl.czx[k + 2]) / (2 * h) + (fl.czz[k + 3] - fl.czz[k + 4]) / (2 * h);
        EXPECT_NEAR(divX, -fl.fcx[k] + fl.fwx[k], 1e-6 * scale) << "point " << k / 5;
        EXPECT_NEAR(divZ, -fl.fcz[k] + fl.fwz[k], 1e-6 * scale) << "point " << k / 5;
    }
}

TEST(DemCoarseGrain, MomentumBalanceLucy) {
    expectMomentumBalance({CoarseKernel::Lucy, 2e-3, 16}, 1);
    expectMomentumBalance({CoarseKernel::Lucy, 4e-3, 16}, 2);
}

TEST(DemCoarseGrain, MomentumBalanceGaussian) {
    expectMomentumBalance({CoarseKernel::Gaussian, 1e-3, 16}, 3, 1e-6);
    expectMomentumBalance({CoarseKernel::Gaussian, 0.5e-3, 16}, 4, 1e-6);
}

TEST(DemCoarseGrain, ContactVirialAndDensity) {
    // Two disks pressed together with f along x: int sigma^c_xx dA = f d (compressive-positive),
    // the other components 0; int rho dA = total mass.
    analysis::GrainFrame f;
    test::addDisk(f, 0, 0, 1e-3, 2e-3);
    test::addDisk(f, 2e-3, 0, 1e-3, 3e-3);
    f.vx[1] = 0.5;
    analysis::ContactFrame c;
    const Real force = 0.7;
    test::addContact(c, 0, 1, -1, {1e-3, 0}, {1, 0}, {-force, 0});
    const CoarseGrainParams p{CoarseKernel::Lucy, 2e-3, 16};
    const Real dx = 2e-5;
    const std::size_t n = 400;
    const std::vector<Vec2> pts = analysis::gridPoints({-3e-3, -4e-3}, dx, dx, n, n);
    const analysis::CoarseGrainFields fl = analysis::coarseGrain(f, c, pts, p);
    Real xx = 0, zz = 0, xz = 0, mass = 0, momentum = 0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
        xx += fl.cxx[k] * dx * dx;
        zz += fl.czz[k] * dx * dx;
        xz += fl.cxz[k] * dx * dx;
        mass += fl.rho[k] * dx * dx;
        momentum += fl.jx[k] * dx * dx;
    }
    EXPECT_NEAR(xx / (force * 2e-3), 1, 1e-6);
    EXPECT_NEAR(zz, 0, 1e-12);
    EXPECT_NEAR(xz, 0, 1e-12);
    EXPECT_NEAR(mass / 5e-3, 1, 1e-6);
    EXPECT_NEAR(momentum / (3e-3 * 0.5), 1, 1e-6);
    const analysis::Table t = analysis::coarseGrainTable(fl, p);
    EXPECT_EQ(t.name, "coarse_grain");
    EXPECT_EQ(t.rows(), pts.size());
    EXPECT_THROW(analysis::coarseGrain(f, c, pts, {CoarseKernel::Lucy, 0, 16}), std::invalid_argument);
}

}  // namespace
}  // namespace granulab
