// SPDX-License-Identifier: MIT
// Cluster-population master equation (edmd spec section 5.6, Eqs. 5.29-5.43; erratum 14):
// rates, the right-hand side term by term, the invariants of the printed (number of clusters)
// and symmetric (mass) forms, an analytic pure-coagulation solution, detailed balance as a fixed
// point, and AT-24: from p_1 = 1 with xi = 2, lambda/(beta0/alpha0)^2 = 4 puts the weight at the
// largest sizes while 0.25 gives a power law with an exponential cut-off (Fig. 5.24).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "analysis/master_equation.hpp"

using namespace granulab;
using namespace granulab::analysis;

namespace {

MasterEquationParams at24Params(Real ratio, bool symmetric = false) {
    MasterEquationParams p;
    p.maxSize = 100;
    p.dim = 3;
    p.alpha0 = 1;
    p.beta0 = 0.25;
    p.xi = 2;
    p.lambda = ratio * p.beta0 * p.beta0 / (p.alpha0 * p.alpha0);  // lambda/(beta0/alpha0)^2 = ratio
    p.symmetricGain = symmetric;
    return p;
}

/// Fraction of the mass sum s p_s in sizes s > S/2.
Real massFractionAboveHalf(const std::vector<Real>& p) {
    Real all = 0, big = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        all += Real(i + 1) * p[i];
        if (2 * (i + 1) > p.size()) big += Real(i + 1) * p[i];
    }
    return big / all;
}

Real maxAbs(const std::vector<Real>& v) {
    Real m = 0;
    for (Real x : v) m = std::max(m, std::abs(x));
    return m;
}

}  // namespace

TEST(MasterEquation, RatesAndDetailedBalanceRatio) {
    MasterEquationParams p;
    p.maxSize = 10;
    p.dim = 3;
    p.alpha0 = 1.5;
    p.beta0 = 0.4;
    p.lambda = 0.36;
    p.xi = 1.7;
    p.velocity = 2;
    const MasterEquation me(p);
    // Eq. 5.29, 5.30
    EXPECT_NEAR(me.alpha(2, 3), 1.5 * std::pow(5.0, 2.0 / 3) * 2 * 0.6, 1e-13);
    EXPECT_NEAR(me.beta(2, 3), 0.4 * std::pow(5.0, 2.0 / 3) * 2 * std::pow(5.0 / 6, 1.7), 1e-13);
    EXPECT_NEAR(me.alpha(2, 3), me.alpha(3, 2), 1e-15);
    EXPECT_NEAR(me.beta(2, 3), me.beta(3, 2), 1e-15);
    p.dim = 2;
    EXPECT_NEAR(MasterEquation(p).alpha(1, 3), 1.5 * 2 * 2 * 0.6, 1e-13);  // (i+j)^(1/2) = 2
    // Eqs. 5.32-5.35: beta_ij/alpha_ij = p_i p_j/p_{i+j} for p_s = c s^-xi e^-ws, c = beta0/(alpha0 sqrt
    // lambda)
    const DetailedBalanceState eq = detailedBalanceEquilibrium(p);
    EXPECT_NEAR(eq.c, 0.4 / (1.5 * 0.6), 1e-15);
    for (int i = 1; i <= 4; ++i) {
        for (int j = 1; j <= 5; ++j) {
            const Real ratio =
                eq.p[std::size_t(i - 1)] * eq.p[std::size_t(j - 1)] / eq.p[std::size_t(i + j - 1)];
            EXPECT_NEAR(ratio, me.beta(i, j) / me.alpha(i, j), 1e-12 * ratio);
        }
    }
}

