// SPDX-License-Identifier: MIT
// summary.json writer (io/summary.hpp).
#include "io/summary.hpp"

#include <stdexcept>

#include "core/memory.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"

namespace granulab::io {

void writeSummary(const std::string& path, const SummaryCommon& c, const nlohmann::json& engineKeys) {
    nlohmann::json js;
    js["engine"] = c.engine;
    js["version"] = kVersion;
    js["scene"] = c.scene;
    js["status"] = c.status == RunStatus::Completed     ? "completed"
                   : c.status == RunStatus::Interrupted ? "interrupted"
                                                        : "unstable";
    if (c.status == RunStatus::Unstable) js["diagnosis"] = c.diagnosis;
    if (c.status == RunStatus::Interrupted && !c.resumeCommand.empty()) js["resume"] = c.resumeCommand;
    js["particles"] = c.particles;
    js["sim_time"] = c.simTime;
    js["wall_time_s"] = c.wallTime;
    js["loop_time_s"] = c.loopTime;
    js["memory_bytes"] = c.memoryBytes;
    js["bytes_per_particle"] =
        c.particles > 0 ? static_cast<double>(c.memoryBytes) / static_cast<double>(c.particles) : 0.0;
    js["peak_rss_bytes"] = peakRssBytes();
    js["warnings"] = c.warnings;
    for (const auto& [key, value] : engineKeys.items()) {
        if (js.contains(key))
            throw std::logic_error("summary.json: engine key '" + key + "' repeats a common key");
        js[key] = value;
    }
    writeFileAtomically(path, js.dump(2) + "\n");
}

}  // namespace granulab::io
