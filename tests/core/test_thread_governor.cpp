// SPDX-License-Identifier: MIT
// The automatic thread count (core/thread_governor.hpp; docs/physics/dem-threads.md, "How the
// default is chosen"), driven by made-up step times: a larger team that is faster is taken, one
// that is slower is left within two steps, tries that lose come less and less often, a machine
// whose cores become busy is followed back to one thread, and an explicit count never changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "core/idle_cores.hpp"
#include "core/thread_governor.hpp"

using granulab::ThreadGovernor;

namespace {

/// Runs `steps` steps whose wall time is cost(team) [s]; returns how many steps ran on each team
/// (index = team, up to 8).
template <class Cost>
std::array<int, 9> drive(ThreadGovernor& g, int steps, Cost cost) {
    std::array<int, 9> on{};
    for (int k = 0; k < steps; ++k) {
        ++on[static_cast<std::size_t>(g.team())];
        g.stepDone(cost(g.team()));
    }
    return on;
}

}  // namespace

TEST(ThreadGovernor, AnExplicitCountIsKeptWhateverTheTimes) {
    ThreadGovernor g;
    g.setExplicit(3);
    g.setWorkLimit(1, "few particles");
    const auto on = drive(g, 10000, [](int team) { return team == 3 ? 1.0 : 1e-6; });
    EXPECT_EQ(on[3], 10000);
    EXPECT_EQ(g.trials(), 0u);
    EXPECT_NE(g.reason().find("asked for"), std::string::npos) << g.reason();
}

TEST(ThreadGovernor, BelowTheThreadedSizeItStaysOnOneThreadWithoutTrying) {
    ThreadGovernor g;
    g.setAutomatic(8);
    g.setWorkLimit(1, "512 particles is below the threaded size (1024 per thread)");
    const auto on = drive(g, 5000, [](int team) { return 1e-4 / team; });
    EXPECT_EQ(on[1], 5000);
    EXPECT_EQ(g.trials(), 0u);
    EXPECT_EQ(g.reason(), "1 thread: 512 particles is below the threaded size (1024 per thread)");
}

TEST(ThreadGovernor, OneCoreMeansOneThread) {
    ThreadGovernor g;
    g.setAutomatic(1);
    g.setWorkLimit(100, "");
    drive(g, 1000, [](int team) { return 1e-4 / team; });
    EXPECT_EQ(g.team(), 1);
    EXPECT_EQ(g.reason(), "1 thread: this process may use 1 core");
}

TEST(ThreadGovernor, ClimbsToTheFastestTeamOnIdleCores) {
    // 1 ms per step on one thread, 1.8x on 2, 3.2x on 4, 3.0x on 8 (memory-bound beyond 4).
    ThreadGovernor g;
    g.setAutomatic(8);
    g.setWorkLimit(64, "");
    const auto cost = [](int team) {
        switch (team) {
            case 1:
                return 1e-3;
            case 2:
                return 1e-3 / 1.8;
            case 4:
                return 1e-3 / 3.2;
            default:
                return 1e-3 / 3.0;
        }
    };
    const auto on = drive(g, 20000, cost);
    EXPECT_EQ(g.team(), 4) << g.reason();
    EXPECT_GT(on[4], 18000);  // found within the first windows, and kept
    EXPECT_NE(g.reason().find("4 threads: "), std::string::npos) << g.reason();
}

TEST(ThreadGovernor, TheFirstStepOfATrialStartsItsThreadsAndIsNotJudged) {
    // Idle cores, 2 threads 1.5x faster, but the first step of a new team costs 10 one-thread steps
    // (threads started or woken, caches cold): as on the 2-core VM with 10,000 disks.
    ThreadGovernor g;
    g.setAutomatic(2);
    g.setWorkLimit(2, "");
    int previous = g.team();
    const auto on = drive(g, 20000, [&](int team) {
        const bool first = team != previous;
        previous = team;
        if (first && team == 2) return 1e-3;
        return team == 1 ? 1e-4 : 1e-4 / 1.5;
    });
    EXPECT_EQ(g.team(), 2) << g.reason();
    EXPECT_GT(on[2], 15000);
    EXPECT_NE(g.reason().find("2 threads: 1.50x the speed of 1 thread"), std::string::npos) << g.reason();
}

TEST(ThreadGovernor, AShortRunOnBusyCoresPaysForOneTrialAtMost) {
    // 512 polygons on busy cores (the 2-core VM with a busy loop per core): 26 us per step on one
    // thread, 12 ms on two (each barrier waits for a time slice). A 0.4 s run must not lose more
    // than a few per cent to trials: after the first one lost ~24 ms, the next waits >= 1.2 s.
    ThreadGovernor g;
    g.setAutomatic(2);
    g.setWorkLimit(2, "");
    double wall = 0, wallOnOne = 0;
    for (int k = 0; k < 16000; ++k) {
        const double t = g.team() == 1 ? 26e-6 : 12e-3;
        wall += t;
        wallOnOne += 26e-6;
        g.stepDone(t);
    }
    EXPECT_EQ(g.team(), 1);
    EXPECT_EQ(g.trials(), 1u);
    EXPECT_LT(wall, 1.07 * wallOnOne) << "the trials cost more than 7 % of a 0.4 s run";
}

