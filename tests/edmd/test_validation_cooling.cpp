// SPDX-License-Identifier: MIT
// Physics validation of the event-driven engine, freely cooling gases (edmd spec 4.3-4.6,
// 5.2-5.3, 5.7 AT-10 to AT-12): Haff's law with the kinetic-theory Enskog time below the
// clustering threshold (2D and 3D, TC model), and the clustering instability of 2D disks: a gas
// well below lambda_cl stays homogeneous, one well above clusters (largest cluster, local density
// distribution, energy above Haff).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "analysis/gas_clusters.hpp"
#include "analysis/gas_structure.hpp"
#include "gas_fixture.hpp"

using namespace granulab;
using namespace granulab::edmd;
using namespace granulab::edmd::validation;
namespace kt {  // the measurements (analysis) and the kinetic theory of the gas (edmd)
using namespace granulab::analysis;
using namespace granulab::edmd;
}  // namespace kt

namespace {

Real secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<Real>(std::chrono::steady_clock::now() - start).count();
}

/// Free cooling at nu = 0.25 from equilibrated elastic states (spec 4.2), TC model with
/// t_c = 1e-5 t_E: T(tau)/T_Haff(tau) at tau = tauStep, 2 tauStep, ... tauMax, averaged over
/// `seeds` independent runs; t_E from the kinetic theory (contact value at nu). Also the energy lost
/// per collision over the whole run in units of lambda <T> (1 for molecular chaos: a colliding
/// pair has <v_n^2> = 4 T/m in any dimension).
struct HaffRun {
    Real lambda = 0, lambdaCl = 0, lambdaSh = 0, tE = 0;
    std::vector<Real> tau, ratio;  ///< T/T_Haff averaged over the seeds
    Real lossPerCollision = 0;     ///< dissipated energy / (collisions lambda T), T per window
    std::uint64_t collisions = 0, tcElastic = 0;
    Real seconds = 0;
    Real worstUpTo(Real tauMax) const {
        Real w = 0;
        for (std::size_t k = 0; k < tau.size(); ++k)
            if (tau[k] <= tauMax + 1e-9) w = std::max(w, std::abs(ratio[k] - 1));
        return w;
    }
};

template <int D>
HaffRun haffRun(std::uint64_t n, Real eps, Real tauMax, Real tauStep, int seeds, std::uint64_t seed) {
    const auto start = std::chrono::steady_clock::now();
    const Real nu = 0.25;
    HaffRun r;
    r.lambda = kt::lambdaFromEps(eps);
    const Real lOpt = kt::opticalDepth(D, static_cast<Real>(n), nu);
    r.lambdaCl = kt::clusteringLambda(D, lOpt);
    r.lambdaSh = kt::shearLambda(D, lOpt);
    const int steps = static_cast<int>(std::lround(tauMax / tauStep));
    r.ratio.assign(static_cast<std::size_t>(steps), 0);
    Real lossSum = 0, lossWeight = 0;
    for (int s = 0; s < seeds; ++s) {
        auto e = makeGas<D>(n, nu, seed + static_cast<std::uint64_t>(s));
        equilibrate(e, 100);
        const Real T0 = temperature(e);
        r.tE = kt::enskogCollisionTime(D, nu, T0, 1, 1);
        Restitution rules;
        rules.eps = eps;
        e.setCollisionRules(rules, 1, 1e-5 * r.tE);
        r.tau.clear();
        for (int k = 1; k <= steps; ++k) {
            const Real tau = k * tauStep;
            // Fine windows for the loss per collision (T changes by < 1 % within one).
            for (int sub = 1; sub <= 10; ++sub) {
                const Real Ta = temperature(e), da = e.dissipatedEnergy();
                const auto ca = e.stats().collisions;
                e.runUntil(kt::haffTime(D, r.lambda, tau - tauStep + sub * tauStep / 10, r.tE));
                const auto dc = static_cast<Real>(e.stats().collisions - ca);
                lossSum += e.dissipatedEnergy() - da;
                lossWeight += dc * r.lambda * 0.5 * (Ta + temperature(e));
            }
            r.tau.push_back(tau);
            r.ratio[static_cast<std::size_t>(k - 1)] += temperature(e) / kt::haffTemperature(T0, tau) / seeds;
        }
        r.collisions += e.stats().collisions;
        r.tcElastic += e.stats().tcElastic;
    }
    r.lossPerCollision = lossSum / lossWeight;
    r.seconds = secondsSince(start);
    return r;
}

