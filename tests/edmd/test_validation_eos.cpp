// SPDX-License-Identifier: MIT
// Physics validation of the event-driven engine, elastic equilibrium (edmd spec 4.4-4.5, 5.7
// AT-1, AT-7, AT-8): conservation and no overlaps over 1e6 collisions; the equation of state
// from the collisional virial against Henderson (2D) and Carnahan-Starling (3D); the collision
// frequency against Enskog with the measured contact value; the spec's kinetic numbers at
// nu = 0.25. Statistical errors come from block averages and are printed with every figure.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "gas_fixture.hpp"

using namespace granulab;
using namespace granulab::edmd;
using namespace granulab::edmd::validation;
namespace kt {  // the measurements (analysis) and the kinetic theory of the gas (edmd)
using namespace granulab::analysis;
using namespace granulab::edmd;
}  // namespace kt

namespace {

/// Best available hard-disk EOS for the comparison beyond Henderson: the virial series with the
/// exact coefficients B2..B10 (N. Clisby and B. M. McCoy, J. Stat. Phys. 122, 15 (2006), Table 1:
/// B_k/B_2^(k-1) = 0.782004, 0.53223180, 0.33355604, 0.1988425, 0.1148728, 0.0649930, 0.0362193,
/// 0.0199537 for k = 3..10), written in the packing fraction (coefficient of eta^(k-1) is
/// 2^(k-1) B_k/B_2^(k-1)), plus a tail k > 10 whose coefficients continue linearly with the last
/// difference (b10 - b9 = 0.944; the differences fall slowly, 1.13 ... 0.94). At eta = 0.6 the tail
/// is 0.19 of Z - 1 = 5.46; a +-10 % change of its slope moves Z by only +-0.002. Henderson
/// (1 + eta^2/8)/(1 - eta)^2 has the coefficients 3.125, 4.25, 5.375, 6.5, 7.625 for k = 3..7
/// against the exact 3.128, 4.258, 5.337, 6.363, 7.352: it overestimates Z at high density.
Real hardDiskVirialZ(Real eta) {
    const Real reduced[] = {0.782004,  0.53223180, 0.33355604, 0.1988425,
                            0.1148728, 0.0649930,  0.0362193,  0.0199537};
    Real z = 1 + 2 * eta, power = eta, coefficient = 0, previous = 0;
    for (int k = 3; k <= 10; ++k) {
        power *= eta;
        previous = coefficient;
        coefficient = reduced[k - 3] * std::pow(2.0, k - 1);
        z += coefficient * power;
    }
    const Real slope = coefficient - previous;
    for (int k = 11; k <= 400; ++k) {
        power *= eta;
        z += (coefficient + slope * (k - 10)) * power;
    }
    return z;
}

/// Best simple hard-sphere EOS: Kolafa's correction of Carnahan-Starling,
/// Z = (1 + eta + eta^2 - (2/3)(eta^3 + eta^4))/(1 - eta)^3 (T. Boublik and I. Nezbeda, Collect.
/// Czech. Chem. Commun. 51, 2301 (1986); fits the simulation data to ~1e-3 in the stable fluid).
/// It has the fourth virial coefficient 18.33 (exact 18.365) where Carnahan-Starling has 18, so CS is
/// ~0.35 % low in P_red at eta = 0.3 and ~0.2 % at 0.45.
Real hardSphereKolafaZ(Real eta) {
    return (1 + eta + eta * eta - 2.0 / 3.0 * (eta * eta * eta + eta * eta * eta * eta)) /
           std::pow(1 - eta, 3);
}

/// Reduced pressure of the best reference EOS (see above).
Real referenceReducedPressure(int dim, Real nu) {
    return (dim == 2 ? hardDiskVirialZ(nu) : hardSphereKolafaZ(nu)) - 1;
}

/// Elastic equilibrium measurement: reduced pressure P V/(N T) - 1 from the collisional virial,
/// the collision frequency f = 2 C/(N t), and the ratio of f to Enskog's f_E evaluated with the
/// contact value implied by the measured pressure (exact in equilibrium: both are set by g(2a)).
struct EosRun {
    int dim = 0;
    std::uint64_t n = 0;
    Real nu = 0;
    BlockMean pRed, freq, freqOverEnskog;
    Real drift = 0;  ///< (second half - first half) of P_red, in units of its error: equilibration check
    std::uint64_t collisions = 0;
    Real seconds = 0;
};

/// Runs `blocks` windows of equal length after an elastic pre-run of 100 collisions per particle
/// (spec 4.2: "10^2 collisions per particle"). The windows together hold ~`collisions` collisions.
template <int D>
EosRun measureEos(std::uint64_t n, Real nu, std::uint64_t collisions, int blocks, std::uint64_t seed) {
    const auto start = std::chrono::steady_clock::now();
    auto e = makeGas<D>(n, nu, seed);
    equilibrate(e, 100);
    const Real T = temperature(e);  // constant: elastic
    const Real fGuess = kt::enskogCollisionFrequency(D, nu, T, 1, 1);
    const Real dt = 2 * static_cast<Real>(collisions) / (static_cast<Real>(n) * fGuess) / blocks;
    const auto N = static_cast<Real>(n);
    std::vector<Real> p, f, r;
    Real w0 = e.collisionalVirial();
    std::uint64_t c0 = e.stats().collisions;
    for (int b = 1; b <= blocks; ++b) {
        e.runUntil(b * dt);
        const Real w = e.collisionalVirial() - w0;
        const auto c = static_cast<Real>(e.stats().collisions - c0);
        w0 = e.collisionalVirial();
        c0 = e.stats().collisions;
        const Real pRed = w / (D * N * T * dt);  // P V/(N T) - 1 = virial/(D N T dt)
        const Real freq = 2 * c / (N * dt);
        // Enskog with the measured contact value g = P_red/(2^(D-1) nu) (spec Eq. 4.45):
        // f_E(g) = D 2^(D-1) nu g sqrt(T/m)/(sqrt(pi) a) = D P_red sqrt(T/m)/(sqrt(pi) a).
        const Real gMeasured = pRed / (std::pow(2.0, D - 1) * nu);
        const Real fEnskog =
            kt::enskogCollisionFrequency(D, nu, T, 1, 1) * gMeasured / kt::contactValue(D, nu);
        p.push_back(pRed);
        f.push_back(freq);
        r.push_back(freq / fEnskog);
    }
    EosRun run;
    run.dim = D;
    run.n = n;
    run.nu = nu;
    run.pRed = blockedMean(p);
    run.freq = blockedMean(f);
    run.freqOverEnskog = blockedMean(r);
    const std::vector<Real> first(p.begin(), p.begin() + blocks / 2), second(p.begin() + blocks / 2, p.end());
    const auto h1 = blockMean(first), h2 = blockMean(second);
    run.drift = (h2.mean - h1.mean) / std::hypot(h1.error, h2.error);
    run.collisions = e.stats().collisions;
    run.seconds = std::chrono::duration<Real>(std::chrono::steady_clock::now() - start).count();
    return run;
}

/// The runs of EquationOfState are reused by CollisionFrequency when both run in one process.
const EosRun& eosRun(int dim, Real nu, std::uint64_t collisions = 3000000) {
    static std::map<std::pair<int, Real>, EosRun> cache;
    const auto key = std::make_pair(dim, nu);
    auto it = cache.find(key);
    if (it == cache.end()) {
        // N = 4096 (64^2 disks, 16^3 spheres): finite-size corrections to P are O(1/N); the
        // agreement with the reference EOS to <~0.1 % below bounds them. 3e6 collisions in 30
        // blocks (~50 collisions per particle each) give a statistical error of ~0.1 % on P_red.
        const EosRun run = dim == 2 ? measureEos<2>(4096, nu, collisions, 30, 11)
                                    : measureEos<3>(4096, nu, collisions, 30, 12);
        it = cache.emplace(key, run).first;
    }
    return it->second;
}

}  // namespace

