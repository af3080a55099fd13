// SPDX-License-Identifier: MIT
// The seam between the run loop and an engine (docs/architecture.md "The seam"): one Simulation
// per run, called once per output stop, never per particle or per step (so DESIGN.md's "no
// virtual calls in hot loops" holds). An engine joins granulab with one adapter implementing
// this interface and one row in the engine table (app/engine_table.cpp).
//
// Several MPI ranks (an engine whose table row allows them): the run loop runs on every rank in
// step, so every member is called on every rank in the same order, and a member may be
// collective (gather particles, sum statistics). What the loop branches on (time, count, the
// status of advance and health, plan) must be the same on every rank. Only the root rank
// writes files and prints: snapshot, writeFinal and saveState write on the root (saveState's
// stream discards elsewhere); seriesRow's values are used on the root only.
#pragma once
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"
#include "io/vtk_writer.hpp"

namespace granulab::app {

/// Why an advance stopped early (bit flags). kSimInterrupted ends the run cleanly with exit
/// status 128 + signal (core/interrupt.hpp); any other flag ends it with exit status 3.
enum SimStatus : std::uint32_t {
    kSimOk = 0,
    kSimNonFinite = 1u << 0,    ///< a position, velocity or energy became NaN or infinite
    kSimUnstable = 1u << 1,     ///< tunnelling or an unphysical step (engine-specific diagnosis)
    kSimOverlap = 1u << 2,      ///< particles interpenetrate beyond the engine's tolerance
    kSimInterrupted = 1u << 3,  ///< SIGINT/SIGTERM: stopped after a whole step or event
    kSimStalled = 1u << 4,      ///< no progress: a clock standing still, a pre-run that cannot end
    kSimInputFailed = 1u << 5,  ///< an input read during the run (a flow field) could not be used
};

/// Where an advance stops: at simulated time `time` [s] or when the engine's count (steps,
/// collisions) reaches `count`, whichever comes first.
struct Stop {
    double time = std::numeric_limits<double>::infinity();
    std::uint64_t count = std::numeric_limits<std::uint64_t>::max();
};

/// The points at which one output fires, in simulated time [s] or in the engine's count.
/// Exact schedules are stopped at; polled ones fire at the first stop at or after their point.
struct Schedule {
    enum class Unit { Time, Count };
    Unit unit = Unit::Time;
    bool exact = true;
    /// k-th point (k >= 1), nondecreasing; +inf: never. Null: periodic with `every`.
    std::function<double(std::int64_t k)> point;
    /// Periodic schedules: point k is `every` added k times (the sum, as a loop would add it).
    double every = 0;

    static Schedule never() {
        return {Unit::Time, true, [](std::int64_t) { return std::numeric_limits<double>::infinity(); }, 0};
    }
    static Schedule periodic(Unit unit, double every, bool exact = true) {
        return {unit, exact, nullptr, every};
    }
    /// One exact point `at` (the end of the run, the start of the benchmark segment).
    static Schedule once(Unit unit, double at) {
        return {unit, true,
                [at](std::int64_t k) { return k == 1 ? at : std::numeric_limits<double>::infinity(); }, 0};
    }
    /// Exact points given by `point(k)`, k >= 1.
    static Schedule points(Unit unit, std::function<double(std::int64_t k)> point) {
        return {unit, true, std::move(point), 0};
    }
};

/// When the run ends and when each output fires (scene settings in the engine's units).
struct RunPlan {
    Schedule end;                  ///< one point: the end of the run
    Schedule series;               ///< series.csv rows
    Schedule snapshots;            ///< VTK snapshots and per-snapshot files
    Schedule checkpoints;          ///< checkpoint.bin
    Schedule lines;                ///< engine line outputs (dem: gc2d's gpl); default: never
    Schedule setups;               ///< engine state dumps (dem: gc2d's numbered gso/gco); default: never
    Schedule progress;             ///< progress updates (besides every other stop)
    Schedule benchmark;            ///< one point: start of the timed segment (run.benchmark_from)
    double progressEnd = 0;        ///< progress bar: end position (time [s] or count)
    bool progressByCount = false;  ///< progress position is the count, not the time
};

/// Timing of the run loop, handed to the engine's summary keys.
struct RunReport {
    bool resumed = false;
    double loopSeconds = 0;            ///< [s] wall time of the loop, outputs included
    double outputSeconds = 0;          ///< [s] of it spent in outputs and measurements
    double benchmarkSeconds = -1;      ///< [s] from the benchmark point to the end (<0: none)
    std::uint64_t benchmarkCount = 0;  ///< counts (steps) in that segment
};

class Simulation {
public:
    virtual ~Simulation() = default;

