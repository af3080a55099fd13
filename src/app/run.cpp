// SPDX-License-Identifier: MIT
// The run loop: stage 9 (observers) of DESIGN.md lives here, around World::step().
#include "app/run.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/progress.hpp"
#include "app/run_edmd.hpp"
#include "app/scene_input.hpp"
#include "core/timer.hpp"
#include "core/version.hpp"
#include "dem/setup.hpp"
#include "io/checkpoint.hpp"
#include "io/csv_writers.hpp"
#include "io/validate.hpp"
#include "io/vtk_writer.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

std::string defaultOutDir(const std::string& scenePath) {
    return (fs::path("out") / fs::path(scenePath).stem()).string();
}

std::size_t peakRssBytes() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmHWM:", 0) == 0) return static_cast<std::size_t>(std::stoull(line.substr(6))) * 1024;
    return 0;
}

namespace {

std::int64_t stepsOf(double interval, double dt) {
    return std::max<std::int64_t>(1, std::llround(interval / dt));
}

/// Observers of one run: series rows, VTK snapshots, checkpoints.
class Outputs {
public:
    Outputs(const std::string& dir, const model::SceneDef& scene, const dem::World& world, double resumeTime)
        : m_dir(dir), m_vtk(scene.output.vtk), m_pvd(dir + "/snapshots.pvd"),
          m_series(dir + "/series.csv", columns(world), resumeTime) {
        if (resumeTime >= 0 && fs::exists(dir + "/snapshots.pvd")) {
            m_pvd.load();
            m_pvd.truncateAfter(resumeTime);
        }
    }

    static std::vector<std::string> columns(const dem::World& world) {
        std::vector<std::string> c = {"time", "step", "kinetic_energy", "rotational_energy", "potential_energy",
                                      "elastic_energy", "total_energy", "contacts", "wall_contacts",
                                      "max_overlap_ratio", "neighbor_builds"};
        for (const auto& w : world.walls().walls) {
            c.push_back("wall_" + w.name + "_fx");
            c.push_back("wall_" + w.name + "_fy");
        }
        return c;
    }

    void seriesRow(const dem::World& world) {
        const auto e = world.energies();
        const auto& st = world.forceStats();
        std::vector<double> row = {world.time(), static_cast<double>(world.stepIndex()), e.kinetic, e.rotational,
                                   e.potential, e.elastic, e.total(), static_cast<double>(st.contacts),
                                   static_cast<double>(st.wallContacts), st.maxRelativeOverlap,
                                   static_cast<double>(world.neighbors().builds)};
        for (const auto& f : world.wallForce()) {
            row.push_back(f.x);
            row.push_back(f.y);
        }
        m_series.row(row);
        m_lastEnergy = e;
    }

    void snapshot(const dem::World& world, io::OutputCounters& counters) {
        if (!m_vtk) return;
        io::writeSnapshot(m_dir, static_cast<int>(counters.nextSnapshot++), world.store(), world.shapes(), world.walls(),
                          world.time(), m_pvd);
        m_series.flush();
    }

    const dem::Energies& lastEnergy() const { return m_lastEnergy; }

private:
    std::string m_dir;
    bool m_vtk;
    io::PvdWriter m_pvd;
    io::SeriesWriter m_series;
    dem::Energies m_lastEnergy;
};

std::string describeStatus(std::uint32_t status, const dem::World& world, const std::string& lastCheckpoint,
                           std::uint64_t guardSkips) {
    std::vector<std::string> why;
    if (status & dem::kStepNonFinite) why.push_back("a particle position or velocity became NaN/infinite");
    if (status & dem::kStepTunnelling)
        why.push_back("a particle moved more than half its radius in one step (tunnelling)");
    if (status & dem::kStepDeepOverlap)
        why.push_back(fmt::format("a contact overlap reached {:.3g} times the smaller radius",
                                  world.forceStats().maxRelativeOverlap));
    std::string s = fmt::format("the run became unstable at t = {:.6g} s (step {}): ", world.time(), world.stepIndex());
    for (std::size_t k = 0; k < why.size(); ++k) s += (k ? "; " : "") + why[k];
    s += ". Likely causes: ";
    if ((status & dem::kStepDeepOverlap) && guardSkips > 0)
        s += "the overlap guard (dem.overlap_guard) skipped contacts deeper than 1 % of the radius, so particles "
             "interpenetrated; switch the guard off or raise the stiffness";
    else if (status & dem::kStepDeepOverlap)
        s += "contact stiffness too low for the impact speeds (overlap ~ v sqrt(meff/kn)); raise kn or lower the speeds";
    else
        s += "time step too large for the contact stiffness (see `granulab info` for the advised dt), "
             "or particles created overlapping";
    s += ". " + lastCheckpoint;
    return s;
}

}  // namespace

