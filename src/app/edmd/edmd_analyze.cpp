// SPDX-License-Identifier: MIT
// `granulab analyze` of an edmd output folder (edmd spec 5.2): g(r) and its contact value, p(v),
// local density quantiles, clusters and tau_p (edmd Eq. 5.15) of the final state.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/gas_clusters.hpp"
#include "analysis/gas_structure.hpp"
#include "analysis/gas_velocity.hpp"
#include "app/edmd/edmd_engine.hpp"
#include "app/exit_codes.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/gas_analysis_files.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void badInput(const std::string& where, const std::string& what) {
    throw SceneError(makeDiagnostic(where, 0, "", what));
}

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) out.push_back(cell);
    return out;
}

/// Column index of `name` in a CSV header; -1 if absent.
int column(const std::vector<std::string>& header, const std::string& name) {
    for (std::size_t k = 0; k < header.size(); ++k)
        if (header[k] == name) return static_cast<int>(k);
    return -1;
}

double toNumber(const std::string& text, const std::string& where) {
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used != text.size()) throw std::invalid_argument(text);
        return v;
    } catch (const std::exception&) {
        badInput(where, fmt::format("'{}' is not a number", text));
    }
}

}  // namespace

int edmdAnalyze(const AnalyzeOptions& opt, const nlohmann::json& summary) {
    const std::string summaryPath = opt.dir + "/summary.json";
    analysis::PointSet points;
    points.dim = summary.at("dimension").get<int>();
    const auto box = summary.at("box").get<std::vector<double>>();
    const auto periodic = summary.value("periodic", std::vector<bool>(box.size(), true));
    for (std::size_t d = 0; d < box.size() && d < 3; ++d) {
        points.box[d] = box[d];
        points.periodic[d] = periodic[d];
    }
    const int D = points.dim;
    // final.csv: id, shape, positions, velocities, spin, radius, mass, collisions.
    const std::string finalPath = opt.dir + "/final.csv";
    std::ifstream in(finalPath);
    if (!in) badInput(finalPath, "cannot open (the run did not finish?)");
    std::string line;
    std::getline(in, line);
    const auto header = splitCsv(line);
    const char* axes[] = {"x", "y", "z"};
    int cx[3], cv[3];
    for (int d = 0; d < D; ++d) {
        cx[d] = column(header, axes[d]);
        cv[d] = column(header, std::string("v") + axes[d]);
        if (cx[d] < 0 || cv[d] < 0)
            badInput(finalPath, fmt::format("missing column {} or v{}", axes[d], axes[d]));
    }
    const int cr = column(header, "radius"), cm = column(header, "mass");
    if (cr < 0 || cm < 0) badInput(finalPath, "missing column radius or mass");
    int lineNo = 1;
    while (std::getline(in, line)) {
        ++lineNo;
        if (line.empty()) continue;
        const auto cells = splitCsv(line);
        const std::string where = fmt::format("{}:{}", finalPath, lineNo);
        if (cells.size() != header.size())
            badInput(where, fmt::format("{} cells, the header has {}", cells.size(), header.size()));
        for (int d = 0; d < D; ++d) {
            double x = toNumber(cells[static_cast<std::size_t>(cx[d])], where);
            if (points.periodic[d]) x -= points.box[d] * std::floor(x / points.box[d]);
            points.x.push_back(std::clamp(x, 0.0, std::nextafter(points.box[d], 0.0)));
        }
        for (int d = 0; d < D; ++d)
            points.v.push_back(toNumber(cells[static_cast<std::size_t>(cv[d])], where));
        points.radius.push_back(toNumber(cells[static_cast<std::size_t>(cr)], where));
        points.mass.push_back(toNumber(cells[static_cast<std::size_t>(cm)], where));
    }
    const std::size_t n = points.size();
    if (n == 0) badInput(finalPath, "no particles");
    // The radius of g(2a) is the current one, from final.csv (grown spheres are larger than the
    // scene's edmd.radius; polydisperse gases: the smallest, as edmd.radius is).
    const double a = *std::min_element(points.radius.begin(), points.radius.end());
    fs::create_directories(opt.dir + "/analysis");
    const auto vel = analysis::velocityStats(points);
    analysis::DensityParams dp;
    dp.particlesPerBin = opt.particlesPerBin;
    const auto dens = analysis::densityDistribution(points, dp);
    const auto cs = analysis::computeClusterStats(analysis::findClusters(points, opt.delta).sizes, n);
    io::GasAnalysisSettings settings;
    settings.radius = a;
    settings.rMaxRadii = opt.rMaxRadii;
    settings.grBins = static_cast<std::size_t>(opt.bins);
    settings.clusterDelta = opt.delta;
    const double contact = io::writeGasAnalysisFiles(opt.dir + "/analysis/final_{}.csv", points, dens, cs,
                                                     settings, summary.value("sim_time", 0.0))
                               .gContact;

    // tau_p from the series (peak of M'_2 on a logarithmic tau axis, edmd Eq. 5.15).
    double tauP = std::nan("");
    std::ifstream series(opt.dir + "/series.csv");
    if (series && std::getline(series, line)) {
        const auto h = splitCsv(line);
        const int ct = column(h, "tau"), cm2 = column(h, "M2_reduced");
        std::vector<double> logTau, m2;
        while (ct >= 0 && cm2 >= 0 && std::getline(series, line)) {
            const auto c = splitCsv(line);
            if (c.size() != h.size()) continue;
            const double tau = std::atof(c[static_cast<std::size_t>(ct)].c_str());
            if (tau > 0) {
                logTau.push_back(std::log(tau));
                m2.push_back(std::atof(c[static_cast<std::size_t>(cm2)].c_str()));
            }
        }
        // A maximum at the last row is no peak yet: M'_2 is still rising (tau_p is reported as NaN).
        const bool peaked = logTau.size() >= 3 && std::max_element(m2.begin(), m2.end()) != m2.end() - 1;
        if (peaked) tauP = std::exp(analysis::tauPeak(logTau, m2));
    }
    nlohmann::json js = {{"particles", n},
                         {"g_contact", contact},
                         {"temperature", vel.temperature},
                         {"kurtosis", vel.pooled.kurtosis},
                         {"density_quantiles", dens.quantiles},
                         {"clusters", cs.clusterCount},
                         {"M1", cs.moment[1]},
                         {"M2", cs.moment[2]},
                         {"M1_reduced", cs.reducedMoment[1]},
                         {"M2_reduced", cs.reducedMoment[2]},
                         {"largest_cluster", cs.largest},
                         {"q_x", cs.largestFraction},
                         {"tau_p", tauP},
                         {"cluster_delta", opt.delta}};
    io::writeFileAtomically(opt.dir + "/analysis/final_summary.json", js.dump(2) + "\n");
    if (!opt.quiet) {
        fmt::print("{}: {} {} at t = {:.6g}\n", opt.dir, n, D == 2 ? "disks" : "spheres",
                   summary.value("sim_time", 0.0));
        fmt::print("  temperature {:.6g}, velocity kurtosis {:.4f} (Gaussian 3)\n", vel.temperature,
                   vel.pooled.kurtosis);
        fmt::print("  g(2a) {:.4f} (g(r) in analysis/final_gr.csv)\n", contact);
        fmt::print("  local volume fraction quantiles 1/10/25/50/75/90/99 %: {:.3f}\n",
                   fmt::join(dens.quantiles, " "));
        fmt::print(
            "  clusters (gap < {} d): {}, M1 {:.4g}, M2 {:.4g}, M'2 {:.4g}, largest {} (q_x = {:.4f})\n",
            opt.delta, cs.clusterCount, cs.moment[1], cs.moment[2], cs.reducedMoment[2], cs.largest,
            cs.largestFraction);
        if (std::isfinite(tauP))
            fmt::print("  tau_p (peak of M'_2 in series.csv) {:.4g}\n", tauP);
        else
            fmt::print("  tau_p: M'_2 has no peak in series.csv yet (still rising at the last row)\n");
        fmt::print("  files: {}/analysis/final_{{gr,velocity,density,clusters}}.csv, final_summary.json\n",
                   opt.dir);
    }
    return kExitOk;
}

}  // namespace granulab::app
