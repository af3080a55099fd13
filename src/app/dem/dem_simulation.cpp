// SPDX-License-Identifier: MIT
// The dem engine behind the Simulation seam (app/simulation.hpp; DESIGN.md "The DEM step"):
// steps of World::step() between output stops, every output period converted to whole steps
// (dem/step_clock.hpp), series.csv energies and contact counts, VTK snapshots of particles and
// walls, final.csv of the particle store, the World's checkpoint state; gc2d's legacy files
// (output.gc2d, app/dem/gc2d_files.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "app/dem/dem_contacts.hpp"
#include "app/dem/dem_engine.hpp"
#include "app/dem/dem_fluid.hpp"
#include "app/dem/gc2d_files.hpp"
#include "app/dem/gc2d_restart.hpp"
#include "app/dem/particle_series.hpp"
#include "app/simulation_options.hpp"
#include "core/binary_io.hpp"
#include "core/communicator.hpp"
#include "core/interrupt.hpp"
#include "core/version.hpp"
#include "dem/parallel/domain_world.hpp"
#include "dem/setup.hpp"
#include "dem/step_clock.hpp"
#include "io/csv_writers.hpp"
#include "io/validate_dem.hpp"
#include "model/material_names.hpp"

namespace granulab::app {

namespace {

/// Walls whose displacement goes to series.csv (translating ones: piston, vibration, velocity).
bool tracksPosition(const model::Wall& w) noexcept {
    using K = model::WallDriver::Kind;
    return w.driver.kind == K::Velocity || w.driver.kind == K::Vibration || w.driver.kind == K::Piston;
}

class DemSimulation final : public Simulation {
public:
    DemSimulation(const model::SceneDef& scene, dem::PreparedScene prepared, const SimulationOptions& options)
        : m_scene(scene),
          m_options(options),
          m_warnings(std::move(prepared.warnings)),
          m_fieldsNote(prepared.fieldsNote),
          m_world(dem::makeWorld(scene, prepared.initial, std::move(prepared.fields))),
          m_dt(scene.dem.dt),
          m_endStep(dem::stepsIn(scene.run.endTime, scene.dem.dt)),
          m_initialParticles(m_world.store().size()) {
        if (worldCommunicator().size() >
            1)  // domain decomposition: this rank's part comes from a whole world
            m_whole.emplace(dem::makeWorld(
                scene, prepared.initial, m_world.field() ? m_world.field()->source() : fluid::FieldSource{}));
    }

    double time() const override { return m_domain ? m_domain->time() : m_world.time(); }
    std::uint64_t count() const override { return static_cast<std::uint64_t>(currentStep()); }
    std::string progressUnit() const override { return "steps"; }
    std::size_t particles() const override {
        return m_domain ? m_domain->particles() : m_world.store().size();
    }
    std::size_t memoryBytes() const override {
        return m_domain ? m_domain->memoryBytes() : m_world.memoryBytes();
    }
    std::vector<std::string> warnings() const override {
        std::vector<std::string> w = m_warnings;
        if (const std::size_t n = m_world.unrestoredContacts(); n > 0)
            w.push_back(
                fmt::format("{} of the gci's {} contacts were not restored (unknown ids, or the bodies "
                            "are not in contact range); ignored, as gc2d ignores unknown pairs",
                            n, m_scene.rememberedContacts.size()));
        if (m_guardSkips > 0)
            w.push_back(
                fmt::format("overlap guard skipped {} particle-pair contact evaluations", m_guardSkips));
        return w;
    }

    RunPlan plan() const override {
        using U = Schedule::Unit;
        const auto& out = m_scene.output;
        const auto every = [&](Real interval, std::int64_t fallback) {
            return static_cast<double>(interval > 0 ? dem::periodSteps(interval, m_dt) : fallback);
        };
        RunPlan p;
        p.end = Schedule::once(U::Count, static_cast<double>(m_endStep));
        p.series = Schedule::periodic(U::Count,
                                      every(out.seriesInterval, std::max<std::int64_t>(1, m_endStep / 100)));
        p.snapshots = Schedule::periodic(U::Count, every(out.snapshotInterval, m_endStep));
        // Default: ten checkpoints over the run, so that a failing run keeps a recent good state.
        p.checkpoints = Schedule::periodic(
            U::Count, every(out.checkpointInterval, std::max<std::int64_t>(1, m_endStep / 10)));
        // gc2d's gpl lines (output.gc2d_line_interval; 0: none).
        const Real lineInterval = out.gc2d.enabled ? out.gc2d.lineInterval : 0;
        p.lines = lineInterval > 0 ? Schedule::periodic(U::Count, every(lineInterval, 1)) : Schedule::never();
        p.progress =
            Schedule::periodic(U::Count, static_cast<double>(std::max<std::int64_t>(64, m_endStep / 200)));
        const std::int64_t benchStep =
            m_scene.run.benchmarkFrom >= 0 ? dem::stepsIn(m_scene.run.benchmarkFrom, m_dt) : -1;
        p.benchmark =
            benchStep >= 0 ? Schedule::once(U::Count, static_cast<double>(benchStep)) : Schedule::never();
        const auto& gc2d = m_scene.output.gc2d;
        p.setups = gc2d.enabled && gc2d.setupInterval > 0
                       ? Schedule::periodic(U::Count, static_cast<double>(setupEvery()))
                       : Schedule::never();
        p.progressEnd = m_scene.run.endTime;
        return p;
    }
    /// Steps between gc2d's numbered setup dumps (output.gc2d_setup_interval, STEPS_SETUP).
    std::int64_t setupEvery() const { return dem::periodSteps(m_scene.output.gc2d.setupInterval, m_dt); }

