// SPDX-License-Identifier: MIT
// `granulab analyze DIR` (dispatched through the engine table to the engine that wrote DIR) and
// `granulab master-equation` (edmd Eq. 5.29-5.31, spec 7 item 32).
#include "app/analyze.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/engine_table.hpp"
#include "app/exit_codes.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void badInput(const std::string& where, const std::string& what) {
    throw SceneError(makeDiagnostic(where, 0, "", what));
}

}  // namespace

int analyzeCommand(const AnalyzeOptions& opt) {
    const std::string summaryPath = opt.dir + "/summary.json";
    std::ifstream summaryFile(summaryPath);
    if (!summaryFile) badInput(summaryPath, "cannot open: is this the output folder of a granulab run?");
    nlohmann::json summary;
    try {
        summary = nlohmann::json::parse(summaryFile);
    } catch (const std::exception& e) {
        badInput(summaryPath, fmt::format("not valid JSON ({})", e.what()));
    }
    const std::string engine = summary.value("engine", "");
    const EngineEntry* entry = findEngine(engine);
    if (entry == nullptr)
        badInput(summaryPath, fmt::format("engine '{}' is not one of {}", engine, engineNamesText()));
    if (entry->analyze == nullptr)
        badInput(summaryPath, fmt::format("`granulab analyze` has no analyses of {} runs yet; {}", engine,
                                          entry->analyzeLater));
    return entry->analyze(opt, summary);
}

int masterEquationCommand(const MasterEquationOptions& opt) {
    analysis::MasterEquation eq(opt.params);  // std::invalid_argument -> message in main
    std::vector<Real> times;
    for (int k = 0; k < opt.points; ++k)
        times.push_back(opt.tEnd *
                        std::pow(1e-4, 1.0 - static_cast<double>(k) / std::max(1, opt.points - 1)));
    const auto result = eq.integrate({}, times);
    std::string moments = "t,M1,M2,total,mass\n", dist = "t,s,p_s\n";
    for (const auto& sample : result.samples) {
        moments += fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", sample.t, sample.m1, sample.m2,
                               sample.total, sample.mass);
        for (std::size_t s = 0; s < sample.p.size(); ++s)
            if (sample.p[s] > 0) dist += fmt::format("{:.10g},{},{:.10g}\n", sample.t, s + 1, sample.p[s]);
    }
    io::writeFileAtomically(opt.out + "_moments.csv", moments);
    io::writeFileAtomically(opt.out + "_distributions.csv", dist);
    const auto& last = result.samples.back();
    fmt::print(
        "master equation (edmd Eq. 5.31{}): S_max {}, lambda/(beta0/alpha0)^2 = {:.4g}, xi {}; {} steps\n",
        opt.params.symmetricGain ? ", symmetric gain" : ", as printed", opt.params.maxSize,
        opt.params.lambda / std::pow(opt.params.beta0 / opt.params.alpha0, 2), opt.params.xi,
        result.acceptedSteps);
    fmt::print("at t = {:.4g}: M1 {:.4g}, M2 {:.4g}; files {}_moments.csv, {}_distributions.csv\n", last.t,
               last.m1, last.m2, opt.out, opt.out);
    return kExitOk;
}

}  // namespace granulab::app
