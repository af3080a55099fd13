// SPDX-License-Identifier: MIT
// One fuzz input, run in process as `granulab info` and the start of `granulab run` would: the
// scene read through the engine table, the engine's info, its build, start() and a bounded
// advance over the run loop's own stops (app/run_loop.cpp). Bad input (SceneError, exit 2) and
// a failed advance (SimStatus, exit 3) are accepted outcomes; any other exception is a finding.
#pragma once
#include <cstddef>
#include <string>

namespace granulab::fuzz {

enum class Outcome { Ok, BadInput, Unstable, Finding };

struct RunResult {
    Outcome outcome = Outcome::Ok;
    std::string message;  ///< first line of the error or diagnosis; the exception of a finding
};

struct RunLimits {
    int slices = 200;                   ///< advance in at most this many slices ...
    double runSeconds = 1.0;            ///< ... and stop slicing after this CPU time [s]
    double sliceFraction = 1e-3;        ///< a slice: this fraction of the run (time or count) ...
    std::uint64_t sliceCount = 100000;  ///< ... and at most this many steps or collisions
    /// Larger scenes are read, described and built but not started: a valid scene of millions
    /// of particles is slow, not stuck, and would be reported as a hang.
    std::size_t maxParticles = 20000;
};

/// Runs `text` (named `path` in messages). Never throws; crashes and hangs end the process
/// (fuzz_guard.hpp saves the input).
RunResult runScene(const std::string& text, const std::string& path, const RunLimits& limits);

/// "ok", "bad input", "unstable", "FINDING".
const char* outcomeName(Outcome outcome);

}  // namespace granulab::fuzz
