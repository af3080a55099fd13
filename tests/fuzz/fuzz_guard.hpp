// SPDX-License-Identifier: MIT
// The fuzz harness's safety net: the engines' stdout/stderr silenced (the harness keeps its own
// copies), and handlers that save the input being run when the process dies on it: a crash
// signal (SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT), a sanitizer error, or the per-input limit
// (a hang: SIGPROF after that much CPU time, SIGALRM after four times as much wall time). The
// handler prints the summary counters before the process ends.
#pragma once
#include <cstdint>
#include <string>

namespace granulab::fuzz {

/// Exit status of the harness when an input hangs (as timeout(1) reports a time-out).
constexpr int kExitHang = 124;

/// Outcome counters; the crash handlers print them too, so a run that dies still reports.
struct Counters {
    std::uint64_t mutants = 0, ok = 0, badInput = 0, unstable = 0, exceptions = 0;
};
Counters& counters();

/// The one-line machine-readable summary ("fuzz-summary mutants=... crashes=... hangs=...").
std::string summaryLine(std::uint64_t crashes, std::uint64_t hangs);

/// Sends fds 1 and 2 to /dev/null (engines print progress and warnings there); the harness
/// writes through say()/report(). Sanitizer reports go to the harness's stderr.
void silenceEngines();
void say(const std::string& text);     ///< the harness's stderr (progress, findings)
void report(const std::string& text);  ///< the harness's stdout (summary, replay results)

/// Installs the crash, hang and sanitizer handlers; `hangSeconds` is the per-input CPU limit.
void installHandlers(unsigned hangSeconds);

/// The input run next: saved as DIR/crash-<hash>.toml or DIR/hang-<hash>.toml (with a .txt
/// note naming `origin` and the stage) if the process dies on it; DIR empty: not saved. The
/// text must outlive the run. Starts the hang alarm; endInput() stops it.
void beginInput(const std::string& text, const std::string& findingsDir, const std::string& origin);
void endInput();

/// What the input is doing now ("read", "info", "build", "start", "advance"), for the notes.
void setStage(const char* stage);

/// Saves a finding that did not kill the process (an unexpected exception) as
/// DIR/<kind>-<hash>.toml with a .txt note; returns the path.
std::string saveFinding(const std::string& kind, const std::string& text, const std::string& findingsDir,
                        const std::string& note);

}  // namespace granulab::fuzz
