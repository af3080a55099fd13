// SPDX-License-Identifier: MIT
// The thread count of a run that leaves it open (run.threads = 0): a default that never loses by
// much, on an idle machine or a busy one (docs/physics/dem-threads.md, "How the default is chosen";
// gc2d spec section 5.4 runs the step's phases on threads). The results of the DEM step do not
// depend on the thread count (dem/slot_tiles.hpp), so the count may change at any step. The
// governor starts on one thread, runs a larger team for a short window of steps, keeps whichever
// had the shorter wall time per step (a trial's first step, which starts its threads, is not
// measured), and measures again from time to time (less often after each
// try that lost), so that it follows a machine whose cores become busy (other runs, a build) or
// idle again. A trial that is clearly slower stops after a step or two: on busy cores a barrier may
// wait for a whole time slice of the operating system. Before it tries a larger team it asks how
// many cores were idle (core/idle_cores.hpp) and waits while the cores are busy with other work.
// Where each thread would get less work than a barrier costs, it stays on one thread without
// trying. An explicit count is used as it is.
#pragma once
#include <cstdint>
#include <functional>
#include <string>

namespace granulab {

class ThreadGovernor {
public:
    /// Exactly `threads` threads (run.threads > 0 or --threads): never measured, never changed.
    void setExplicit(int threads) noexcept;
    /// Automatic: at most `cores` threads (those this process may use; defaultThreads()).
    void setAutomatic(int cores) noexcept;
    /// The most threads the work can use (>= 1) and why, e.g. "512 polygons is below the threaded
    /// size (2 x 256)"; shown as the reason when it is what keeps the run on fewer threads.
    void setWorkLimit(int byWork, std::string why);
    /// The machine's idle cores, asked before a larger team is tried: start() begins an interval,
    /// read() returns the cores idle on average over it (< 0: unknown). Without a probe (or while
    /// it answers unknown) every due trial runs and its measurement alone decides.
    struct IdleProbe {
        std::function<void()> start;
        std::function<double()> read;
    };
    void setIdleProbe(IdleProbe probe) { m_probe = std::move(probe); }
    /// Reports the wall time [s] of the step just done; true when team() changes for the next step.
    bool stepDone(double seconds);

    /// Threads for the next step.
    int team() const noexcept { return m_probing ? m_probeTeam : m_team; }
    bool automatic() const noexcept { return m_automatic; }
    /// The most threads the run may use now: the explicit count, or min(cores, work limit).
    int limit() const noexcept;
    /// Why team() threads run, in words ("2 threads: 1.74x the speed of 1 thread, measured").
    std::string reason() const;
    /// Trial windows run, and how often the team changed.
    std::uint64_t trials() const noexcept { return m_trials; }
    std::uint64_t changes() const noexcept { return m_changes; }
    /// Due trials of a larger team put off because the cores were busy.
    std::uint64_t busySkips() const noexcept { return m_busySkips; }

    /// [s] shortest trial window and fewest steps in it; [s] of steps between the first tries.
    static constexpr double kWindow = 0.02;
    static constexpr int kWindowSteps = 16;
    /// [s] a window of long steps (large scenes: 5-10 ms each) is full after kLongWindow and
    /// kLongWindowSteps steps, so that the run does not spend 16 of them on the slower team.
    static constexpr double kLongWindow = 0.05;
    static constexpr int kLongWindowSteps = 4;
    static constexpr double kFirstBackoff = 0.25, kMaxBackoff = 30.0;
    /// A trial wins when its time per step is below kWin times the current team's; it has lost
    /// as soon as its time passes kLose times the current team's for the same steps (plus slack).
    static constexpr double kWin = 0.93, kLose = 1.25;
    /// A lost trial's extra wall time (over the current team's pace for its steps) is at most this
    /// fraction of the run time before the next one: on busy cores one trial step can take a
    /// whole time slice of the operating system (10-20 ms against 0.03 ms on one thread).
    static constexpr double kTrialBudget = 0.02;
    /// A due trial of a larger team runs if, since the run's start or the last trial or check,
    /// at least kFreeShare of a core was idle for each thread it would add (or the probe cannot
    /// tell: /proc/stat counts in ticks of 10 ms, so the first check, after the first window of
    /// 20 ms, sees two ticks per core).
    static constexpr double kFreeShare = 0.5;

private:
    void startWindow() noexcept {
        m_windowSteps = 0;
        m_windowSeconds = 0;
    }
    /// Ends the trial: the trial team becomes the team if it won.
    void endTrial(bool won, double ratio) noexcept;
    /// The next larger (up) or smaller team to try from `team`, or 0 if none.
    int neighbour(int team, bool up) const noexcept;
    /// False when the idle cores since the last check are too few for a trial of `next` threads
    /// (the trial is then put off as a lost one would be); starts the next interval.
    bool coresLookFree(int next);
    /// Starts the probe's interval (the cores' idle time on the current team) now.
    void restartSample();

    bool m_automatic = false;
    int m_explicit = 1;
    int m_cores = 1;
    int m_byWork = 1;
    std::string m_workWhy;
    int m_team = 1;
    bool m_probing = false;
    bool m_warmup = false;  ///< the trial's first step is still to come (not measured)
    int m_probeTeam = 1;
    int m_windowSteps = 0;
    double m_windowSeconds = 0;
    int m_trialSteps = 0;       ///< steps of the running trial, its first step included
    double m_trialSeconds = 0;  ///< [s] their wall time
    double m_cost = -1;         ///< [s] per step of m_team (smoothed); < 0: not measured yet
    double m_clock = 0;         ///< [s] sum of the reported step times
    double m_nextUp = 0;        ///< m_clock at which the next larger team may be tried
    double m_nextDown = 0;
    double m_backoffUp = kFirstBackoff, m_backoffDown = kFirstBackoff;
    // The last comparison, for reason(): team `m_comparedTeam` ran at m_comparedRatio times the
    // speed of `m_comparedWith` (> 1: faster).
    int m_comparedTeam = 0, m_comparedWith = 0;
    double m_comparedRatio = 0;
    std::uint64_t m_trials = 0, m_changes = 0, m_busySkips = 0;
    IdleProbe m_probe;
    bool m_sampling = false;  ///< the probe's interval is running
    double m_busyIdle = -1;   ///< idle cores at the last check that put a trial off; < 0: none since
    int m_busyTeam = 0;       ///< the team that check wanted to try
};

}  // namespace granulab