void printHaff(int dim, std::uint64_t n, int seeds, Real eps, const HaffRun& r) {
    std::printf(
        "[Haff %dD N=%llu x %d runs, nu=0.25, eps=%.3f, t_c=1e-5 t_E] lambda %.4f vs lambda_cl %.4f "
        "(lambda_sh %.4f), t_E %.4f; mean T/T_Haff:",
        dim, (unsigned long long)n, seeds, eps, r.lambda, r.lambdaCl, r.lambdaSh, r.tE);
    for (std::size_t k = 0; k < r.tau.size(); ++k)
        if (std::fmod(r.tau[k] + 1e-9, 0.5) < 1e-6) std::printf(" tau %.1f: %.4f", r.tau[k], r.ratio[k]);
    std::printf("; loss per collision / (lambda T) %.4f; %llu collisions (%llu TC-elastic), %.1f s\n",
                r.lossPerCollision, (unsigned long long)r.collisions, (unsigned long long)r.tcElastic,
                r.seconds);
}

}  // namespace

// AT-10 / spec 4.4: T(tau) = T0/(1 + tau)^2, tau = lambda t/(2 D t_E), below lambda_cl.
// Measured: the gas cools slightly slower than Haff, because the energy lost per collision is a
// little below lambda T (inelastic collisions leave correlated, slower relative normal velocities
// behind; molecular chaos is only approximate). The deficit grows with lambda and is larger in 2D:
// at nu = 0.25, 2D, loss/(lambda T) ~ 0.995 (eps 0.995), ~ 0.98-0.99 (eps 0.98), ~ 0.95 (eps 0.9); 3D
// eps 0.98 ~ 0.997. The Sonine a2 correction (1 + 3 a2/16, a2 ~ -0.009 in 2D) is only -0.2 %. For
// eps = 0.98 in 2D, T/T_Haff reaches ~1.011 at tau = 1, ~1.02 at tau = 2 and ~1.026 at tau = 3 (mean of
// 8 runs, N = 1024 and 2025 alike, so not a finite-size effect; one run scatters by ~1 %); the 2 %
// test therefore stops at tau = 1 in 2D (mean of 32 runs) and runs to tau = 3 in 3D (T/T_Haff ~
// 1.005 there). Cf. Soto, Piasecki and Mareschal, Phys. Rev. E 64, 031306 (2001): precollisional
// velocity correlations in dissipative hard disks lower the cooling rate below the Enskog value.
TEST(EdmdValidation, HomogeneousCoolingFollowsHaffsLaw) {
    {
        const auto r = haffRun<2>(1024, 0.98, 3, 0.25, 32, 21);
        printHaff(2, 1024, 32, 0.98, r);
        EXPECT_LT(r.lambda, 0.5 * r.lambdaCl);
        EXPECT_LT(r.worstUpTo(1), 0.02);
        EXPECT_NEAR(r.lossPerCollision, 1, 0.04);
    }
    {
        const auto r = haffRun<3>(4096, 0.98, 3, 0.25, 2, 41);
        printHaff(3, 4096, 2, 0.98, r);
        EXPECT_LT(r.lambda, 0.5 * r.lambdaCl);
        EXPECT_LT(r.worstUpTo(3), 0.02);
        EXPECT_NEAR(r.lossPerCollision, 1, 0.02);
    }
}