TEST(ThreadGovernor, LongStepsAreJudgedOnFewOfThem) {
    // A large scene: 10 ms per step on one thread, 5 ms on two. The run of 200 steps (1 s) must
    // not spend 16 steps on one thread before it tries two, nor 16 in each later check.
    ThreadGovernor g;
    g.setAutomatic(2);
    g.setWorkLimit(2, "");
    const auto on = drive(g, 200, [](int team) { return team == 1 ? 10e-3 : 5e-3; });
    EXPECT_EQ(g.team(), 2) << g.reason();
    // 5 steps of the first window (0.05 s), then checks of one thread that lose within 4 steps.
    EXPECT_LE(on[1], 14) << "steps on the slower team";
    EXPECT_GE(on[1], ThreadGovernor::kLongWindowSteps);
}

TEST(ThreadGovernor, LeavesASlowTrialWithinTwoStepsAndTriesLessOftenAfterEachLoss) {
    // Busy cores: two threads take 60 times as long per step (a barrier waits for a time slice).
    ThreadGovernor g;
    g.setAutomatic(2);
    g.setWorkLimit(2, "");
    int trialSteps = 0, longestTrial = 0, current = 0;
    double wall = 0, wallOnOne = 0;
    const int steps = 200000;  // 20 s of one-thread steps of 0.1 ms
    for (int k = 0; k < steps; ++k) {
        const int team = g.team();
        const double t = team == 1 ? 1e-4 : 6e-3;
        if (team == 2) {
            ++trialSteps;
            ++current;
            longestTrial = std::max(longestTrial, current);
        } else {
            current = 0;
        }
        wall += t;
        wallOnOne += 1e-4;
        g.stepDone(t);
    }
    EXPECT_EQ(g.team(), 1);
    EXPECT_LE(longestTrial, 2);
    // Tries at 0.25, 0.5, 1, 2, 4, 8, 16 s of run time and then every 30 s: a handful.
    EXPECT_LE(g.trials(), 8u);
    EXPECT_LT(wall, 1.01 * wallOnOne) << "the tries cost more than 1 %";
    EXPECT_NE(g.reason().find("1 thread: "), std::string::npos) << g.reason();
    EXPECT_NE(g.reason().find("the cores are busy"), std::string::npos) << g.reason();
    EXPECT_GT(trialSteps, 0);
}

TEST(ThreadGovernor, FollowsCoresThatBecomeBusyAndIdleAgain) {
    ThreadGovernor g;
    g.setAutomatic(2);
    g.setWorkLimit(2, "");
    bool busy = false;
    const auto cost = [&](int team) { return team == 1 ? 1e-3 : (busy ? 2e-2 : 0.55e-3); };
    drive(g, 2000, cost);  // 1-2 s: idle
    EXPECT_EQ(g.team(), 2);
    busy = true;
    drive(g, 20000, cost);  // another job took a core
    EXPECT_EQ(g.team(), 1) << g.reason();
    busy = false;
    drive(g, 100000, cost);  // ~100 s: it is gone
    EXPECT_EQ(g.team(), 2) << g.reason();
}

TEST(ThreadGovernor, FewerParticlesShrinkTheTeam) {
    ThreadGovernor g;
    g.setAutomatic(4);
    g.setWorkLimit(4, "");
    drive(g, 5000, [](int team) { return 1e-3 / team; });
    EXPECT_EQ(g.team(), 4);
    g.setWorkLimit(1, "100 particles is below the threaded size (1024 per thread)");
    EXPECT_EQ(g.team(), 1);
    EXPECT_EQ(g.limit(), 1);
}

namespace {
/// A made-up idle-core meter: `idle` cores idle over any interval; counts its readings.
struct FakeIdle {
    double idle = 0;
    int starts = 0, reads = 0;
    ThreadGovernor::IdleProbe probe() {
        return {[this] { ++starts; },
                [this] {
                    ++reads;
                    return idle;
                }};
    }
};

/// The automatic count on 2 cores, work for 2 threads, asking `meter` (which answers `idle`).
void automaticOnTwoCores(ThreadGovernor& g, FakeIdle& meter, double idle) {
    meter.idle = idle;
    g.setIdleProbe(meter.probe());
    g.setAutomatic(2);
    g.setWorkLimit(2, "");
}
}  // namespace