// Eq. 5.31 for S_max = 3 written out by hand, printed and symmetric form.
TEST(MasterEquation, RightHandSideByHand) {
    MasterEquationParams prm;
    prm.maxSize = 3;
    prm.alpha0 = 1.3;
    prm.beta0 = 0.7;
    prm.lambda = 0.5;
    prm.xi = 2.5;
    const std::vector<Real> p = {0.5, 0.3, 0.2};
    for (bool sym : {false, true}) {
        prm.symmetricGain = sym;
        const MasterEquation me(prm);
        const Real A2 = me.alpha(1, 1), A3 = me.alpha(1, 2), B11 = me.beta(1, 1), B12 = me.beta(1, 2);
        const Real g = sym ? 0.5 : 1.0;  // factor on merging gain and fragmentation loss
        const std::vector<Real> want = {
            -(A2 * p[0] * p[0] + A3 * p[1] * p[0]) + (B11 * p[1] + B12 * p[2]),
            g * A2 * p[0] * p[0] - A3 * p[0] * p[1] + B12 * p[2] - g * B11 * p[1],
            g * 2 * A3 * p[0] * p[1] - g * 2 * B12 * p[2],
        };
        std::vector<Real> got(3);
        me.rhs(p, got);
        for (int s = 0; s < 3; ++s)
            EXPECT_NEAR(got[std::size_t(s)], want[std::size_t(s)], 1e-14) << sym << " " << s;
        // printed form: number of clusters conserved; symmetric form: mass conserved
        const Real dNumber = got[0] + got[1] + got[2], dMass = got[0] + 2 * got[1] + 3 * got[2];
        if (sym) {
            EXPECT_NEAR(dMass, 0, 1e-14);
            EXPECT_GT(std::abs(dNumber), 1e-3);
        } else {
            EXPECT_NEAR(dNumber, 0, 1e-14);
            EXPECT_GT(std::abs(dMass), 1e-3);
        }
    }
}

// Pure coagulation of monomers into dimers (S_max = 2, beta0 = 0): y_1(t) = 1/(1 + alpha_11 t).
TEST(MasterEquation, PureCoagulationMatchesClosedForm) {
    MasterEquationParams prm;
    prm.maxSize = 2;
    prm.beta0 = 0;
    prm.lambda = 0.64;
    for (bool sym : {false, true}) {
        prm.symmetricGain = sym;
        const MasterEquation me(prm);
        const Real A = me.alpha(1, 1);
        const std::vector<Real> times = {0, 0.3, 1, 5, 40};
        const MasterResult r = me.integrate({}, times);
        ASSERT_EQ(r.samples.size(), times.size());
        for (const MasterSample& smp : r.samples) {
            const Real y1 = 1 / (1 + A * smp.t);
            const Real y2 = sym ? (1 - y1) / 2 : 1 - y1;  // a merger makes one dimer of two monomers
            EXPECT_NEAR(smp.p[0] * smp.total, y1, 1e-9) << sym << " t=" << smp.t;
            EXPECT_NEAR(smp.p[1] * smp.total, y2, 1e-9) << sym << " t=" << smp.t;
            EXPECT_NEAR(smp.m1, (y1 + 2 * y2) / (y1 + y2), 1e-9);
        }
    }
}

// The invariant of each form holds to round-off through a long run; the other quantity moves.
TEST(MasterEquation, InvariantsOfPrintedAndSymmetricForms) {
    const std::vector<Real> times = {0.5, 2, 8, 32};
    // printed form: sum p_s = 1 (p_s = n_s/n_tot stays normalised); M1 = mass grows
    const MasterResult printed = MasterEquation(at24Params(4)).integrate({}, times);
    for (const MasterSample& s : printed.samples) EXPECT_NEAR(s.total, 1, 1e-12) << s.t;
    EXPECT_GT(printed.samples.back().mass, 5);
    // symmetric form: sum s y_s = N/n_tot(0) = 1 (mass); n_tot/n_tot(0) = total falls
    const MasterResult sym = MasterEquation(at24Params(4, true)).integrate({}, times);
    for (const MasterSample& s : sym.samples) {
        EXPECT_NEAR(s.mass, 1, 1e-12) << s.t;
        EXPECT_NEAR(s.m1, 1 / s.total, 1e-10) << s.t;  // M1 = N/n_tot
    }
    EXPECT_LT(sym.samples.back().total, 0.9);
    // both keep p_s >= 0 and report normalised p
    for (const MasterResult* r : {&printed, &sym}) {
        for (const MasterSample& s : r->samples) {
            Real sum = 0;
            for (Real v : s.p) {
                EXPECT_GE(v, 0);
                sum += v;
            }
            EXPECT_NEAR(sum, 1, 1e-12);
        }
    }
}