    std::uint32_t start() override {
        if (m_whole) {  // several ranks: every rank reads the flow fields itself
            try {
                m_whole->initialize();
            } catch (const std::exception& e) {  // the flow field of t = 0 could not be loaded
                m_inputError = e.what();
                return kSimInputFailed;
            }
            decompose();
            return kSimOk;
        }
        m_world.recordContacts(wantsContacts());  // the t = 0 snapshot's contacts
        try {
            m_world.initialize();
        } catch (const std::exception& e) {  // the flow field of t = 0 could not be loaded
            m_inputError = e.what();
            return kSimInputFailed;
        }
        m_world.recordContacts(false);
        return kSimOk;
    }
    /// Steps between snapshots (output.snapshot_interval; 0: the first and the last only), as plan().
    std::int64_t snapshotEvery() const {
        const Real interval = m_scene.output.snapshotInterval;
        return std::max<std::int64_t>(1, interval > 0 ? dem::periodSteps(interval, m_dt) : m_endStep);
    }
    /// The contact records of the snapshot steps: for the contact files and for gc2d's gff.
    bool wantsContacts() const { return writesContactFiles() || m_scene.output.gc2d.enabled; }
    bool writesContactFiles() const { return m_scene.output.vtk && m_scene.output.contacts; }
    /// Whether the state after step `s` is written as a snapshot (the periodic ones and the end).
    bool endsAtSnapshot(std::int64_t s) const { return s % snapshotEvery() == 0 || s == m_endStep; }

    void beginLoop() override { m_loopStartStep = currentStep(); }

    std::uint32_t advance(const Stop& stop) override {
        if (m_domain) return advanceOnRanks(stop);
        while (static_cast<std::uint64_t>(m_world.stepIndex()) < stop.count) {
            if (interruptRequested()) return kSimInterrupted;  // between whole steps
            if (wantsContacts()) m_world.recordContacts(endsAtSnapshot(m_world.stepIndex() + 1));
            const std::uint32_t status = m_world.step();
            if (status & dem::kStepFieldFailed) {
                m_inputError = m_world.fieldError();
                return kSimInputFailed;
            }
            if (status != dem::kStepOk)
                return (status & dem::kStepNonFinite ? kSimNonFinite : 0u) |
                       (status & dem::kStepTunnelling ? kSimUnstable : 0u) |
                       (status & dem::kStepDeepOverlap ? kSimOverlap : 0u);
            if (const auto skips = m_world.forceStats().guardSkips; skips > 0) {
                if (m_guardSkips == 0 && !m_options.quiet)
                    fmt::print(stderr,
                               "\nnote: overlap guard skipped {} contact(s) deeper than 1 % of the radius at "
                               "t = {:.6g} s "
                               "(counted in summary.json)\n",
                               skips, m_world.time());
                m_guardSkips += skips;
            }
        }
        return kSimOk;
    }

    std::uint32_t health() const override {
        return std::isfinite(m_lastEnergy.total()) ? kSimOk : kSimNonFinite;
    }