// AT-12 / spec 4.6, 5.3 at CI size: 2D, N = 4096, nu = 0.25 (l_opt 28.4, lambda_cl = pi^3/l_opt^2 =
// 0.0386). eps = 0.995 (lambda 0.01, a quarter of lambda_cl) stays homogeneous up to tau = 400 (the
// tau_hc = D^2/lambda it would cluster at if it were unstable); eps = 0.5 (lambda 0.75 = 19 lambda_cl,
// tau_hc 5.3) clusters. TC model t_c = 1e-5 t_E in both. Observables (spec 5.2): largest-cluster
// fraction q_x (links at gaps < delta, delta/2a = 0.1), the 10-90 % quantile range of the local volume
// fraction in bins of ~40 particles, and E/E_Haff. Measured at tau = 400: homogeneous q_x 0.002,
// quantile range 0.055 (the equilibrium spread: 2.56 nu sqrt(S(0)/40) ~ 0.06), E/E_Haff 1.016;
// clustered q_x 0.17 (0.1-0.33 from tau = 100 on, clusters merge and break), range 0.56, E/E_Haff 76.
TEST(EdmdValidation, ClusteringOnlyAboveThreshold) {
    const std::uint64_t n = 4096;
    const Real nu = 0.25;
    struct Observed {
        Real qx = 0, spread = 0, energyRatio = 0;
    };
    auto run = [&](Real eps, std::uint64_t collisionCap) {
        const auto start = std::chrono::steady_clock::now();
        auto e = makeGas<2>(n, nu, 31);
        equilibrate(e, 100);
        const Real T0 = temperature(e);
        const Real tE = kt::enskogCollisionTime(2, nu, T0, 1, 1);
        const Real lambda = kt::lambdaFromEps(eps);
        const Real lCl = kt::clusteringLambda(2, kt::opticalDepth(2, static_cast<Real>(n), nu));
        Restitution rules;
        rules.eps = eps;
        e.setCollisionRules(rules, 1, 1e-5 * tE);
        std::printf(
            "[clustering 2D N=%llu nu=0.25 eps=%.3f] lambda %.4f, lambda_cl %.4f (lambda/lambda_cl %.2f), "
            "tau_hc %.1f\n",
            (unsigned long long)n, eps, lambda, lCl, lambda / lCl, kt::homogeneousClusterTau(2, lambda));
        Observed o;
        for (const Real tau : {1.0, 5.0, 20.0, 100.0, 400.0}) {
            const Real t = kt::haffTime(2, lambda, tau, tE);
            // Cap the collisions (TC micro-collisions in clusters could explode if the engine broke).
            e.runCollisions(collisionCap - e.stats().collisions, t);
            if (e.stats().collisions >= collisionCap) {
                ADD_FAILURE() << "collision cap " << collisionCap << " reached before tau " << tau << " (eps "
                              << eps << ")";
                return o;
            }
            e.runUntil(t);
            const auto snap = snapshot(e);
            const auto cs = kt::computeClusterStats(kt::findClusters(snap, 0.1).sizes, n);
            const auto dd = kt::densityDistribution(snap);
            o = {cs.largestFraction, dd.quantiles[5] - dd.quantiles[1],
                 temperature(e) / kt::haffTemperature(T0, tau)};
            std::printf(
                "  tau %5.1f: q_x %.4f, M1 %.3f, local nu q10 %.3f q50 %.3f q90 %.3f (q90-q10 %.3f), "
                "E/E_Haff %.3f; %llu events, %llu collisions (%llu TC-elastic), %.1f s\n",
                tau, o.qx, cs.moment[1], dd.quantiles[1], dd.quantiles[3], dd.quantiles[5], o.spread,
                o.energyRatio, (unsigned long long)e.stats().events, (unsigned long long)e.stats().collisions,
                (unsigned long long)e.stats().tcElastic, secondsSince(start));
        }
        return o;
    };
    // Homogeneous: ~5e6 collisions (N D ln(1 + tau)/lambda); clustered: ~1e6, mostly inside clusters.
    const Observed homogeneous = run(0.995, 20000000), clustered = run(0.5, 20000000);
    EXPECT_LT(homogeneous.qx, 0.01);  // 41 disks; equilibrium largest cluster ~8
    EXPECT_LT(homogeneous.spread, 0.1);
    EXPECT_NEAR(homogeneous.energyRatio, 1, 0.05);
    EXPECT_GT(clustered.qx, 0.05);
    EXPECT_GT(clustered.spread, 0.3);
    EXPECT_GT(clustered.energyRatio, 10);
}