// AT-1: elastic spheres conserve energy and momentum to round-off, never overlap.
TEST(EdmdValidation, ElasticGasConservesEnergyAndMomentumWithoutOverlap) {
    const auto start = std::chrono::steady_clock::now();
    auto e = makeGas<3>(4000, 0.3, 5);
    const Real e0 = e.kineticEnergy();
    const Real pScale = std::sqrt(4000 * 2 * e0 / 3);  // sqrt(N m T) per component
    Real worstEnergy = 0, worstMomentum = 0, worstGap = 1e300;
    for (int k = 1; k <= 10; ++k) {
        e.runCollisions(100000);
        const auto p = e.momentum();
        worstEnergy = std::max(worstEnergy, std::abs(e.kineticEnergy() / e0 - 1));
        worstMomentum = std::max(worstMomentum, std::sqrt(dot(p, p)) / pScale);
        worstGap = std::min(worstGap, minimumGapRatio(e));
    }
    const Real seconds = std::chrono::duration<Real>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "[elastic 3D N=4000 nu=0.3] %llu collisions, %llu events (%llu annulled), max |dE/E| %.2e, "
        "max |P|/sqrt(NmT) %.2e, min pair distance/(2a) %.15f (10 O(N^2) checks), %.1f s\n",
        (unsigned long long)e.stats().collisions, (unsigned long long)e.stats().events,
        (unsigned long long)e.stats().annulled, worstEnergy, worstMomentum, worstGap, seconds);
    EXPECT_EQ(e.stats().collisions, 1000000u);
    // Round-off: each collision rule is exact to ~1e-16 of the pair's energy and momentum, so a
    // random walk over 1e6 collisions stays near 1e-14 relative (measured ~1e-13 and ~1e-16). The
    // bounds catch a systematic relative error of 1e-13 in the impulse (measured 4e-11, 3e-12).
    EXPECT_LT(worstEnergy, 1e-12);
    EXPECT_LT(worstMomentum, 1e-13);
    // Contact is computed to round-off (~1e-15 of the distance); a missed collision overlaps by O(1).
    EXPECT_LT(1 - worstGap, 1e-9);
}