    std::string diagnose(std::uint32_t status) const override {
        if (status & kSimStalled)
            return fmt::format(
                "the run made no progress at t = {:.6g} s (step {}): the output stops no longer advance the "
                "clock (an internal error; please report it with the scene).",
                time(), currentStep());
        if (status & kSimInputFailed)
            return fmt::format(
                "a flow field could not be loaded at t = {:.6g} s (step {}): {}. {}", time(), currentStep(),
                m_inputError,
                m_scene.fluid.check == "first"
                    ? "With fluid.check = \"first\" the later files are read only when they are due; "
                      "fix the file and resume from the last checkpoint."
                    : "The files were read at the start of the run; was one changed or removed since?");
        std::vector<std::string> why;
        if (status & kSimNonFinite) why.push_back("a particle position or velocity became NaN/infinite");
        if (status & kSimUnstable)
            why.push_back("a particle moved more than half its radius in one step (tunnelling)");
        if (status & kSimOverlap)
            why.push_back(fmt::format("a contact overlap reached {:.3g} times the smaller radius",
                                      stepWorld().forceStats().maxRelativeOverlap));
        std::string s =
            fmt::format("the run became unstable at t = {:.6g} s (step {}): ", time(), currentStep());
        for (std::size_t k = 0; k < why.size(); ++k) s += (k ? "; " : "") + why[k];
        s += ". Likely causes: ";
        if ((status & kSimOverlap) && m_guardSkips > 0)
            s += "the overlap guard (dem.overlap_guard) skipped contacts deeper than 1 % of the radius, so "
                 "particles "
                 "interpenetrated; switch the guard off or raise the stiffness";
        else if (status & kSimOverlap)
            s += "contact stiffness too low for the impact speeds (overlap ~ v sqrt(meff/kn)); raise kn or "
                 "lower the speeds";
        else
            s += "time step too large for the contact stiffness (see `granulab info` for the advised dt), "
                 "or particles created overlapping";
        return s + ".";
    }

    void openOutputs(const std::string& dir, double resumeTime) override {
        if (m_scene.output.particleSeries)
            m_particleSeries = std::make_unique<ParticleSeries>(dir, resumeTime);
        if (m_scene.output.gc2d.enabled) {  // the root's; snapshot() writes the walls and grains
            m_gc2d = std::make_unique<Gc2dFiles>(m_scene, m_world);
            m_gc2d->open(dir, resumeTime);
        }
    }

    std::vector<std::string> seriesColumns() const override {
        std::vector<std::string> c = {
            "time",           "step",         "kinetic_energy", "rotational_energy", "potential_energy",
            "elastic_energy", "total_energy", "contacts",       "wall_contacts",     "max_overlap_ratio",
            "neighbor_builds"};
        for (const auto& w : m_world.walls().walls) {
            c.push_back("wall_" + w.name + "_fx");
            c.push_back("wall_" + w.name + "_fy");
        }
        for (const auto& w : m_world.walls().walls)
            if (tracksPosition(w)) {
                c.push_back("wall_" + w.name + "_dx");
                c.push_back("wall_" + w.name + "_dy");
            }
        if (m_scene.machines.gravity.present) {
            c.push_back("gravity_x");
            c.push_back("gravity_y");
        }
        if (m_scene.machines.sizeScaling.present) c.push_back("size_scale");
        if (m_world.flow().active()) {  // particles in and out (cumulative counts and masses)
            for (const char* k :
                 {"particles", "mass", "inserted", "skipped", "removed", "mass_in", "mass_out"})
                c.push_back(k);
            for (const auto& o : m_world.flow().config().outlets) {
                c.push_back("outlet_" + o.name + "_removed");
                c.push_back("outlet_" + o.name + "_mass");
            }
        }
        for (auto& k : fluidSeriesColumns(m_scene)) c.push_back(std::move(k));
        return c;
    }

    std::vector<double> seriesRow() override {
        if (m_domain) {  // collective: the gathered copy on the root; its energy decides health() everywhere
            view();
            double total = worldCommunicator().root() ? m_world.energies().total() : 0.0;
            worldCommunicator().allSum(std::span<double>(&total, 1));
            m_lastEnergy = {total, 0, 0, 0};
            if (!worldCommunicator().root()) return {};
        }
        const auto e = m_world.energies();
        const auto& st = m_world.forceStats();
        std::vector<double> row = {m_world.time(),
                                   static_cast<double>(m_world.stepIndex()),
                                   e.kinetic,
                                   e.rotational,
                                   e.potential,
                                   e.elastic,
                                   e.total(),
                                   static_cast<double>(st.contacts),
                                   static_cast<double>(st.wallContacts),
                                   st.maxRelativeOverlap,
                                   static_cast<double>(m_world.neighbors().builds)};
        for (const auto& f : m_world.wallForce()) {
            row.push_back(f.x);
            row.push_back(f.y);
        }
        for (const auto& w : m_world.walls().walls)
            if (tracksPosition(w)) {
                row.push_back(w.displacement.x);
                row.push_back(w.displacement.y);
            }
        if (m_scene.machines.gravity.present) {
            const Vec2 g = m_world.gravity();
            row.push_back(g.x);
            row.push_back(g.y);
        }
        if (m_scene.machines.sizeScaling.present) row.push_back(m_world.sizeScale());
        if (m_world.flow().active()) {
            const auto& fc = m_world.flow().counters();
            for (const double v : {static_cast<double>(m_world.store().size()), m_world.totalMass(),
                                   static_cast<double>(fc.inserted), static_cast<double>(fc.skipped),
                                   static_cast<double>(fc.removed), fc.massIn, fc.massOut})
                row.push_back(v);
            for (std::size_t o = 0; o < fc.outletRemoved.size(); ++o) {
                row.push_back(static_cast<double>(fc.outletRemoved[o]));
                row.push_back(fc.outletMass[o]);
            }
        }
        appendFluidSeriesRow(m_scene, m_world, row);
        if (m_particleSeries) m_particleSeries->write(m_world.time(), m_world.store());
        m_lastEnergy = e;
        return row;
    }