TEST(ThreadGovernor, BusyCoresPutTheTrialOffWithoutRunningIt) {
    // Other programs keep both cores busy (0.05 of a core idle): no trial of 2 threads runs, the
    // run stays on one thread, and the reason says why.
    ThreadGovernor g;
    FakeIdle meter;
    automaticOnTwoCores(g, meter, 0.05);
    const auto on = drive(g, 40000, [](int team) { return team == 1 ? 1e-4 : 1e-2; });  // 4 s
    EXPECT_EQ(on[2], 0);
    EXPECT_EQ(g.trials(), 0u);
    EXPECT_GT(g.busySkips(), 0u);
    EXPECT_LE(meter.reads, 10) << "the meter is read rarely (its backoff doubles)";
    EXPECT_NE(g.reason().find("1 thread: the other cores are busy (0.05 of a core idle"), std::string::npos)
        << g.reason();
}

TEST(ThreadGovernor, IdleCoresLetTheTrialRunAndItsMeasurementDecides) {
    ThreadGovernor g;
    FakeIdle meter;
    automaticOnTwoCores(g, meter, 1.0);
    const auto on = drive(g, 20000, [](int team) { return team == 1 ? 1e-4 : 0.6e-4; });
    EXPECT_EQ(g.team(), 2) << g.reason();
    EXPECT_GT(on[2], 18000);  // the first check, after the first window, lets the trial run
    EXPECT_EQ(g.busySkips(), 0u);
    EXPECT_NE(g.reason().find("2 threads: "), std::string::npos) << g.reason();
}

TEST(ThreadGovernor, CoresThatBecomeFreeAreTakenWhenMeasuredFreeAgain) {
    ThreadGovernor g;
    FakeIdle meter;
    automaticOnTwoCores(g, meter, 0.0);
    const auto cost = [](int team) { return team == 1 ? 1e-3 : 0.55e-3; };
    drive(g, 5000, cost);  // 5 s busy
    EXPECT_EQ(g.team(), 1);
    meter.idle = 0.9;       // the other job ended
    drive(g, 70000, cost);  // within the longest backoff (30 s) and a trial
    EXPECT_EQ(g.team(), 2) << g.reason();
}

TEST(ThreadGovernor, AnUnknownIdleCountLeavesTheDecisionToTheTrial) {
    ThreadGovernor g;
    FakeIdle meter;
    automaticOnTwoCores(g, meter, -1);  // no /proc/stat
    drive(g, 20000, [](int team) { return team == 1 ? 1e-4 : 0.6e-4; });
    EXPECT_EQ(g.team(), 2) << g.reason();
    EXPECT_EQ(g.busySkips(), 0u);
}

TEST(IdleCores, SumsTheIdleShareOfEachCpu) {
    using T = granulab::IdleCores::Ticks;
    const std::vector<T> before{{100, 1000}, {50, 1000}};
    // CPU 0: 90 of 100 ticks idle; CPU 1: none of 100.
    const std::vector<T> after{{190, 1100}, {50, 1100}};
    EXPECT_DOUBLE_EQ(granulab::IdleCores::idleBetween(before, after), 0.9);
    EXPECT_LT(granulab::IdleCores::idleBetween(before, before), 0) << "no tick passed: unknown";
    EXPECT_LT(granulab::IdleCores::idleBetween(before, {{190, 1100}}), 0) << "another CPU set";
    EXPECT_LT(granulab::IdleCores::idleBetween(after, before), 0) << "counters went back (CPU offline)";
}

TEST(IdleCores, ParsesTheCpuLinesOfProcStat) {
    // The first line sums all CPUs and must not be taken for a CPU (its user ticks once were).
    char text[] =
        "cpu  80800 0 17193 260594 486 0 285 0 0 0\n"
        "cpu0 39062 0 7725 132739 25 0 110 0 0 0\n"
        "cpu1 41737 0 9468 127854 460 0 175 7 0 0\n"
        "intr 540694 0 0 0\n";
    std::FILE* f = fmemopen(text, sizeof text - 1, "r");
    ASSERT_NE(f, nullptr);
    const auto ticks = granulab::IdleCores::parseStat(f, {1});
    std::fclose(f);
    ASSERT_EQ(ticks.size(), 1u);
    EXPECT_EQ(ticks[0].idle, 127854u + 460u);
    EXPECT_EQ(ticks[0].total, 41737u + 9468u + 127854u + 460u + 175u + 7u);
    std::FILE* g = fmemopen(text, sizeof text - 1, "r");
    EXPECT_TRUE(granulab::IdleCores::parseStat(g, {2}).empty()) << "a CPU of the mask not listed";
    std::fclose(g);
}

TEST(IdleCores, ReadsThisMachine) {
    // On Linux the meter knows an answer over a quarter of a second, between 0 and the cores.
    granulab::IdleCores meter;
    meter.start();
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(250);
    while (std::chrono::steady_clock::now() < until) {
    }
    const double idle = meter.idleSinceStart();
#ifdef __linux__
    EXPECT_GE(idle, 0);
#endif
    EXPECT_LE(idle, static_cast<double>(std::thread::hardware_concurrency()) + 1e-9);
}