// AT-8 / spec 4.5: P V/(N T) - 1 against Henderson (2D) and Carnahan-Starling (3D), and against the
// best reference EOS (virial series with exact B2..B10 for disks, Kolafa's CS correction for spheres).
// Measured (N = 4096, 3e6 collisions each; statistical error ~0.1 %): 2D 0.3 -0.01 % vs
// Henderson; 2D 0.5 -0.8 % vs Henderson, -0.2 % vs virial (+0.03 % with another seed); 2D 0.6 -1.3 % vs
// Henderson, +0.07 % vs virial; 3D 0.3 +0.33 % vs CS, -0.02 % vs Kolafa; 3D 0.45 +0.20 % vs CS, -0.02 % vs
// Kolafa. Henderson is itself ~1.2 % high at nu = 0.6 (its higher virial coefficients are too large), so that
// case is asserted against the virial reference (1 %), and Henderson's error there is printed.
TEST(EdmdValidation, EquationOfStateMatchesHendersonAndCarnahanStarling) {
    const std::pair<int, Real> cases[] = {{2, 0.3}, {2, 0.5}, {2, 0.6}, {3, 0.3}, {3, 0.45}};
    for (const auto& [dim, nu] : cases) {
        const EosRun& r = eosRun(dim, nu);
        const Real theory = kt::reducedPressure(dim, nu);
        const Real reference = referenceReducedPressure(dim, nu);
        const Real rel = r.pRed.mean / theory - 1, relRef = r.pRed.mean / reference - 1;
        std::printf(
            "[EOS %dD N=%llu nu=%.2f] P_red %.5f +- %.5f (stat %.3f %%); %s %.5f: %+.3f %%; %s %.5f: %+.3f "
            "%%; "
            "half-run drift %+.1f sigma; %llu collisions, %.1f s\n",
            dim, (unsigned long long)r.n, nu, r.pRed.mean, r.pRed.error, 100 * r.pRed.error / r.pRed.mean,
            dim == 2 ? "Henderson" : "Carnahan-Starling", theory, 100 * rel,
            dim == 2 ? "virial B2..B10" : "Kolafa", reference, 100 * relRef, r.drift,
            (unsigned long long)r.collisions, r.seconds);
        EXPECT_LT(r.pRed.error / r.pRed.mean, 0.003) << "statistics too poor for a 1 % test";
        EXPECT_LT(std::abs(r.drift), 4) << "not equilibrated: the two halves of the run differ";
        if (dim == 2 && nu > 0.55)
            EXPECT_LT(std::abs(relRef), 0.01)
                << "Henderson is off by itself here; the reference is the virial series";
        else
            EXPECT_LT(std::abs(rel), 0.01) << dim << "D nu " << nu;
        // The accurate references allow a much tighter check (stat error < 0.1 %, finite size ~0.1 %).
        EXPECT_LT(std::abs(relRef), 0.005) << dim << "D nu " << nu;
    }
}