    void snapshot(const std::string& dir, int index, io::PvdWriter& pvd) override {
        if (m_domain && (view(), !worldCommunicator().root())) return;
        if (m_particleSeries) m_particleSeries->flush();
        if (m_gc2d && !m_gc2d->dump(dir, index) && m_gc2dWarned++ == 0)
            m_warnings.push_back(fmt::format(
                "gc2d: the gff of snapshot {} (t = {:.6g} s) holds no contact forces (no contact records "
                "of that step)",
                index, m_world.time()));
        if (!m_scene.output.vtk) return;
        const io::FluidAtParticles fluid = fluidSnapshotArrays(m_world);
        io::writeSnapshot(dir, index, m_world.store(), m_world.shapes(), m_world.walls(), m_world.time(), pvd,
                          m_world.field() ? &fluid : nullptr);
        // The records are those of this step's force evaluation (recorded because the step ends at a
        // snapshot); a snapshot at a step that was not recorded has no contact file.
        if (writesContactFiles() && m_world.contactLog().step == m_world.stepIndex())
            writeContactSnapshot(dir, index, m_world, pvd);
        if (!m_scene.output.analyses.empty()) analyzeSnapshot(dir, index);
    }

    void writeLine(const std::string& dir) override {
        (void)dir;
        if (m_domain && (view(), !worldCommunicator().root())) return;
        if (m_gc2d) m_gc2d->line();
    }

    /// gc2d's numbered setup dump <basename>.NNNN.gso/.gco, NNNN = NEXT_SETUP_FILENUMBER + the
    /// number of earlier dumps (from the step, so that a resumed run numbers on).
    void writeSetup(const std::string& dir) override {
        if (m_domain && (view(), !worldCommunicator().root())) return;
        const auto& gc2d = m_scene.output.gc2d;
        const std::int64_t start = dem::stepsIn(m_scene.run.startTime, m_dt);  // dumps after the start
        const std::int64_t number =
            gc2d.nextSetupNumber + m_world.stepIndex() / setupEvery() - start / setupEvery() - 1;
        writeRestartFiles(dir + "/" + io::gc2dFileName(gc2d.basename, number, "gso"),
                          dir + "/" + io::gc2dFileName(gc2d.basename, number, "gco"));
    }
    /// gc2d's checkpoint <basename>.gso/.gco (STEPS_CHECKPOINT), overwritten each time.
    void writeCheckpointFiles(const std::string& dir) override {
        if (!m_scene.output.gc2d.enabled) return;
        if (m_domain && (view(), !worldCommunicator().root())) return;
        const std::string& base = m_scene.output.gc2d.basename;
        writeRestartFiles(dir + "/" + io::gc2dFileName(base, "gso"),
                          dir + "/" + io::gc2dFileName(base, "gco"));
    }
    void writeRestartFiles(const std::string& gso, const std::string& gco) {
        try {
            writeGc2dRestart(gso, gco, m_scene, m_world);
        } catch (const std::invalid_argument& e) {  // what gsi cannot hold (disks): once
            if (m_restartWarned++ == 0)
                m_warnings.push_back(fmt::format("gc2d restart files (gso, gco) not written: {}", e.what()));
        }
    }

    void writeFinal(const std::string& dir) override {
        if (m_domain && (view(), !worldCommunicator().root())) return;
        if (m_gc2d && !m_gc2d->picture(dir))  // after the run's warnings: printed here
            fmt::print(stderr, "warning: gc2d: cannot write {}/{}\n", dir,
                       io::gc2dFileName(m_scene.output.gc2d.basename, "ps"));
        io::writeFinalCsv(dir + "/final.csv", m_world.store(), m_world.shapes(),
                          model::materialNames(m_scene), model::massModelOf(m_scene.dem.massModel),
                          fluidFinalColumns(m_world));
    }