// Eqs. 5.32-5.35: every detailed-balance state is a fixed point of both forms; other states are not.
TEST(MasterEquation, DetailedBalanceIsStationary) {
    for (int dim : {2, 3}) {
        for (Real xi : {1.5, 2.0, 3.0}) {
            for (Real ratio : {0.25, 4.0}) {
                MasterEquationParams prm = at24Params(ratio);
                prm.dim = dim;
                prm.xi = xi;
                prm.maxSize = 60;
                for (bool sym : {false, true}) {
                    prm.symmetricGain = sym;
                    const MasterEquation me(prm);
                    const auto kind = sym ? EquilibriumNorm::Mass : EquilibriumNorm::Number;
                    const DetailedBalanceState eq = detailedBalanceEquilibrium(prm, 1, kind);
                    std::vector<Real> r(eq.p.size());
                    me.rhs(eq.p, r);
                    EXPECT_LT(maxAbs(r), 1e-13) << dim << " " << xi << " " << ratio << " " << sym;
                    // perturb one size by 1 %: no longer stationary
                    std::vector<Real> q = eq.p;
                    q[2] *= 1.01;
                    me.rhs(q, r);
                    EXPECT_GT(maxAbs(r), 1e-4 * q[2]) << dim << " " << xi << " " << ratio << " " << sym;
                }
            }
        }
    }
}

TEST(MasterEquation, EquilibriumNormalisationAndThreshold) {
    MasterEquationParams prm = at24Params(1);
    const Real lambdaStar = populationThresholdLambda(prm);
    Real zetaS = 0;
    for (int s = 1; s <= prm.maxSize; ++s) zetaS += 1.0 / (Real(s) * s);
    EXPECT_NEAR(lambdaStar, 0.0625 * zetaS * zetaS, 1e-14);  // (beta0/alpha0)^2 (sum s^-xi)^2
    for (Real f : {0.5, 0.999, 1.001, 3.0}) {
        prm.lambda = f * lambdaStar;
        const DetailedBalanceState eq = detailedBalanceEquilibrium(prm);
        Real sum = 0;
        for (Real v : eq.p) sum += v;
        EXPECT_NEAR(sum, 1, 1e-12);
        if (f < 1) {
            EXPECT_GT(eq.w, 0) << f;
        } else {
            EXPECT_LT(eq.w, 0) << f;
        }
        EXPECT_NEAR(eq.p[0], eq.c * std::exp(-eq.w), 1e-14);
    }
    // Eq. 5.41: above the threshold, w = 0 with sum p = 1 - q_x, q_x = 1 - sqrt(lambda*/lambda)
    prm.lambda = 3 * lambdaStar;
    const DetailedBalanceState q = detailedBalanceEquilibrium(prm, std::sqrt(1.0 / 3));
    EXPECT_NEAR(q.w, 0, 1e-12);
    // at the threshold w = 0 with sum p = 1
    prm.lambda = lambdaStar;
    EXPECT_NEAR(detailedBalanceEquilibrium(prm).w, 0, 1e-12);
    // mass normalisation
    const DetailedBalanceState m = detailedBalanceEquilibrium(prm, 2.5, EquilibriumNorm::Mass);
    Real mass = 0;
    for (std::size_t i = 0; i < m.p.size(); ++i) mass += Real(i + 1) * m.p[i];
    EXPECT_NEAR(mass, 2.5, 1e-11);
    EXPECT_THROW(detailedBalanceEquilibrium(prm, 0), std::invalid_argument);
}