    // ---- identity and state --------------------------------------------------------------
    virtual double time() const = 0;                                   ///< [s]
    virtual std::uint64_t count() const = 0;                           ///< steps (dem), collisions (edmd)
    virtual std::uint64_t progressCounter() const { return count(); }  ///< for the rate shown
    virtual std::string progressUnit() const = 0;                      ///< "steps", "events"
    /// Said at the end of each progress line (the DEM: how many threads run and why); may be empty.
    virtual std::string progressNote() const { return {}; }
    virtual std::size_t particles() const = 0;
    virtual std::size_t memoryBytes() const = 0;  ///< engine state [bytes]
    virtual std::vector<std::string> warnings() const = 0;

    // ---- the run ---------------------------------------------------------------------------
    virtual RunPlan plan() const = 0;
    /// A fresh run's preparation before the t = 0 outputs (edmd: elastic pre-run); returns
    /// SimStatus flags: kSimStalled for a pre-run that cannot finish, kSimInterrupted when
    /// interruptRequested() (core/interrupt.hpp) stopped it; the run loop then ends.
    virtual std::uint32_t start() = 0;
    /// Called once before the loop (fresh or resumed), after the t = 0 outputs.
    virtual void beginLoop() = 0;
    /// Runs until `stop`; returns SimStatus flags (kSimOk when the stop was reached). Polls
    /// interruptRequested() once per step or batch of events and returns kSimInterrupted, at a
    /// state that a checkpoint resumes, when it is set.
    virtual std::uint32_t advance(const Stop& stop) = 0;
    /// Status after a series row (e.g. a non-finite energy); kSimOk by default.
    virtual std::uint32_t health() const { return kSimOk; }
    /// The diagnosis of a failed advance, with likely causes.
    virtual std::string diagnose(std::uint32_t status) const = 0;

    // ---- outputs -----------------------------------------------------------------------------
    /// Opens the engine's own per-row files in `dir` once before the first row (a resumed run:
    /// `resumeTime` >= 0, rows after it are dropped, as for series.csv). Default: none.
    virtual void openOutputs(const std::string& dir, double resumeTime) {
        (void)dir;
        (void)resumeTime;
    }
    virtual std::vector<std::string> seriesColumns() const = 0;
    /// The series row at the current state (may update interval averages kept for the next row).
    virtual std::vector<double> seriesRow() = 0;
    /// Writes snapshot `index` into `dir` (VTK files registered in `pvd`, engine extras).
    virtual void snapshot(const std::string& dir, int index, io::PvdWriter& pvd) = 0;
    /// Appends the engine's own one-line-per-stop outputs at a point of RunPlan::lines (dem:
    /// gc2d's gpl line); also at t = 0 of a fresh run when the schedule has points. Default: none.
    virtual void writeLine(const std::string& dir) { (void)dir; }
    /// Writes the engine's numbered state dump at a point of RunPlan::setups (dem: gc2d's
    /// <basename>.NNNN.gso and .gco). Default: none.
    virtual void writeSetup(const std::string& dir) { (void)dir; }
    /// The engine's own files beside every checkpoint.bin (dem: gc2d's unnumbered <basename>.gso
    /// and .gco). Default: none.
    virtual void writeCheckpointFiles(const std::string& dir) { (void)dir; }
    /// Writes final.csv (io/final_csv.hpp contract) and the engine's other end-of-run files.
    virtual void writeFinal(const std::string& dir) = 0;
    /// The engine's own summary.json keys (io/summary.hpp merges them with the common ones).
    virtual nlohmann::json summaryKeys(const RunReport& report) = 0;
    /// First line printed before the loop (what runs, how long, where to).
    virtual std::string banner(const std::string& dir) const = 0;
    /// Prints the lines after a successful run (throughput; files and how to look at them).
    virtual void printDone(const std::string& dir, const RunReport& report) const = 0;

    // ---- checkpoints -------------------------------------------------------------------------
    /// What a checkpoint must share with this scene to resume it.
    virtual io::SceneIdentity identity() const = 0;
    virtual void saveState(std::ostream& out) = 0;
    virtual void loadState(std::istream& in) = 0;
};

}  // namespace granulab::app