    nlohmann::json summaryKeys(const RunReport& report) override {
        if (m_domain && (view(), !worldCommunicator().root())) return {};
        const double n = static_cast<double>(m_world.store().size());
        const std::int64_t steps = m_world.stepIndex() - m_loopStartStep;
        nlohmann::json js;
        js["resumed_from_step"] = report.resumed ? m_loopStartStep : 0;
        js["wall_segments"] = m_world.walls().segments.size();
        js.update(analysisKeys());  // at the end of the run
        js["dt"] = m_dt;
        js["steps"] = steps;
        js["particle_steps_per_s"] =
            report.loopSeconds > 0 ? n * static_cast<double>(steps) / report.loopSeconds : 0.0;
        js["integrator"] = m_world.integratorName();
        js["broad_phase"] = m_world.broadPhaseName();
        {  // how many threads ran and why (docs/physics/dem-threads.md, "How the default is chosen")
            const dem::World& w = m_domain ? m_domain->local() : m_world;
            const ThreadGovernor& g = w.threadGovernor();
            js["threads"] = w.team();
            js["threads_choice"] = {{"mode", g.automatic() ? "automatic" : "explicit"},
                                    {"limit", g.limit()},
                                    {"reason", g.reason()},
                                    {"trials", g.trials()},
                                    {"changes", g.changes()},
                                    {"busy_skips", g.busySkips()}};
        }
        js["ranks"] = worldCommunicator().size();
        if (m_domain) js["domains"] = domainKeys();
        {  // the work split of the threaded step (docs/physics/dem-threads.md)
            const auto& list = m_world.neighbors();
            js["tiles"] = {
                {"count", list.tiles.count},
                {"slots_per_tile", list.tiles.slotsPerTile},
                {"cross_pair_fraction", list.pairs.size() ? static_cast<double>(list.crossPairs()) /
                                                                static_cast<double>(list.pairs.size())
                                                          : 0.0}};
        }
        js["neighbor_builds"] = m_world.neighbors().builds;
        js["force_evaluations_per_step"] =
            m_world.stepIndex() > 0
                ? static_cast<double>(m_world.forceEvaluations()) / static_cast<double>(m_world.stepIndex())
                : 0.0;
        js["candidate_pairs"] = m_world.neighbors().pairs.size();
        js["contacts"] = m_world.forceStats().contacts;
        if (m_world.shapes().size() > 0) {  // polygon contacts: closest-feature work (gc2d spec section 5.3)
            const auto& fs = m_world.featureStats();
            const double evals = fs.evaluations ? static_cast<double>(fs.evaluations) : 1.0;
            js["closest_feature"] = {{"evaluations", fs.evaluations},
                                     {"tests_per_evaluation", static_cast<double>(fs.iterations) / evals},
                                     {"cold_start_fraction", static_cast<double>(fs.coldStarts) / evals},
                                     {"full_clip_fraction", static_cast<double>(fs.fullClips) / evals}};
        }
        js["wall_contacts"] = m_world.forceStats().wallContacts;
        js["overlap_guard_skips"] = m_guardSkips;
        nlohmann::json timers;
        for (std::size_t s = 0; s < static_cast<std::size_t>(dem::Stage::Count); ++s)
            timers[dem::stageName(static_cast<dem::Stage>(s))] =
                m_world.timers().seconds(static_cast<dem::Stage>(s));
        timers["output"] = report.outputSeconds;
        js["timers_s"] = timers;
        const auto e = m_world.energies();
        js["energy"] = {{"kinetic", e.kinetic},
                        {"rotational", e.rotational},
                        {"potential", e.potential},
                        {"elastic", e.elastic},
                        {"total", e.total()}};
        const Vec2 p = m_world.momentum();
        js["momentum"] = {p.x, p.y};
        Real top = -1e300;
        for (std::size_t i = 0; i < m_world.store().size(); ++i)
            top = std::max(top, m_world.store().y[i] + m_world.store().radius[i]);
        js["max_height"] = top;
        nlohmann::json walls = nlohmann::json::array();
        for (std::size_t w = 0; w < m_world.walls().walls.size(); ++w)
            walls.push_back({{"name", m_world.walls().walls[w].name},
                             {"force", {m_world.wallForce()[w].x, m_world.wallForce()[w].y}}});
        js["wall_forces"] = walls;
        if (m_world.flow().active()) {
            const auto& fc = m_world.flow().counters();
            const auto& cfg = m_world.flow().config();
            nlohmann::json flow;
            flow["inserted"] = fc.inserted;
            flow["skipped"] = fc.skipped;
            flow["removed"] = fc.removed;
            flow["mass_in"] = fc.massIn;
            flow["mass_out"] = fc.massOut;
            flow["mass"] = m_world.totalMass();
            nlohmann::json sources = nlohmann::json::array(), inlets = nlohmann::json::array(),
                           outlets = nlohmann::json::array();
            for (std::size_t k = 0; k < cfg.sources.size(); ++k)
                sources.push_back({{"name", cfg.sources[k].name},
                                   {"drops", fc.sourceDrops[k]},
                                   {"skipped", fc.sourceSkipped[k]}});
            for (std::size_t k = 0; k < cfg.inlets.size(); ++k)
                inlets.push_back({{"name", cfg.inlets[k].name},
                                  {"emitted", fc.inletEmitted[k]},
                                  {"skipped", fc.inletSkipped[k]}});
            for (std::size_t k = 0; k < cfg.outlets.size(); ++k)
                outlets.push_back({{"name", cfg.outlets[k].name},
                                   {"removed", fc.outletRemoved[k]},
                                   {"mass", fc.outletMass[k]}});
            flow["sources"] = sources;
            flow["inlets"] = inlets;
            flow["outlets"] = outlets;
            js["flow"] = flow;
        }
        if (m_scene.fluid.present) js["fluid"] = fluidSummary(m_scene, m_world, m_fieldsNote);
        if (report.benchmarkSeconds >= 0) {
            const double bw = report.benchmarkSeconds;
            js["benchmark"] = {
                {"from_time", m_scene.run.benchmarkFrom},
                {"steps", report.benchmarkCount},
                {"wall_s", bw},
                {"particle_steps_per_s", bw > 0 ? n * static_cast<double>(report.benchmarkCount) / bw : 0.0}};
        }
        return js;
    }

