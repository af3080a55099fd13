// SPDX-License-Identifier: MIT
// `granulab analyze DIR` (gas measurements of a finished edmd run, edmd spec 5.2) and
// `granulab master-equation` (the cluster-population model, edmd Eq. 5.31, checklist item 32).
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "analysis/master_equation.hpp"

namespace granulab::app {

struct AnalyzeOptions {
    std::string dir;
    double rMaxRadii = 10;        ///< g(r) range in radii
    int bins = 200;               ///< g(r) bins
    double delta = 0.1;           ///< cluster criterion delta/2a
    double particlesPerBin = 40;  ///< density coarse-graining
    bool quiet = false;
    // ---- dem (app/dem/dem_analyze.cpp; docs/analysis.md) --------------------------------------
    std::vector<std::string> what;   ///< analyses to run (empty: the engine's default set)
    double at = -1;                  ///< [s] analyse the snapshot nearest this time (< 0: the last)
    int every = 0;                   ///< analyse every Nth snapshot (0: one snapshot)
    std::string window;              ///< "W[:H]" [m] test areas (stress, packing, janssen, strain)
    std::string step;                ///< "SX[:SY]" [m] between test areas (default half the window)
    std::vector<std::string> walls;  ///< wall names or indices (pressure; default: all walls)
    std::string silo;                ///< "straight:R", "stepped:R1,R2,H0", "slanted:A,B", "parabolic:A,B"
    double surface = std::numeric_limits<double>::quiet_NaN();  ///< [m] free-surface height (janssen)
    std::string depth;      ///< "Z0:Z1" [m] janssen: fit only the depths in this range (default: all)
    double reference = -1;  ///< [s] the second snapshot (strain: unloaded; persistence: before)
    std::vector<std::string> ranges;  ///< "X0:X1" [m] surface ranges (roughness; repose halves)
    std::string region;               ///< "X0:X1,Y0:Y1" [m] grains counted (coordination, persistence)
    std::string kernel = "gauss";     ///< coarse: gauss | lucy
    double kernelWidth = 0;           ///< [m] coarse: Gaussian w or Lucy support c (0: the width rule)
    double halfWidth = 0;             ///< [m] pressure profile window half width b (0: 5 grain diameters)
    double binWidth = 0;              ///< [m] surface bins (0: one grain diameter)
};

/// Reads DIR/summary.json, DIR/final.csv and DIR/series.csv of an edmd run, writes
/// DIR/analysis/final_{gr,velocity,density,clusters}.csv and prints a summary (contact value,
/// kurtosis, density quantiles, cluster moments, tau_p). Exit status 2 on bad input.
int analyzeCommand(const AnalyzeOptions& options);

struct MasterEquationOptions {
    analysis::MasterEquationParams params;
    double tEnd = 10;                     ///< end time (units of 1/alpha0)
    int points = 50;                      ///< output times, logarithmic from tEnd/1e4
    std::string out = "master_equation";  ///< output prefix: PREFIX_moments.csv, PREFIX_distributions.csv
};

int masterEquationCommand(const MasterEquationOptions& options);

}  // namespace granulab::app
