// SPDX-License-Identifier: MIT
// The straight silo of gc2d spec 8.3 end to end, reduced for CI: the scene
// examples/studies/silos/straight_reduced.toml (800 gc2d grains, r = 1 mm, 8-10 corners, mu = 0.5,
// a silo 2 cm wide) is run for two seeds; the last snapshots are read back, the stress grid
// (Eq. 2.52) is averaged over the width at each depth and Janssen's law is fitted to both seeds'
// profiles together. The bounds are physical, not tuned to the run:
//  * saturation: the column is deeper than Janssen's depth scale r/(k mu_j), i.e. the fit gives
//    k mu_j H/r > 1, and the measured sigma_zz at the bottom is below (1 - 1/e) rho g H, the value
//    at H = r/(k mu_j). Hydrostatic pressure (walls carrying no weight) fails both;
//  * wall friction: 0 < mu_j <= mu = 0.5, the Coulomb coefficient of the grain-wall contacts
//    (the mobilized friction cannot exceed it);
//  * k between Rankine's active and passive ratios (1 -+ sin phi)/(1 +- sin phi) for a bulk
//    friction angle phi = atan(mu) = 26.6 deg (0.38 .. 2.62); a real packing's angle is larger,
//    so these bounds are the narrower, stricter ones;
//  * the Janssen fit describes the profiles better than the best hydrostatic profile
//    (sigma_zz = rho g z, sigma_xx = k_h rho g z) with the same weighting;
//  * no compaction at the bottom: the packing fraction of the lower third of the column differs by
//    less than the thesis' spread 0.03 from that of the upper third.
// About 2 x 30 s on one core.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numeric>
#include <vector>

#include "../support.hpp"
#include "analysis/dem_grid.hpp"
#include "analysis/dem_packing.hpp"
#include "analysis/dem_stress.hpp"
#include "analysis/janssen.hpp"
#include "io/contact_file.hpp"
#include "io/vtk_reader.hpp"

using namespace granulab;

namespace {

constexpr double kHalfWidth = 0.01;  // [m] the reduced silo's walls at x = -+10 mm
constexpr double kMuWall = 0.5;      // grain-wall Coulomb coefficient of the scene
constexpr double kAreal = 5000.0;    // [kg/m^2] grain areal density of the scene
constexpr double kG = 9.81;          // [m/s^2]
constexpr double kWindowH = 0.015;   // [m] test areas 20 x 15 mm: ~90 grains each
constexpr double kWindowStep = 0.0075;

struct SiloRun {
    analysis::DepthProfile profile;
    double surface = 0;  ///< [m] highest grain top
    double rhoRel = 0;   ///< mean packing fraction of the column's test areas
    double rhoLower = 0, rhoUpper = 0;
};

SiloRun runSilo(const std::filesystem::path& dir, int seed) {
    const std::string scene =
        std::string(GRANULAB_SOURCE_DIR) + "/examples/studies/silos/straight_reduced.toml";
    const std::string out = fmt::format("out{}", seed);
    const auto r =
        test::runGranulab(fmt::format("run '{}' -q --out {} --set run.seed={}", scene, out, seed), dir, 300);
    EXPECT_EQ(r.status, 0) << r.output;
    SiloRun run;
    if (r.status != 0) return run;
    std::string particles;
    for (const auto& e : io::readPvd((dir / out / "snapshots.pvd").string()))
        if (e.part == 0) particles = e.file;  // the last snapshot
    const auto grains = io::readParticlesVtp((dir / out / particles).string());
    std::string contacts = particles;
    contacts.replace(contacts.find("particles_"), 10, "contacts_");
    contacts.replace(contacts.rfind(".vtp"), 4, ".npy");
    const auto forces = io::readContactsNpy((dir / out / contacts).string());
    run.surface = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < grains.size(); ++i)
        run.surface = std::max(run.surface, grains.y[i] + grains.radius[i]);
    // Full-width rows of test areas from the floor to one window below the surface.
    const auto grid = analysis::coveringGrid(-kHalfWidth, 0.0, kHalfWidth, run.surface - kWindowH,
                                             2 * kHalfWidth, kWindowH, 2 * kHalfWidth, kWindowStep);
    run.profile = analysis::depthProfile(analysis::stressGrid(grains, forces, grid), run.surface);
    const auto packing = analysis::packingGrid(grains, grid);
    std::vector<double> lower, upper, all;
    for (std::size_t k = 0; k < grid.count(); ++k) {
        const double y = grid.centre(k).y, rho = packing.simple[k];
        all.push_back(rho);
        if (y < run.surface / 3) lower.push_back(rho);
        if (y > 2 * run.surface / 3 - kWindowH) upper.push_back(rho);
    }
    const auto mean = [](const std::vector<double>& v) {
        return v.empty() ? std::nan("")
                         : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    };
    run.rhoRel = mean(all);
    run.rhoLower = mean(lower);
    run.rhoUpper = mean(upper);
    return run;
}

}  // namespace