    /// "2 threads: asked for ...", "1 thread: 512 ... is below the threaded size", or the measured
    /// choice of the automatic count (ThreadGovernor::reason).
    std::string threadsNote() const {
        if (m_domain) {  // the root's share; the others alike
            const dem::World& local = m_domain->local();
            const int ranks = worldCommunicator().size();
            return fmt::format(
                "{} ranks (slabs across {}{}) x {}", ranks, m_domain->partition().axis == 0 ? "x" : "y",
                m_scene.run.loadBalance ? ", balanced by contacts" : "", local.threadGovernor().reason());
        }
        return m_world.threadGovernor().reason();
    }

    std::string progressNote() const override { return threadsNote(); }

    std::string banner(const std::string& dir) const override {
        return fmt::format(
                   "granulab {}: {} particles, {} wall segments, dt = {:.4g} s, {} steps to t = {:.6g} s, "
                   "{} -> {}",
                   kVersion, m_world.store().size(), m_world.walls().segments.size(), m_dt,
                   m_endStep - m_world.stepIndex(), m_scene.run.endTime, threadsNote(), dir) +
               (m_fieldsNote.empty() ? "" : "\nfluid: " + m_fieldsNote);
    }

    void printDone(const std::string& dir, const RunReport& report) const override {
        const std::int64_t steps = m_world.stepIndex() - m_loopStartStep;
        const double n = static_cast<double>(m_world.store().size());
        fmt::print(stderr, "done: {} steps in {:.3g} s ({:.3g} particle-steps/s; {})\n", steps,
                   report.loopSeconds,
                   report.loopSeconds > 0 ? n * static_cast<double>(steps) / report.loopSeconds : 0.0,
                   threadsNote());
        if (!m_scene.output.vtk) {
            fmt::print(
                "results in {}/ : summary.json, series.csv, final.csv, checkpoint.bin (VTK output off)\n",
                dir);
            return;
        }
        fmt::print("results in {}/ : summary.json, series.csv, final.csv, snapshots.pvd, checkpoint.bin\n",
                   dir);
        const bool polygons = m_world.shapes().size() > 0;
        const auto& shape = m_world.store().shape;
        const bool disks =
            std::any_of(shape.begin(), shape.end(), [](std::uint32_t k) { return k == model::kDiskShape; });
        if (disks)
            fmt::print(
                "view in ParaView: paraview {}/snapshots.pvd  (disks: Glyph filter, type Sphere, scale array "
                "'radius', factor 2, glyph mode 'All Points'{})\n",
                dir, polygons ? "; polygons show as they are" : "");
        else
            fmt::print(
                "view in ParaView: paraview {}/snapshots.pvd  (polygons show as cells; colour by 'speed')\n",
                dir);
        fmt::print("pictures:         granulab render {} --png\n", dir);
    }

