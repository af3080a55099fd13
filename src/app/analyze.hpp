// SPDX-License-Identifier: MIT
// `granulab analyze DIR` (gas measurements of a finished edmd run, edmd spec 5.2) and
// `granulab master-equation` (the cluster-population model, edmd Eq. 5.31, checklist item 32).
#pragma once
#include <string>

#include "analysis/master_equation.hpp"

namespace granulab::app {

struct AnalyzeOptions {
    std::string dir;
    double rMaxRadii = 10;        ///< g(r) range in radii
    int bins = 200;               ///< g(r) bins
    double delta = 0.1;           ///< cluster criterion delta/2a
    double particlesPerBin = 40;  ///< density coarse-graining
    bool quiet = false;
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