// AT-24 / Fig. 5.24: start p_1 = 1, xi = 2.
TEST(MasterEquation, At24DissipationDichotomy) {
    const std::vector<Real> times = {1, 4, 16, 64};
    // strong dissipation, lambda = 4 (beta0/alpha0)^2 > lambda*: the early cut-off disappears and the
    // weight moves to the largest sizes
    const MasterEquationParams strongP = at24Params(4);
    const MasterResult strong = MasterEquation(strongP).integrate({}, times);
    const MasterSample& s1 = strong.samples.front();
    const MasterSample& sEnd = strong.samples.back();
    EXPECT_GT(fitExponentialCutoff(s1.p, 2, 1, 20, 1e-9), 0.1);  // early: power law with cut-off
    EXPECT_LT(massFractionAboveHalf(s1.p), 1e-6);
    EXPECT_LT(fitExponentialCutoff(sEnd.p, 2, 1, 100, 1e-9), -0.01);  // late: weight grows with s
    EXPECT_GT(massFractionAboveHalf(sEnd.p), 0.5);
    EXPECT_GT(sEnd.m1, 5 * s1.m1);
    // small sizes stay a power law: p_2/p_1 ~ 2^-xi
    EXPECT_NEAR(sEnd.p[1] / sEnd.p[0], 0.25, 0.02);
    // and the end state is the detailed-balance equilibrium with w < 0
    const DetailedBalanceState eqS = detailedBalanceEquilibrium(strongP);
    EXPECT_LT(eqS.w, 0);
    for (std::size_t i = 0; i < eqS.p.size(); ++i)
        EXPECT_NEAR(sEnd.p[i], eqS.p[i], 1e-7 + 1e-5 * eqS.p[i]) << i;
    EXPECT_NEAR(fitExponentialCutoff(sEnd.p, 2, 1, 100, 1e-9), eqS.w, 1e-4);

    // weak dissipation, lambda = 0.25 (beta0/alpha0)^2: quickly a power law with exponential cut-off
    const MasterEquationParams weakP = at24Params(0.25);
    const MasterResult weak = MasterEquation(weakP).integrate({}, times);
    const MasterSample& wEnd = weak.samples.back();
    const DetailedBalanceState eqW = detailedBalanceEquilibrium(weakP);
    EXPECT_GT(eqW.w, 0.5);
    const Real wFit = fitExponentialCutoff(wEnd.p, 2, 1, 100, 1e-9);
    EXPECT_NEAR(wFit, eqW.w, 1e-3);
    EXPECT_LT(massFractionAboveHalf(wEnd.p), 1e-9);
    EXPECT_LT(wEnd.m1, 1.5);
    for (std::size_t i = 0; i < eqW.p.size(); ++i)
        EXPECT_NEAR(wEnd.p[i], eqW.p[i], 1e-9 + 1e-5 * eqW.p[i]) << i;
    // quickly: already near the equilibrium cut-off at t = 4
    EXPECT_NEAR(weak.samples[1].m1, wEnd.m1, 1e-3);
}

// The symmetric (mass-conserving) form relaxes to the detailed-balance state of equal mass.
TEST(MasterEquation, SymmetricFormRelaxesToMassNormalisedEquilibrium) {
    for (Real ratio : {0.25, 4.0}) {
        const MasterEquationParams prm = at24Params(ratio, true);
        const std::vector<Real> times = {64};
        const MasterSample end = MasterEquation(prm).integrate({}, times).samples.back();
        const DetailedBalanceState eq = detailedBalanceEquilibrium(prm, 1, EquilibriumNorm::Mass);
        Real eqTotal = 0;
        for (Real v : eq.p) eqTotal += v;
        EXPECT_NEAR(end.total, eqTotal, 1e-6) << ratio;
        for (std::size_t i = 0; i < 10; ++i)
            EXPECT_NEAR(end.p[i] * end.total, eq.p[i], 1e-7) << ratio << " " << i;
    }
}

TEST(MasterEquation, HelpersAndValidation) {
    const std::vector<Real> p = {0.5, 0.25, 0.25};
    EXPECT_NEAR(clusterMoment(p, 0), 1, 1e-15);
    EXPECT_NEAR(clusterMoment(p, 1), 0.5 + 0.5 + 0.75, 1e-15);
    EXPECT_NEAR(clusterMoment(p, 2), 0.5 + 1 + 2.25, 1e-15);
    std::vector<Real> synth(50);
    for (std::size_t i = 0; i < synth.size(); ++i) {
        const Real s = Real(i + 1);
        synth[i] = 0.3 * std::pow(s, -1.7) * std::exp(-0.05 * s);
    }
    EXPECT_NEAR(fitExponentialCutoff(synth, 1.7, 1, 50), 0.05, 1e-12);  // Fig. 5.23 shape
    EXPECT_THROW(fitExponentialCutoff(synth, 1.7, 5, 5), std::invalid_argument);

    MasterEquationParams bad;
    bad.maxSize = 0;
    EXPECT_THROW(MasterEquation{bad}, std::invalid_argument);
    bad = {};
    bad.lambda = 0;
    EXPECT_THROW(MasterEquation{bad}, std::invalid_argument);
    bad = {};
    bad.dim = 4;
    EXPECT_THROW(MasterEquation{bad}, std::invalid_argument);
    const MasterEquation me(MasterEquationParams{});
    const std::vector<Real> wrongSize(3, 0.1);
    const std::vector<Real> times = {1};
    EXPECT_THROW(me.integrate(wrongSize, times), std::invalid_argument);
    const std::vector<Real> backwards = {2, 1};
    EXPECT_THROW(me.integrate({}, backwards), std::invalid_argument);
    MasterIntegratorOptions few;
    few.maxSteps = 3;
    const std::vector<Real> far = {1000};
    EXPECT_THROW(me.integrate({}, far, few), std::runtime_error);
}