    io::SceneIdentity identity() const override {
        // The integrator's state is part of the checkpoint; dt, particles and walls pin the scene.
        io::SceneIdentity id = {{"dem.integrator", m_world.integratorName()},
                                {"dt", fmt::format("{:.17g}", m_dt)},
                                {"particles", std::to_string(m_initialParticles)},
                                {"wall segments", std::to_string(m_world.walls().segments.size())}};
        // The seed's even rule spreads the fields over run.end_time: another end would move them.
        if (const fluid::FieldSeries* f = m_world.field(); f && f->source().afterTime)
            id.push_back({"fluid field times (fluid.timing = \"even\", spread over run.end_time)",
                          fmt::format("{:.17g} s", m_scene.run.endTime)});
        return id;
    }
    /// The slab cuts of a run on several ranks (none on one), then the World's state in the
    /// one-rank format (the gathered copy), so that any rank count resumes it. On several ranks
    /// the particles are first redistributed over the same cuts: a run resumed on as many ranks
    /// then continues bit for bit.
    void saveState(std::ostream& out) override {
        if (m_domain) {
            m_domain->redistribute();
            m_viewFresh = false;
            view();
            if (!worldCommunicator().root()) return;
        }
        writePod(out, kDomainMagic);
        const dem::SlabPartition none;
        const dem::SlabPartition& part = m_domain ? m_domain->partition() : none;
        writePod<std::int32_t>(out, part.axis);
        writeVector(out, part.cuts);
        m_world.saveState(out);
    }
    void loadState(std::istream& in) override {
        dem::SlabPartition part;
        const auto at = in.tellg();
        if (readPod<std::uint64_t>(in) == kDomainMagic) {
            part.axis = readPod<std::int32_t>(in);
            readVector(in, part.cuts);
            if (part.axis < 0 || part.axis > 1 || !std::is_sorted(part.cuts.begin(), part.cuts.end()))
                throw std::runtime_error("checkpoint corrupt (domain cuts)");
        } else {
            in.seekg(at);  // written before the domain decomposition: the World's state only
        }
        if (!m_whole) return m_world.loadState(in);
        m_whole->loadState(in);
        decompose(&part);
    }

private:
    static constexpr std::uint64_t kDomainMagic = 0x31534e49414d4f44ULL;  // "DOMAINS1"

    std::int64_t currentStep() const noexcept {
        return m_domain ? m_domain->stepIndex() : m_world.stepIndex();
    }
    /// The World that steps: the engine on one rank, this rank's part on several.
    const dem::World& stepWorld() const noexcept { return m_domain ? m_domain->local() : m_world; }

    /// Hands the whole world (initialised or loaded) to the domain decomposition; the adapter's
    /// own world becomes the gathered copy for outputs (empty until the first gather).
    void decompose(const dem::SlabPartition* cuts = nullptr) {
        dem::DomainConfig config;
        config.balance = m_scene.run.loadBalance;
        m_domain = std::make_unique<dem::DomainWorld>(worldCommunicator(), std::move(*m_whole), config, cuts);
        m_whole.reset();
        m_world.replaceParticles({}, {}, {}, {}, 0, false);
        m_world.recordContacts(wantsContacts());
        m_viewFresh = false;
    }

    /// The gathered copy of a decomposed run, refreshed once per stop (collective).
    void view() {
        if (!m_domain || m_viewFresh) return;
        m_domain->gather(m_world);
        m_viewFresh = true;
    }

    std::uint32_t advanceOnRanks(const Stop& stop) {
        double skips = 0;  // overlap-guard skips of every rank (a pair on two ranks counts twice)
        const auto countSkips = [&] {
            worldCommunicator().allSum(std::span<double>(&skips, 1));
            m_guardSkips += static_cast<std::uint64_t>(skips);
        };
        while (static_cast<std::uint64_t>(m_domain->stepIndex()) < stop.count) {
            const std::uint32_t status = m_domain->step(interruptRequested());
            m_viewFresh = false;
            skips += static_cast<double>(m_domain->local().forceStats().guardSkips);
            if (status & dem::kStepFieldFailed) {  // every rank reads the same files
                m_inputError = m_domain->local().fieldError().empty() ? "on another rank"
                                                                      : m_domain->local().fieldError();
                countSkips();
                return kSimInputFailed;
            }
            if (status != dem::kStepOk) {
                countSkips();
                return (status & dem::kStepNonFinite ? kSimNonFinite : 0u) |
                       (status & dem::kStepTunnelling ? kSimUnstable : 0u) |
                       (status & dem::kStepDeepOverlap ? kSimOverlap : 0u);
            }
            if (m_domain->stopRequested()) {  // every rank after the same step
                countSkips();
                return kSimInterrupted;
            }
        }
        countSkips();
        return m_domain->settle() & dem::kStepDeepOverlap ? kSimOverlap : kSimOk;
    }