TEST(Cli, StraightSiloSaturatesAsJanssenPredicts) {
    test::ScratchDir dir;
    std::vector<SiloRun> runs;
    for (int seed : {1, 2}) runs.push_back(runSilo(dir.path, seed));
    ASSERT_FALSE(HasFailure());

    // Both seeds' depth samples together, ascending in z.
    struct Sample {
        double z, sxx, szz;
    };
    std::vector<Sample> samples;
    double rhoRel = 0, height = 0, bottomRatio = 0;
    for (const auto& run : runs) {
        const auto& p = run.profile;
        ASSERT_GE(p.z.size(), 10u);
        for (std::size_t i = 0; i < p.z.size(); ++i) samples.push_back({p.z[i], p.sigmaXx[i], p.sigmaZz[i]});
        rhoRel += run.rhoRel / static_cast<double>(runs.size());
        height += run.surface / static_cast<double>(runs.size());
        EXPECT_LT(std::abs(run.rhoLower - run.rhoUpper), 0.03)
            << "compaction: lower third " << run.rhoLower << ", upper third " << run.rhoUpper;
    }
    std::sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.z < b.z; });
    std::vector<double> z, sxx, szz;
    for (const auto& s : samples) {
        z.push_back(s.z);
        sxx.push_back(s.sxx);
        szz.push_back(s.szz);
    }
    const double rho = rhoRel * kAreal;
    const auto shape = analysis::straightSilo(kHalfWidth);
    const auto fit = analysis::fitJanssen(shape, z, sxx, szz, rho, kG);
    ASSERT_TRUE(fit.converged);

    // sigma_zz at the bottom: the deepest row of each run against rho g z there.
    for (const auto& run : runs)
        bottomRatio +=
            run.profile.sigmaZz.back() / (rho * kG * run.profile.z.back()) / static_cast<double>(runs.size());

    // The best hydrostatic profile with the fit's weighting (root mean square of each profile).
    const auto rms = [](const std::vector<double>& v) {
        double s = 0;
        for (double x : v) s += x * x;
        return std::sqrt(s / static_cast<double>(v.size()));
    };
    const double sx = rms(sxx), sz = rms(szz);
    double num = 0, den = 0;
    for (std::size_t i = 0; i < z.size(); ++i) {
        num += sxx[i] * rho * kG * z[i];
        den += rho * kG * z[i] * rho * kG * z[i];
    }
    const double kh = num / den;
    double hydro = 0;
    for (std::size_t i = 0; i < z.size(); ++i) {
        const double t = rho * kG * z[i];
        hydro += std::pow((szz[i] - t) / sz, 2) + std::pow((sxx[i] - kh * t) / sx, 2);
    }
    hydro = std::sqrt(hydro / static_cast<double>(2 * z.size()));

    const double depthScale = kHalfWidth / (fit.k * fit.mu);
    const double kActive = (1 - std::sin(std::atan(kMuWall))) / (1 + std::sin(std::atan(kMuWall)));
    RecordProperty("k", fmt::format("{:.3f}", fit.k));
    RecordProperty("mu_j", fmt::format("{:.3f}", fit.mu));
    RecordProperty("rho_rel", fmt::format("{:.3f}", rhoRel));
    std::printf(
        "straight silo (2 seeds): k = %.3f, mu_j = %.3f, rho_rel = %.3f, H = %.3f m, r/(k mu_j) = %.3f m, "
        "sigma_zz(bottom)/(rho g z) = %.3f, fit rms %.3f vs hydrostatic %.3f, k by areas %.3f/%.3f\n",
        fit.k, fit.mu, rhoRel, height, depthScale, bottomRatio, fit.rms, hydro, runs[0].profile.kMean,
        runs[1].profile.kMean);

    EXPECT_GT(height / depthScale, 1.0) << "the column is not deeper than Janssen's depth scale";
    EXPECT_LT(bottomRatio, 1 - std::exp(-1.0)) << "sigma_zz at the bottom is not saturated";
    EXPECT_GT(fit.mu, 0.0);
    EXPECT_LE(fit.mu, kMuWall) << "mobilized wall friction above the Coulomb coefficient";
    EXPECT_GE(fit.k, kActive);
    EXPECT_LE(fit.k, 1 / kActive);
    EXPECT_LT(fit.rms, hydro) << "Janssen's law fits no better than hydrostatic pressure";
}
