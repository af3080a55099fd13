// SPDX-License-Identifier: MIT
// Progress bar / periodic log lines.
#include "app/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "core/timer.hpp"

namespace granulab::app {

namespace {
std::string clock(double seconds) {
    if (!(seconds >= 0) || seconds > 1e7) return "--:--";
    const auto s = static_cast<long>(seconds + 0.5);
    if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
    return fmt::format("{:02}:{:02}", s / 60, s % 60);
}
}  // namespace

Progress::Progress(double end, bool quiet, std::string unit, bool byCount)
    : m_endTime(end),
      m_unit(std::move(unit)),
      m_byCount(byCount),
      m_quiet(quiet),
      m_tty(isatty(fileno(stderr)) != 0),
      m_start(wallSeconds()),
      m_last(m_start) {}

void Progress::update(double simTime, std::int64_t steps) {
    if (m_quiet || steps < m_nextCheck) return;
    m_nextCheck = steps + 64;  // look at the clock only every 64 steps
    if (m_startSimTime < 0) {
        m_startSimTime = simTime;
        m_startSteps = steps;
    }
    const double now = wallSeconds();
    if (now - m_last < (m_tty ? 0.25 : 10.0)) return;
    m_last = now;
    print(simTime, steps, false);
}

void Progress::finish(double simTime, std::int64_t steps) {
    if (m_quiet) return;
    if (m_startSimTime < 0) {
        m_startSimTime = simTime;
        m_startSteps = steps;
    }
    print(simTime, steps, true);
}

void Progress::print(double simTime, std::int64_t steps, bool final) {
    const double elapsed = wallSeconds() - m_start;
    const double rate = elapsed > 0 ? static_cast<double>(steps - m_startSteps) / elapsed : 0;
    const double done = m_endTime > 0 ? std::clamp(simTime / m_endTime, 0.0, 1.0) : 1.0;
    const double simDone = simTime - m_startSimTime, simLeft = m_endTime - simTime;
    const double eta = simDone > 0 ? elapsed * simLeft / simDone : -1;
    const std::string note = m_note ? m_note() : std::string();
    const std::string tail = note.empty() ? note : ", " + note;
    if (m_tty) {
        constexpr int kWidth = 30;
        const int filled = static_cast<int>(done * kWidth);
        std::string bar(static_cast<std::size_t>(filled), '=');
        if (filled < kWidth) bar += '>' + std::string(static_cast<std::size_t>(kWidth - filled - 1), ' ');
        // The bar line stays short (one terminal line): the note's part before its colon.
        const std::string brief = note.substr(0, note.find(':'));
        std::fprintf(stderr, "\r[%s] %s%.4g / %.4g%s  %.3g %s/s  %s %s%s%s ", bar.c_str(),
                     m_byCount ? "" : "t = ", simTime, m_endTime, m_byCount ? "" : " s", rate, m_unit.c_str(),
                     final ? "elapsed" : "ETA", clock(final ? elapsed : eta).c_str(),
                     brief.empty() ? "" : "  ", brief.c_str());
        if (final) std::fputc('\n', stderr);
    } else {
        std::fprintf(stderr, "progress: %s%.6g / %.6g%s (%.1f %%), %lld %s, %.3g %s/s, %s %s%s\n",
                     m_byCount ? "" : "t = ", simTime, m_endTime, m_byCount ? "" : " s", 100 * done,
                     static_cast<long long>(steps), m_unit.c_str(), rate, m_unit.c_str(),
                     final ? "elapsed" : "ETA", clock(final ? elapsed : eta).c_str(), tail.c_str());
    }
    std::fflush(stderr);
}

}  // namespace granulab::app
