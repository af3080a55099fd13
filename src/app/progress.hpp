// SPDX-License-Identifier: MIT
// Run progress: a bar with simulated time, steps/s and ETA on a terminal; plain log lines every
// 10 s of wall time otherwise (CI logs, pipes).
#pragma once
#include <cstdint>
#include <functional>
#include <string>

namespace granulab::app {

class Progress {
public:
    /// `end`: the end position, simulated time [s] or (byCount) the engine's count; `unit`: what
    /// the rate counts.
    Progress(double end, bool quiet, std::string unit = "steps", bool byCount = false);
    /// Called at every stop of the run loop; cheap unless an update is due.
    void update(double simTime, std::int64_t steps);
    void finish(double simTime, std::int64_t steps);
    /// Text added to each line, asked for when a line is printed (how many threads run and why).
    void setNote(std::function<std::string()> note) { m_note = std::move(note); }

private:
    void print(double simTime, std::int64_t steps, bool final);
    std::function<std::string()> m_note;
    double m_endTime;
    std::string m_unit;
    bool m_byCount;
    bool m_quiet;
    bool m_tty;
    double m_start;
    double m_last;
    double m_startSimTime = -1;
    std::int64_t m_startSteps = 0;
    std::int64_t m_nextCheck = 0;
};

}  // namespace granulab::app
