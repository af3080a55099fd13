// SPDX-License-Identifier: MIT
// The run loop (app/run_loop.hpp). A stop is the earliest point of every exact schedule; at a
// stop each due output fires once, in the order series row, snapshot, engine line
// (RunPlan::lines), checkpoint (series.csv is flushed before a checkpoint, so a resumed run finds
// every row up to it). The end of the run fires the series row, the snapshot and the checkpoint;
// the engine lines keep to their own schedule. Polled schedules fire at the first stop at or after
// their point.
// SIGINT/SIGTERM (core/interrupt.hpp): the engine stops after a whole step or event, the loop
// writes a series row and a checkpoint at that state, summary.json says "interrupted" with the
// command that resumes, and the exit status is 128 + signal.
// Under mpirun (an engine that runs on several ranks) the loop runs on every rank in step; the
// root rank alone writes the files and prints (app/simulation.hpp says what is collective).
#include "app/run_loop.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <utility>

#include "app/exit_codes.hpp"
#include "app/progress.hpp"
#include "app/trigger.hpp"
#include "core/communicator.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/timer.hpp"
#include "io/csv_writers.hpp"
#include "io/summary.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

namespace {

std::string checkpointLine(double time, const std::string& where) {
    return fmt::format("The last good checkpoint (t = {:.6g} s) is kept in {}/checkpoint.bin.", time, where);
}

io::CheckpointHeader headerOf(const std::string& engine, const Simulation& sim, std::int64_t nextSnapshot) {
    return {engine, sim.identity(), {nextSnapshot}};
}

/// Writes checkpoint.bin (root); saveState is collective, so the other ranks call it too, into
/// a stream that discards.
void writeCheckpoint(Simulation& sim, const RunContext& ctx, std::int64_t nextSnapshot) {
    if (worldCommunicator().root()) {
        io::writeCheckpoint(ctx.dir, headerOf(ctx.engine, sim, nextSnapshot),
                            [&](std::ostream& out) { sim.saveState(out); });
    } else {
        std::ostream discard(nullptr);
        sim.saveState(discard);
    }
    sim.writeCheckpointFiles(ctx.dir);
}

/// Loads `ctx.resumeDir`/checkpoint.bin into `sim`; a missing or foreign checkpoint is bad
/// input (SceneError, exit status 2).
io::RunBookkeeping resume(Simulation& sim, const RunContext& ctx, std::string& lastCheckpoint) {
    io::RunBookkeeping book;
    try {
        book = io::readCheckpoint(ctx.resumeDir, headerOf(ctx.engine, sim, 0),
                                  [&](std::istream& in) { sim.loadState(in); });
    } catch (const std::runtime_error& e) {
        throw SceneError(makeDiagnostic(ctx.resumeDir, 0, "--resume", e.what()));
    }
    lastCheckpoint = checkpointLine(sim.time(), ctx.resumeDir);
    return book;
}

/// How the loop ended, for finishRun.
struct LoopOutcome {
    std::uint32_t status = kSimOk;  ///< SimStatus flags of the failed advance or row
    RunReport report;
    std::string lastCheckpoint;      ///< sentence naming the last good checkpoint
    std::size_t warningsBefore = 0;  ///< warnings already printed before the loop
    bool resumable = true;           ///< interrupted: a checkpoint of this state was written
};

/// The lines of an interrupted run: where it stopped, what was written, how to go on.
std::string interruptMessage(const Simulation& sim, const RunContext& ctx, bool resumable) {
    const char* signal = signalName(interruptSignal());
    if (!resumable)
        return fmt::format(
            "interrupted by {} during the preparation of the run (before t = 0); no checkpoint was "
            "written: run the scene again",
            signal);
    return fmt::format(
        "interrupted by {} at t = {:.6g} s: checkpoint.bin, a series row and summary.json written to "
        "{}/\nresume with: {}",
        signal, sim.time(), ctx.dir, ctx.resumeCommand);
}

/// The end of a run: warnings raised during it, final.csv (completed runs), summary.json, the
/// diagnosis of a failure, the resume command of an interrupted run or the done message.
/// Returns the exit status.
int finishRun(Simulation& sim, const RunContext& ctx, const LoopOutcome& outcome) {
    const auto& [status, report, lastCheckpoint, warningsBefore, resumable] = outcome;
    const bool ok = status == kSimOk;
    const bool interrupted = status == kSimInterrupted;
    const bool root = worldCommunicator().root();
    const auto warnings = sim.warnings();
    if (root)
        for (std::size_t k = warningsBefore; k < warnings.size(); ++k)
            fmt::print(stderr, "warning: {}\n", warnings[k]);  // shown even with --quiet
    if (ok) sim.writeFinal(ctx.dir);
    const nlohmann::json engineKeys = sim.summaryKeys(report);  // collective
    io::SummaryCommon common;
    common.engine = ctx.engine;
    common.scene = ctx.scenePath;
    common.status =
        ok ? io::RunStatus::Completed : (interrupted ? io::RunStatus::Interrupted : io::RunStatus::Unstable);
    if (!ok && !interrupted) common.diagnosis = sim.diagnose(status) + " " + lastCheckpoint;
    if (interrupted && resumable) common.resumeCommand = ctx.resumeCommand;
    common.particles = sim.particles();
    common.simTime = sim.time();
    common.wallTime = wallSeconds() - ctx.startWall;
    common.loopTime = report.loopSeconds;
    common.memoryBytes = sim.memoryBytes();
    common.warnings = warnings;
    if (!root) return interrupted ? exitStatusOfSignal(interruptSignal()) : (ok ? kExitOk : kExitUnstable);
    io::writeSummary(ctx.dir + "/summary.json", common, engineKeys);
    if (interrupted) {
        fmt::print(stderr, "\n{}\n", interruptMessage(sim, ctx, resumable));  // shown even with --quiet
        return exitStatusOfSignal(interruptSignal());
    }
    if (!ok) {
        fmt::print(stderr, "error: {}\n", common.diagnosis);
        return kExitUnstable;
    }
    if (!ctx.quiet) sim.printDone(ctx.dir, report);
    return kExitOk;
}

}  // namespace

