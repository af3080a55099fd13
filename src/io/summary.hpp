// SPDX-License-Identifier: MIT
// summary.json, the one run summary of every engine (DESIGN.md "Contract"): the common keys
// written once here, the engine's own keys merged in (dem: steps, particle_steps_per_s, timers,
// ...; edmd: events, collisions, events_per_s, collisions_per_s, ...).
#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace granulab::io {

/// How a run ended: summary.json "status" is "completed", "interrupted" (SIGINT/SIGTERM, a
/// checkpoint to resume) or "unstable" (with "diagnosis").
enum class RunStatus { Completed, Interrupted, Unstable };

/// The keys every engine's summary.json has.
struct SummaryCommon {
    std::string engine;  ///< run.engine
    std::string scene;   ///< scene file
    RunStatus status = RunStatus::Completed;
    std::string diagnosis;      ///< why an unstable run stopped
    std::string resumeCommand;  ///< interrupted runs: the command that continues it ("" none)
    std::size_t particles = 0;
    double simTime = 0;           ///< [s] simulated time at the end
    double wallTime = 0;          ///< [s] whole command
    double loopTime = 0;          ///< [s] run loop (engine + outputs), this session
    std::size_t memoryBytes = 0;  ///< engine state [bytes]
    std::vector<std::string> warnings;
};

/// Writes `path` atomically: engine, version, scene, status, (diagnosis), (resume), particles, sim_time,
/// wall_time_s, loop_time_s, memory_bytes, bytes_per_particle, peak_rss_bytes, warnings, plus
/// `engineKeys` (an object; a key that repeats a common one throws std::logic_error).
void writeSummary(const std::string& path, const SummaryCommon& common, const nlohmann::json& engineKeys);

}  // namespace granulab::io
