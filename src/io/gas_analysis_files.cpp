// SPDX-License-Identifier: MIT
// Gas analysis files (edmd spec 5.2): formats documented in docs/scene-format.md "[edmd]".
#include "io/gas_analysis_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/gas_velocity.hpp"
#include "io/csv_writers.hpp"

namespace granulab::io {

GasAnalysisResult writeGasAnalysisFiles(const std::string& pathPattern, const analysis::PointSet& points,
                                        const analysis::DensityDistribution& density,
                                        const analysis::ClusterStats& clusters,
                                        const GasAnalysisSettings& settings, double time) {
    const auto path = [&](const char* kind) { return fmt::format(fmt::runtime(pathPattern), kind); };
    const int D = points.dim;
    GasAnalysisResult result;
    result.gContact = std::numeric_limits<Real>::quiet_NaN();
    Real minEdge = std::numeric_limits<Real>::infinity();
    for (int d = 0; d < D; ++d)
        if (points.periodic[d]) minEdge = std::min(minEdge, points.box[d]);
    const Real a = settings.radius;
    const Real rMax = std::min(settings.rMaxRadii * a, 0.499 * minEdge);
    std::string text;
    if (rMax > 2.2 * a) {
        const auto gr = analysis::pairCorrelation(points, rMax, settings.grBins);
        try {
            result.gContact = analysis::gContact(gr, 2 * a);
        } catch (const std::invalid_argument&) {  // bins too coarse near contact: no estimate
        }
        text = fmt::format(
            "# pair correlation g(r) at t = {:.10g} s (edmd Eq. 5.10, minimum image); r [m]\nr,g\n", time);
        for (std::size_t k = 0; k < gr.r.size(); ++k)
            text += fmt::format("{:.10g},{:.10g}\n", gr.r[k], gr.g[k]);
        writeFileAtomically(path("gr"), text);
    }
    const auto hist = analysis::velocityHistogram(points, 80);
    text = fmt::format("# velocity-component densities p(v) at t = {:.10g} s [s/m]; plot ln p against v^2\nv",
                       time);
    for (int d = 0; d < D; ++d) text += std::string(",p_") + "xyz"[d];
    text += "\n";
    for (std::size_t k = 0; k < hist.v.size(); ++k) {
        text += fmt::format("{:.10g}", hist.v[k]);
        for (int d = 0; d < D; ++d)
            text += fmt::format(",{:.10g}", hist.density[static_cast<std::size_t>(d)][k]);
        text += "\n";
    }
    writeFileAtomically(path("velocity"), text);
    text = fmt::format(
        "# local volume fraction distribution at t = {:.10g} s; quantiles 1/10/25/50/75/90/99 %:", time);
    for (const Real q : density.quantiles) text += fmt::format(" {:.6g}", q);
    text += "\nnu,probability_density\n";
    for (std::size_t k = 0; k < density.nu.size(); ++k)
        text += fmt::format("{:.10g},{:.10g}\n", density.nu[k], density.probabilityDensity[k]);
    writeFileAtomically(path("density"), text);
    text = fmt::format(
        "# cluster sizes at t = {:.10g} s, gap < {} x diameter (edmd Eq. 5.11); n_s and the hole-smoothed "
        "n_s of footnote 5\ns,n_s,n_s_smoothed\n",
        time, settings.clusterDelta);
    for (std::size_t s = 1; s < clusters.sizeCounts.size(); ++s)
        if (clusters.smoothedCounts[s] > 0)
            text += fmt::format("{},{},{:.10g}\n", s, clusters.sizeCounts[s], clusters.smoothedCounts[s]);
    writeFileAtomically(path("clusters"), text);
    return result;
}

}  // namespace granulab::io