int runSimulation(Simulation& sim, const model::SceneDef& scene, const RunContext& ctx) {
    const bool root = worldCommunicator().root();
    const RunPlan plan = sim.plan();
    Trigger end(plan.end), series(plan.series), snapshots(plan.snapshots), checkpoints(plan.checkpoints),
        lines(plan.lines), setups(plan.setups), progressTick(plan.progress), benchmark(plan.benchmark);
    const bool resumed = !ctx.resumeDir.empty();
    io::RunBookkeeping book;
    std::string lastCheckpoint =
        "No checkpoint was written before the failure (see output.checkpoint_interval).";
    installInterruptHandlers();  // from here on a signal stops the run cleanly (pre-run included)
    // The scene's warnings were printed with it; what start() and the t = 0 outputs raise (an
    // engine's set-up, e.g. a gc2d restart's unknown contacts) is printed at the end with the rest.
    const std::size_t warningsBefore = sim.warnings().size();
    if (resumed) {
        book = resume(sim, ctx, lastCheckpoint);
    } else if (std::uint32_t started = sim.start(); started != kSimOk || interruptRequested()) {
        // A pre-run that stalled or was interrupted: nothing to resume from.
        if (interruptRequested()) started = kSimInterrupted;
        LoopOutcome outcome{started, {}, lastCheckpoint, warningsBefore, false};
        return finishRun(sim, ctx, outcome);
    }
    for (Trigger* t : {&end, &series, &snapshots, &checkpoints, &lines, &setups, &progressTick, &benchmark})
        t->seek(sim.time(), sim.count());
    if (resumed && !(end.next() < std::numeric_limits<double>::infinity()))
        throw SceneError(makeDiagnostic(
            scene.run.loc.file, scene.run.loc.line, "run.end_time",
            fmt::format("the checkpoint in {} is at t = {:.6g} s, where this scene's run ends already; "
                        "to continue, set a later end (run.end_time, got {:.6g} s)",
                        ctx.resumeDir, sim.time(), scene.run.endTime)));

    // The files are the root's; the other ranks compute along (collective members) and drop rows.
    std::optional<io::SeriesWriter> seriesFile;
    if (root) {
        seriesFile.emplace(ctx.dir + "/series.csv", sim.seriesColumns(), resumed ? sim.time() : -1.0);
        sim.openOutputs(ctx.dir, resumed ? sim.time() : -1.0);
    }
    const auto seriesRow = [&] {
        std::vector<double> row = sim.seriesRow();
        if (seriesFile) seriesFile->row(row);
    };
    const auto flushSeries = [&] {
        if (seriesFile) seriesFile->flush();
    };
    io::PvdWriter pvd(ctx.dir + "/snapshots.pvd");
    if (root && resumed && fs::exists(ctx.dir + "/snapshots.pvd")) {
        pvd.load();
        pvd.truncateAfter(sim.time());
    }
    const auto writeSnapshot = [&] {
        sim.snapshot(ctx.dir, static_cast<int>(book.nextSnapshot++), pvd);
        flushSeries();
    };
    // The state of the last series row, so that an interrupt does not repeat it (a resumed run's
    // rows end at or before the checkpoint).
    std::pair<double, std::uint64_t> rowState{sim.time(), sim.count()};
    if (!resumed) {
        seriesRow();
        writeSnapshot();
        if (lines.next() < std::numeric_limits<double>::infinity()) sim.writeLine(ctx.dir);
    }
    if (!ctx.quiet && root) fmt::print(stderr, "{}\n", sim.banner(ctx.dir));

    const auto position = [&] {
        return plan.progressByCount ? static_cast<double>(sim.count()) : sim.time();
    };
    Progress progress(plan.progressEnd, ctx.quiet || !root, sim.progressUnit(), plan.progressByCount);
    progress.setNote([&sim] { return sim.progressNote(); });
    RunReport report;
    report.resumed = resumed;
    sim.beginLoop();
    const double loopStart = wallSeconds();
    double benchmarkStart = -1;
    std::uint64_t benchmarkCount = 0;
    if (plan.benchmark.point && plan.benchmark.point(1) == static_cast<double>(sim.count())) {
        benchmarkStart = loopStart;  // the timed segment starts where the loop does
        benchmarkCount = sim.count();
    }
    std::uint32_t status = kSimOk;
    constexpr int kMaxIdleStops = 1000;
    int idleStops = 0;
    double lastTime = sim.time();
    std::uint64_t lastCount = sim.count();
    for (;;) {
        Stop stop;
        for (const Trigger* t :
             {&end, &series, &snapshots, &checkpoints, &lines, &setups, &progressTick, &benchmark})
            t->limit(stop);
        status = sim.advance(stop);
        if (status != kSimOk) break;
        const double t = sim.time();
        const std::uint64_t c = sim.count();
        // The loop's own watchdog: stops that move neither the clock nor the count, over and over,
        // can never reach the end (the engines watch their own inner loops).
        idleStops = (t == lastTime && c == lastCount) ? idleStops + 1 : 0;
        if (idleStops > kMaxIdleStops) {
            status = kSimStalled;
            break;
        }
        lastTime = t;
        lastCount = c;
        if (benchmark.reached(t, c) && benchmarkStart < 0) {
            benchmarkStart = wallSeconds();
            benchmarkCount = c;
        }
        const bool finished = end.reached(t, c);
        const bool doSeries = finished || series.reached(t, c);
        const bool doSnapshot = finished || snapshots.reached(t, c);
        const bool doCheckpoint = finished || checkpoints.reached(t, c);
        const bool doLine = lines.reached(t, c);    // on its own schedule only, not forced at the end
        const bool doSetup = setups.reached(t, c);  // the same
        if (doSeries || doSnapshot || doCheckpoint || doLine || doSetup) {
            const double t0 = wallSeconds();
            if (doSeries) {
                seriesRow();
                rowState = {t, c};
                status = sim.health();
                if (status != kSimOk) break;
            }
            if (doSnapshot) writeSnapshot();
            if (doLine) sim.writeLine(ctx.dir);
            if (doSetup) sim.writeSetup(ctx.dir);
            if (doCheckpoint) {
                flushSeries();
                writeCheckpoint(sim, ctx, book.nextSnapshot);
                lastCheckpoint = checkpointLine(t, ctx.dir);
            }
            report.outputSeconds += wallSeconds() - t0;
        }
        for (Trigger* tr : {&series, &snapshots, &checkpoints, &lines, &setups, &progressTick, &benchmark})
            tr->pass(t, c);
        progress.update(position(), static_cast<std::int64_t>(sim.progressCounter()));
        if (finished) break;
    }
    if (status == kSimInterrupted) {  // a consistent state after a whole step or event
        if (rowState != std::pair{sim.time(), sim.count()}) seriesRow();
        flushSeries();
        writeCheckpoint(sim, ctx, book.nextSnapshot);
    }
    const double loopEnd = wallSeconds();
    progress.finish(position(), static_cast<std::int64_t>(sim.progressCounter()));
    report.loopSeconds = loopEnd - loopStart;
    if (benchmarkStart >= 0) {
        report.benchmarkSeconds = loopEnd - benchmarkStart;
        report.benchmarkCount = sim.count() - benchmarkCount;
    }

    return finishRun(sim, ctx, {status, report, lastCheckpoint, warningsBefore, true});
}

}  // namespace granulab::app
