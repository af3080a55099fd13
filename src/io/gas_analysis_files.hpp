// SPDX-License-Identifier: MIT
// The analysis files of a hard-sphere gas snapshot (edmd spec 5.2): g(r), velocity-component
// densities p(v), the local volume-fraction distribution and the cluster sizes n_s, as CSV.
// One writer for `granulab run` (every snapshot) and `granulab analyze` (the final state).
#pragma once
#include <cstddef>
#include <string>

#include "analysis/gas_clusters.hpp"
#include "analysis/gas_structure.hpp"
#include "analysis/point_set.hpp"

namespace granulab::io {

struct GasAnalysisSettings {
    Real radius = 0;      ///< [m] particle radius a (g(r) range and contact value)
    Real rMaxRadii = 10;  ///< g(r) up to this many radii (capped below half the periodic box)
    std::size_t grBins = 200;
    Real clusterDelta = 0.1;  ///< delta/2a (edmd Eq. 5.11)
};

/// What the files were made from, for summaries.
struct GasAnalysisResult {
    Real gContact = 0;  ///< g(2a) extrapolated from the bins above contact; NaN when g(r) was not computed
};

/// Writes the four files at pathPattern with "{}" replaced by gr, velocity, density and
/// clusters (g(r) only when its range exceeds the contact distance). The density distribution
/// and cluster statistics of the same snapshot are passed in (the caller computes them once).
GasAnalysisResult writeGasAnalysisFiles(const std::string& pathPattern, const analysis::PointSet& points,
                                        const analysis::DensityDistribution& density,
                                        const analysis::ClusterStats& clusters,
                                        const GasAnalysisSettings& settings, double time);

}  // namespace granulab::io