    nlohmann::json domainKeys() const {
        const dem::DomainStats& st = m_domain->stats();
        const dem::SlabPartition& part = m_domain->partition();
        return {{"axis", part.axis == 0 ? "x" : "y"},
                {"cuts_m", part.cuts},
                {"load_balance", m_scene.run.loadBalance},
                {"exchanges", st.exchanges},
                {"rebalances", st.rebalances},
                {"imbalance", st.imbalance},
                {"mean_imbalance", st.exchanges ? st.imbalanceSum / static_cast<double>(st.exchanges) : 1.0},
                {"halo_share", st.haloShare},
                {"root_halo_s", st.haloSeconds},
                {"root_exchange_s", st.exchangeSeconds},
                {"root_reduce_s", st.reduceSeconds}};
    }

    /// What `granulab analyze` reads from summary.json besides the snapshot files: the wall names
    /// in wall-index order (`--wall`, the floor) and |g| [m/s^2] now.
    nlohmann::json analysisKeys() const {
        nlohmann::json js;
        js["walls"] = nlohmann::json::array();
        for (const auto& w : m_world.walls().walls) js["walls"].push_back(w.name);
        js["gravity_magnitude"] = norm(m_world.gravity());
        return js;
    }

    /// output.analyses at a snapshot: the tables of `granulab analyze` from the files just written.
    /// An analysis that cannot run yet (a pour's first snapshot has no grains) becomes one warning
    /// per analysis and message kind, not a failed run.
    void analyzeSnapshot(const std::string& dir, int index) {
        for (const std::string& problem :
             demAnalyzeSnapshot(dir, index, m_scene.output.analyses, analysisKeys())) {
            const std::string line = "output.analyses: " + problem;
            if (m_analysisProblems.insert(line).second)
                m_warnings.push_back(fmt::format("{} (first at snapshot {})", line, index));
        }
    }

    const model::SceneDef& m_scene;
    SimulationOptions m_options;
    std::vector<std::string> m_warnings;
    std::string m_fieldsNote;  ///< [fluid]: what the fields are (banner, summary)
    std::string m_inputError;  ///< why a flow field could not be loaded (kSimInputFailed)
    std::unique_ptr<ParticleSeries> m_particleSeries;  ///< output.particle_series (cfddem 6.6)
    std::unique_ptr<Gc2dFiles> m_gc2d;                 ///< output.gc2d: gc2d's legacy files (root)
    int m_restartWarned = 0;                           ///< gso/gco that gsi cannot hold
    int m_gc2dWarned = 0;                              ///< gff snapshots without contact records
    dem::World m_world;  ///< the engine on one rank; on several, the gathered copy for outputs (root)
    std::optional<dem::World> m_whole;           ///< several ranks: the whole scene until it is split
    std::unique_ptr<dem::DomainWorld> m_domain;  ///< several ranks: this rank's part
    bool m_viewFresh = false;                    ///< m_world holds the state of the current step
    Real m_dt;
    std::int64_t m_endStep;
    std::size_t
        m_initialParticles;  ///< the scene's particles at t = 0 (sources and outlets change the count)
    std::int64_t m_loopStartStep = 0;
    std::uint64_t m_guardSkips = 0;  ///< contact evaluations skipped by the overlap guard
    dem::Energies m_lastEnergy;
    std::set<std::string> m_analysisProblems;  ///< in-run analysis problems already warned about
};

}  // namespace

dem::PreparedScene checkAndPrepareDem(const model::SceneDef& scene) {
    Diagnostics diags;
    std::vector<std::string> warnings;
    io::checkDemDef(scene, diags, warnings);
    // The field files are opened (and each read once) only for a scene whose [fluid] keys are right.
    io::OpenedFields fields;
    if (scene.fluid.present && diags.empty()) fields = io::openFlowFields(scene, diags);
    dem::PreparedScene prepared = dem::prepareScene(scene, diags);
    prepareDemFluid(scene, std::move(fields), prepared, diags);
    diags.throwIfAny();
    warnings.insert(warnings.end(), prepared.warnings.begin(), prepared.warnings.end());
    prepared.warnings = std::move(warnings);
    return prepared;
}

std::unique_ptr<Simulation> makeDemSimulation(const model::SceneDef& scene,
                                              const SimulationOptions& options) {
    return std::make_unique<DemSimulation>(scene, checkAndPrepareDem(scene), options);
}

}  // namespace granulab::app
