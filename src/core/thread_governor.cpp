// SPDX-License-Identifier: MIT
// The automatic thread count: measured trials of larger and smaller teams (core/thread_governor.hpp).
#include "core/thread_governor.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace granulab {

namespace {
std::string threadsWord(int n) {
    return fmt::format("{} thread{}", n, n == 1 ? "" : "s");
}
}  // namespace

void ThreadGovernor::setExplicit(int threads) noexcept {
    m_automatic = false;
    m_explicit = std::max(1, threads);
    m_team = m_explicit;
    m_probing = false;
}

void ThreadGovernor::setAutomatic(int cores) noexcept {
    m_automatic = true;
    m_cores = std::max(1, cores);
    m_team = 1;  // the safe start: one thread never waits for a core that another job holds
    m_probing = false;
    m_sampling = false;
    m_busyIdle = -1;
    m_cost = -1;
    startWindow();
}

int ThreadGovernor::limit() const noexcept {
    return m_automatic ? std::max(1, std::min(m_cores, m_byWork)) : m_explicit;
}

void ThreadGovernor::setWorkLimit(int byWork, std::string why) {
    m_byWork = std::max(1, byWork);
    m_workWhy = std::move(why);
    if (!m_automatic) return;
    const int most = limit();
    if (m_probing && m_probeTeam > most) {
        m_probing = false;
        startWindow();
    }
    if (m_team > most) {  // fewer particles (an outlet): the team shrinks, and is measured anew
        m_probing = false;
        m_team = most;
        m_cost = -1;
        startWindow();
    }
}

int ThreadGovernor::neighbour(int team, bool up) const noexcept {
    const int most = limit();
    if (up) return team >= most ? 0 : std::min(most, 2 * team);
    return team <= 1 ? 0 : team / 2;
}

void ThreadGovernor::restartSample() {
    if (!m_probe.start || !m_probe.read) return;
    m_probe.start();
    m_sampling = true;
}

bool ThreadGovernor::coresLookFree(int next) {
    if (!m_probe.start || !m_probe.read) return true;
    const double idle = m_sampling ? m_probe.read() : -1;
    restartSample();
    if (idle < 0 || idle >= kFreeShare * (next - m_team)) {
        m_busyIdle = -1;
        return true;
    }
    // Busy: other programs hold the cores that the larger team would need.
    m_busyIdle = idle;
    m_busyTeam = next;
    ++m_busySkips;
    m_backoffUp = std::min(kMaxBackoff, 2 * m_backoffUp);
    m_nextUp = m_clock + m_backoffUp;
    return false;
}

bool ThreadGovernor::stepDone(double seconds) {
    if (!m_automatic || limit() <= 1) return false;
    if (!m_sampling && !m_probing) restartSample();  // the idle cores from the first step on
    m_clock += seconds;
    ++m_windowSteps;
    m_windowSeconds += seconds;
    if (m_probing) {
        ++m_trialSteps;
        m_trialSeconds += seconds;
    }
    if (m_probing && m_warmup) {
        // The trial team's first step is not measured: it starts or wakes the threads, and their
        // caches, the force split and the per-thread slots are new (on the idle 2-core VM it took
        // ten times a step of one thread, and a trial of 2 threads on 10,000 disks was judged
        // 9x slower than one thread, where it is 1.3x faster).
        m_warmup = false;
        startWindow();
        return false;
    }
    const bool full = (m_windowSeconds >= kWindow && m_windowSteps >= kWindowSteps) ||
                      (m_windowSeconds >= kLongWindow && m_windowSteps >= kLongWindowSteps);
    if (m_probing) {
        // Lost already: slower by kLose than the team's pace over the same steps, with a slack of
        // two of its steps.
        const double pace = m_cost * m_windowSteps;
        if (m_windowSeconds > kLose * pace + 2 * m_cost) {
            endTrial(false, pace / m_windowSeconds);
            return true;
        }
        if (!full) return false;
        const double cost = m_windowSeconds / m_windowSteps;
        endTrial(cost < kWin * m_cost, m_cost / cost);
        return true;
    }
    if (!full) return false;
    const double cost = m_windowSeconds / m_windowSteps;
    m_cost = m_cost < 0 ? cost : 0.5 * (m_cost + cost);  // smoothed over the team's windows
    startWindow();
    // A trial when one is due: a larger team first (the machine may have cores to spare), else a
    // smaller one (the cores may have become busy).
    for (const bool up : {true, false}) {
        const int next = neighbour(m_team, up);
        if (next == 0 || m_clock < (up ? m_nextUp : m_nextDown)) continue;
        if (up && !coresLookFree(next)) continue;
        m_sampling = false;  // measured again from the trial's end
        m_probing = true;
        m_warmup = true;
        m_trialSteps = 0;
        m_trialSeconds = 0;
        m_probeTeam = next;
        ++m_trials;
        return true;
    }
    return false;
}

void ThreadGovernor::endTrial(bool won, double ratio) noexcept {
    const bool up = m_probeTeam > m_team;
    m_comparedTeam = m_probeTeam;
    m_comparedWith = m_team;
    m_comparedRatio = ratio;
    double& backoff = up ? m_backoffUp : m_backoffDown;
    double& next = up ? m_nextUp : m_nextDown;
    if (won) {
        m_team = m_probeTeam;
        m_cost = -1;  // measured afresh on its own windows
        ++m_changes;
        backoff = kFirstBackoff;
        next = m_clock;  // go on in the same direction at once
        // The way back is tried later, as a check that the cores stay free (or stay busy).
        (up ? m_nextDown : m_nextUp) = m_clock + kFirstBackoff;
        (up ? m_backoffDown : m_backoffUp) = kFirstBackoff;
    } else {
        backoff = std::min(kMaxBackoff, 2 * backoff);
        // The next try waits until this one's loss is at most kTrialBudget of the run time.
        const double lost = std::max(0.0, m_trialSeconds - m_cost * m_trialSteps);
        next = m_clock + std::max(backoff, lost / kTrialBudget);
    }
    m_probing = false;
    startWindow();
}

std::string ThreadGovernor::reason() const {
    const int now = team();
    if (!m_automatic) return threadsWord(now) + ": asked for (--threads / run.threads)";
    if (m_cores <= 1) return "1 thread: this process may use 1 core";
    if (m_byWork <= 1) return "1 thread: " + m_workWhy;
    if (m_busyIdle >= 0)
        return fmt::format(
            "{}: the other cores are busy ({:.2f} of a core idle; {} are tried when {:.1f} are idle)",
            threadsWord(now), m_busyIdle, threadsWord(m_busyTeam), kFreeShare * (m_busyTeam - m_team));
    if (m_comparedTeam == 0)
        return fmt::format("{}: trying up to {} (the fastest is measured during the run)", threadsWord(now),
                           limit());
    // The last trial compared the team in use with another one.
    const bool trialWon = m_comparedTeam == m_team;
    const int other = trialWon ? m_comparedWith : m_comparedTeam;
    const double speed = trialWon ? m_comparedRatio : 1.0 / m_comparedRatio;  // team in use / other
    std::string note =
        fmt::format("{}: {:.2f}x the speed of {}, measured", threadsWord(m_team), speed, threadsWord(other));
    if (m_team < other && speed > 1.5) note += " (the cores are busy)";
    return note;
}

}  // namespace granulab