// AT-7 / spec 4.4: collision frequency f = 2 C/(N t) against Enskog, f_E = D 2^(D-1) nu g sqrt(T/m)/
// (sqrt(pi) a), with the contact value g measured from the same run's pressure (P_red = 2^(D-1) nu g,
// spec Eq. 4.45). In equilibrium both follow from g(2a) exactly, so the ratio tests the collision
// statistics (collision-weighted normal speed <|v_n|> = sqrt(pi T/m)) and the virial bookkeeping.
TEST(EdmdValidation, CollisionFrequencyMatchesEnskogWithMeasuredContactValue) {
    const std::pair<int, Real> cases[] = {{2, 0.3}, {2, 0.5}, {2, 0.6}, {3, 0.3}, {3, 0.45}};
    for (const auto& [dim, nu] : cases) {
        const EosRun& r = eosRun(dim, nu);
        const Real gMeasured = r.pRed.mean / (std::pow(2.0, dim - 1) * nu);
        const Real fAnalytic = kt::enskogCollisionFrequency(dim, nu, 1, 1, 1);
        std::printf(
            "[f_E %dD N=%llu nu=%.2f] f %.5f +- %.5f; g from P %.5f (%s %.5f); Enskog with measured g %.5f; "
            "f/f_E(g measured) - 1 = %+.3f %% +- %.3f %%; f/f_E(analytic g) - 1 = %+.3f %%\n",
            dim, (unsigned long long)r.n, nu, r.freq.mean, r.freq.error, gMeasured,
            dim == 2 ? "Henderson" : "CS", kt::contactValue(dim, nu),
            fAnalytic * gMeasured / kt::contactValue(dim, nu), 100 * (r.freqOverEnskog.mean - 1),
            100 * r.freqOverEnskog.error, 100 * (r.freq.mean / fAnalytic - 1));
        EXPECT_LT(r.freqOverEnskog.error, 0.003);
        EXPECT_LT(std::abs(r.freqOverEnskog.mean - 1), 0.01) << dim << "D nu " << nu;
    }
}

// Spec 4.6 "kinetic numbers at nu = 0.25" (m = a = T = 1), AT-7/AT-8: f_E = 0.8933 (2D), 3.5105 (3D);
// elastic P_red = 0.7917 (2D), 2.0741 (3D); N = 4096, 2e6 collisions each. Measured: 2D f -0.01 %,
// P_red +0.10 %; 3D f +0.25 %, P_red +0.29 % -- the 3D offset is Carnahan-Starling's own error
// (Kolafa's EOS gives P_red 2.0797 at 0.25, measured 2.0800 +- 0.0028).
TEST(EdmdValidation, SpecKineticNumbersAtQuarterFilling) {
    struct Case {
        int dim;
        Real fE, pRed;
    };
    for (const Case c : {Case{2, 0.8933, 0.7917}, Case{3, 3.5105, 2.0741}}) {
        const EosRun& r = eosRun(c.dim, 0.25, 2000000);
        const Real T = 1;  // makeInitialState sets exactly T0 = 1; elastic runs keep it
        std::printf(
            "[nu=0.25 %dD N=%llu] f %.5f +- %.5f vs spec %.4f (%+.2f %%); P_red %.5f +- %.5f vs spec %.4f "
            "(%+.2f %%); kinetic_theory: f_E %.5f, P_red %.5f; %.1f s\n",
            c.dim, (unsigned long long)r.n, r.freq.mean, r.freq.error, c.fE, 100 * (r.freq.mean / c.fE - 1),
            r.pRed.mean, r.pRed.error, c.pRed, 100 * (r.pRed.mean / c.pRed - 1),
            kt::enskogCollisionFrequency(c.dim, 0.25, T, 1, 1), kt::reducedPressure(c.dim, 0.25), r.seconds);
        EXPECT_NEAR(kt::enskogCollisionFrequency(c.dim, 0.25, T, 1, 1), c.fE, 1e-4);
        EXPECT_NEAR(kt::reducedPressure(c.dim, 0.25), c.pRed, 1e-4);
        EXPECT_LT(std::abs(r.freq.mean / c.fE - 1), 0.015);
        EXPECT_LT(std::abs(r.pRed.mean / c.pRed - 1), 0.015);
    }
}