int runCommand(const RunOptions& opt) {
    const double startWall = wallSeconds();
    const model::SceneDef scene = app::readScene(opt.scene, opt.overrides);  // SceneError -> exit 2 in main
    if (scene.run.engine == "edmd") return runEdmdCommand(opt, scene);
    io::ValidatedScene valid = io::validate(scene);
    for (const auto& w : valid.warnings) fmt::print(stderr, "warning: {}\n", w);

    const std::string dir = !opt.outDir.empty() ? opt.outDir : (!opt.resumeDir.empty() ? opt.resumeDir : defaultOutDir(opt.scene));
    fs::create_directories(dir);
    dem::World world = dem::makeWorld(scene, valid.initial);
    valid.initial = {};  // the world holds the particles now; free the generated copy
    const io::CheckpointHeader header{scene.dem.dt, world.store().size(), world.walls().segments.size(),
                                      world.integratorName()};
    io::OutputCounters counters;
    const bool resumed = !opt.resumeDir.empty();
    if (resumed) {
        try {
            counters = io::readCheckpoint(opt.resumeDir, header, world);
        } catch (const std::runtime_error& e) {  // a missing or foreign checkpoint is bad input
            throw SceneError(makeDiagnostic(opt.resumeDir, 0, "--resume", e.what()));
        }
    } else {
        world.initialize();
    }
    const double dt = scene.dem.dt;
    const std::int64_t endStep = std::llround(scene.run.endTime / dt);
    const std::int64_t seriesEvery = scene.output.seriesInterval > 0 ? stepsOf(scene.output.seriesInterval, dt)
                                                                      : std::max<std::int64_t>(1, endStep / 100);
    const std::int64_t snapEvery = scene.output.snapshotInterval > 0 ? stepsOf(scene.output.snapshotInterval, dt) : endStep;
    // Default: ten checkpoints over the run, so that a failing run keeps a recent good state.
    const std::int64_t checkpointEvery = scene.output.checkpointInterval > 0 ? stepsOf(scene.output.checkpointInterval, dt)
                                                                              : std::max<std::int64_t>(1, endStep / 10);
    if (resumed && endStep <= world.stepIndex())
        throw SceneError(makeDiagnostic(scene.run.loc.file, scene.run.loc.line, "run.end_time",
                                        fmt::format("the checkpoint in {} is at t = {:.6g} s; to continue, run.end_time must be "
                                                    "later (got {:.6g} s)",
                                                    opt.resumeDir, world.time(), scene.run.endTime)));
    const auto checkpointLine = [](double time, const std::string& where) {
        return fmt::format("The last good checkpoint (t = {:.6g} s) is kept in {}/checkpoint.bin.", time, where);
    };
    std::string lastCheckpoint = resumed ? checkpointLine(world.time(), opt.resumeDir)
                                         : "No checkpoint was written before the failure (see output.checkpoint_interval).";
    const std::int64_t benchStep = scene.run.benchmarkFrom >= 0 ? std::llround(scene.run.benchmarkFrom / dt) : -1;

    Outputs out(dir, scene, world, resumed ? world.time() : -1.0);
    if (!resumed) {
        out.seriesRow(world);
        out.snapshot(world, counters);
    }
    if (!opt.quiet)
        fmt::print(stderr, "granulab {}: {} particles, {} wall segments, dt = {:.4g} s, {} steps to t = {:.6g} s -> {}\n",
                   kVersion, world.store().size(), world.walls().segments.size(), dt, endStep - world.stepIndex(),
                   scene.run.endTime, dir);

    Progress progress(scene.run.endTime, opt.quiet);
    const double loopStart = wallSeconds();
    const std::int64_t loopStartStep = world.stepIndex();
    double benchStartWall = -1;
    std::int64_t benchStartStep = 0;
    std::uint32_t status = dem::kStepOk;
    double outputSeconds = 0;
    std::uint64_t guardSkips = 0;  // contact evaluations skipped by the overlap guard
    while (world.stepIndex() < endStep) {
        if (world.stepIndex() == benchStep) {
            benchStartWall = wallSeconds();
            benchStartStep = world.stepIndex();
        }
        status = world.step();
        if (status != dem::kStepOk) break;
        if (world.forceStats().guardSkips > 0) {
            if (guardSkips == 0 && !opt.quiet)
                fmt::print(stderr, "\nnote: overlap guard skipped {} contact(s) deeper than 1 % of the radius at t = {:.6g} s "
                                   "(counted in summary.json)\n",
                           world.forceStats().guardSkips, world.time());
            guardSkips += world.forceStats().guardSkips;
        }
        const std::int64_t k = world.stepIndex();
        const bool last = k == endStep;
        const bool doSeries = k % seriesEvery == 0 || last;
        const bool doSnap = k % snapEvery == 0 || last;
        const bool doCheckpoint = (checkpointEvery > 0 && k % checkpointEvery == 0) || last;
        if (doSeries || doSnap || doCheckpoint) {
            const double t0 = wallSeconds();
            if (doSeries) out.seriesRow(world);
            if (!std::isfinite(out.lastEnergy().total())) {
                status = dem::kStepNonFinite;
                break;
            }
            if (doSnap) out.snapshot(world, counters);
            if (doCheckpoint) {
                io::writeCheckpoint(dir, header, counters, world);
                lastCheckpoint = checkpointLine(world.time(), dir);
            }
            outputSeconds += wallSeconds() - t0;
        }
        progress.update(world.time(), k);
    }
    const double loopEnd = wallSeconds();
    progress.finish(world.time(), world.stepIndex());

    const bool ok = status == dem::kStepOk;
    std::vector<std::string> warnings = valid.warnings;
    if (guardSkips > 0) {
        warnings.push_back(fmt::format("overlap guard skipped {} particle-pair contact evaluations", guardSkips));
        fmt::print(stderr, "warning: {}\n", warnings.back());  // warnings are shown even with --quiet
    }
    if (ok)
        io::writeFinalCsv(dir + "/final.csv", world.store(), world.shapes(), dem::materialNames(scene),
                          model::massModelOf(scene.dem.massModel));

    const std::int64_t steps = world.stepIndex() - loopStartStep;
    const double loopSeconds = loopEnd - loopStart;
    const double n = static_cast<double>(world.store().size());
    nlohmann::json js;
    js["engine"] = "dem";
    js["version"] = kVersion;
    js["scene"] = opt.scene;
    js["status"] = ok ? "completed" : "unstable";
    if (!ok) js["diagnosis"] = describeStatus(status, world, lastCheckpoint, guardSkips);
    js["resumed_from_step"] = resumed ? loopStartStep : 0;
    js["particles"] = world.store().size();
    js["wall_segments"] = world.walls().segments.size();
    js["dt"] = dt;
    js["sim_time"] = world.time();
    js["steps"] = steps;
    js["wall_time_s"] = wallSeconds() - startWall;
    js["loop_time_s"] = loopSeconds;
    js["particle_steps_per_s"] = loopSeconds > 0 ? n * static_cast<double>(steps) / loopSeconds : 0.0;
    js["integrator"] = world.integratorName();
    js["broad_phase"] = world.broadPhaseName();
    js["neighbor_builds"] = world.neighbors().builds;
    js["force_evaluations_per_step"] =
        world.stepIndex() > 0 ? static_cast<double>(world.forceEvaluations()) / static_cast<double>(world.stepIndex()) : 0.0;
    js["candidate_pairs"] = world.neighbors().pairs.size();
    js["contacts"] = world.forceStats().contacts;
    if (world.shapes().size() > 0) {  // polygon contacts: closest-feature work (gc2d spec section 5.3)
        const auto& fs = world.featureStats();
        const double evals = fs.evaluations ? static_cast<double>(fs.evaluations) : 1.0;
        js["closest_feature"] = {{"evaluations", fs.evaluations},
                                 {"tests_per_evaluation", static_cast<double>(fs.iterations) / evals},
                                 {"cold_start_fraction", static_cast<double>(fs.coldStarts) / evals},
                                 {"full_clip_fraction", static_cast<double>(fs.fullClips) / evals}};
    }
    js["wall_contacts"] = world.forceStats().wallContacts;
    js["overlap_guard_skips"] = guardSkips;
    nlohmann::json timers;
    for (std::size_t s = 0; s < static_cast<std::size_t>(dem::Stage::Count); ++s)
        timers[dem::stageName(static_cast<dem::Stage>(s))] = world.timers().seconds(static_cast<dem::Stage>(s));
    timers["output"] = outputSeconds;
    js["timers_s"] = timers;
    const auto e = world.energies();
    js["energy"] = {{"kinetic", e.kinetic}, {"rotational", e.rotational}, {"potential", e.potential},
                    {"elastic", e.elastic}, {"total", e.total()}};
    const Vec2 p = world.momentum();
    js["momentum"] = {p.x, p.y};
    Real top = -1e300;
    for (std::size_t i = 0; i < world.store().size(); ++i) top = std::max(top, world.store().y[i] + world.store().radius[i]);
    js["max_height"] = top;
    js["memory_bytes"] = world.memoryBytes();
    js["bytes_per_particle"] = n > 0 ? static_cast<double>(world.memoryBytes()) / n : 0.0;
    js["peak_rss_bytes"] = peakRssBytes();
    nlohmann::json walls = nlohmann::json::array();
    for (std::size_t w = 0; w < world.walls().walls.size(); ++w)
        walls.push_back({{"name", world.walls().walls[w].name},
                         {"force", {world.wallForce()[w].x, world.wallForce()[w].y}}});
    js["wall_forces"] = walls;
    if (benchStartWall >= 0) {
        const double bw = loopEnd - benchStartWall;
        const auto bs = world.stepIndex() - benchStartStep;
        js["benchmark"] = {{"from_time", scene.run.benchmarkFrom},
                           {"steps", bs},
                           {"wall_s", bw},
                           {"particle_steps_per_s", bw > 0 ? n * static_cast<double>(bs) / bw : 0.0}};
    }
    js["warnings"] = warnings;
    io::writeFileAtomically(dir + "/summary.json", js.dump(2) + "\n");

    if (!ok) {
        fmt::print(stderr, "error: {}\n", describeStatus(status, world, lastCheckpoint, guardSkips));
        return kExitUnstable;
    }
    if (!opt.quiet) {
        fmt::print(stderr, "done: {} steps in {:.3g} s ({:.3g} particle-steps/s)\n", steps, loopSeconds,
                   js["particle_steps_per_s"].get<double>());
        if (scene.output.vtk) {
            fmt::print("results in {}/ : summary.json, series.csv, final.csv, snapshots.pvd, checkpoint.bin\n", dir);
            const bool polygons = world.shapes().size() > 0;
            const bool disks = std::any_of(world.store().shape.begin(), world.store().shape.end(),
                                           [](std::uint32_t k) { return k == model::kDiskShape; });
            if (disks)
                fmt::print("view in ParaView: paraview {}/snapshots.pvd  (disks: Glyph filter, type Sphere, scale array "
                           "'radius', factor 2, glyph mode 'All Points'{})\n",
                           dir, polygons ? "; polygons show as they are" : "");
            else
                fmt::print("view in ParaView: paraview {}/snapshots.pvd  (polygons show as cells; colour by 'speed')\n", dir);
            fmt::print("pictures:         granulab render {} --png\n", dir);
        } else {
            fmt::print("results in {}/ : summary.json, series.csv, final.csv, checkpoint.bin (VTK output off)\n", dir);
        }
    }
    return kExitOk;
}

}  // namespace granulab::app
