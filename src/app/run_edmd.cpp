// SPDX-License-Identifier: MIT
// `granulab run` for run.engine = "edmd" (edmd spec sections 2, 4.2, 5.2; checklist items
// 16-30): initial state, elastic pre-run, the event loop stopped at output times (the engine
// extrapolates, the schedule is untouched), series.csv with the gas measurements, VTK
// snapshots, analysis files, kinetic-theory reference curves, checkpoints and --resume.
#include "app/run_edmd.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "analysis/gas_clusters.hpp"
#include "analysis/gas_structure.hpp"
#include "analysis/gas_velocity.hpp"
#include "analysis/kinetic_theory.hpp"
#include "app/progress.hpp"
#include "core/binary_io.hpp"
#include "core/timer.hpp"
#include "core/version.hpp"
#include "io/csv_writers.hpp"
#include "io/gas_analysis_files.hpp"
#include "io/vtk_writer.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kCheckpointMagic = 0x31444d4445424c47ULL;  // "GLBEDMD1"

/// Output bookkeeping that a resume restores (with the engine state).
struct Bookkeeping {
    std::int64_t nextRow = 1;       ///< index of the next series row (row 0 is t = 0)
    std::int64_t nextSnapshot = 0;  ///< index of the next snapshot file
    Real nextSnapshotTime = 0;      ///< [s]
    Real nextCheckpointTime = 0;    ///< [s]
    // Values at the previous row, for interval averages (collision frequency, pressure).
    Real lastTime = 0;
    std::uint64_t lastCollisions = 0;
    Real lastVirial = 0;
    Real lastKinetic = 0;
    Real lastVolumeFraction = -1;   ///< at the previous row (growing spheres), -1 before the first row
    Real equilibrationWall = 0;     ///< [s] wall time of the elastic pre-run
};

template <int D, class Queue>
class EdmdRun {
public:
    using Engine = edmd::Engine<D, Queue>;

    EdmdRun(const RunOptions& opt, const model::SceneDef& scene, const io::EdmdSetup& setup, std::string dir)
        : m_opt(opt), m_scene(scene), m_setup(setup), m_dir(std::move(dir)) {}

    int run();

private:
    std::vector<std::string> columns() const;
    /// The snapshot and the measurements that series rows and snapshots share, made once per stop.
    struct Measurement {
        analysis::PointSet points;
        analysis::DensityDistribution density;
        std::optional<analysis::ClusterStats> clusters;
    };
    Measurement measure(const Engine& e, bool clusters) const;
    analysis::PointSet snapshotPoints(const Engine& e) const;
    void seriesRow(const Engine& e, io::SeriesWriter& series, const Measurement& m);
    void snapshot(const Engine& e, io::PvdWriter& pvd, Measurement& m);
    void writeCheckpoint(const Engine& e) const;
    void readCheckpoint(Engine& e);
    Real rowTime(std::int64_t row) const;

    const RunOptions& m_opt;
    const model::SceneDef& m_scene;
    const io::EdmdSetup& m_setup;
    std::string m_dir;
    Bookkeeping m_book;
    Real m_totalVolume = 1;
    Real m_meanMass = 1;
    Real m_outputSeconds = 0;
    nlohmann::json m_lastRow;
};

template <int D, class Queue>
Real EdmdRun<D, Queue>::rowTime(std::int64_t row) const {
    const Real end = m_setup.endTime;
    const auto points = m_scene.edmd.seriesPoints;
    if (!std::isfinite(end)) return std::numeric_limits<Real>::infinity();  // collision-count rows
    if (m_scene.output.seriesInterval > 0) return std::min(end, m_scene.output.seriesInterval * static_cast<Real>(row));
    if (m_scene.edmd.series == "log") {
        const Real first = m_scene.edmd.seriesFirst > 0 ? m_scene.edmd.seriesFirst : m_setup.tE / 100;
        if (first >= end) return end;
        return first * std::pow(end / first, static_cast<Real>(row - 1) / static_cast<Real>(points - 1));
    }
    return end * static_cast<Real>(row) / static_cast<Real>(points);
}

template <int D, class Queue>
std::vector<std::string> EdmdRun<D, Queue>::columns() const {
    std::vector<std::string> c = {"time", "tau", "events", "collisions", "collisions_per_particle", "wall_collisions",
                                  "kinetic_energy", "rotational_energy", "potential_energy", "total_energy",
                                  "dissipated_energy", "volume_fraction", "energy_per_particle", "temperature",
                                  "temperature_haff",
                                  "collision_frequency", "mean_free_path", "pressure", "reduced_pressure",
                                  "tc_elastic_fraction", "kurtosis"};
    for (int d = 0; d < D; ++d) c.push_back(std::string("kurtosis_") + "xyz"[d]);
    for (const char* q : {"nu_q01", "nu_q10", "nu_q25", "nu_q50", "nu_q75", "nu_q90", "nu_q99"}) c.push_back(q);
    if (m_scene.edmd.clusters)
        for (const char* k : {"clusters", "M1", "M2", "M1_reduced", "M2_reduced", "largest_cluster", "q_x"}) c.push_back(k);
    return c;
}

template <int D, class Queue>
analysis::PointSet EdmdRun<D, Queue>::snapshotPoints(const Engine& e) const {
    analysis::PointSet p;
    p.dim = D;
    p.box = m_setup.config.box;
    p.periodic = m_setup.config.periodic;
    const std::uint32_t n = e.size();
    p.x.resize(static_cast<std::size_t>(D) * n);
    p.v.resize(static_cast<std::size_t>(D) * n);
    p.radius.resize(n);
    p.mass.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const auto x = e.positionNow(i);
        const auto v = e.velocityNow(i);
        for (int d = 0; d < D; ++d) {
            // Inside [0, box) for the analyses (a wall contact sits exactly at the edge).
            p.x[static_cast<std::size_t>(D) * i + d] = std::clamp(x[d], Real(0), std::nextafter(p.box[d], Real(0)));
            p.v[static_cast<std::size_t>(D) * i + d] = v[d];
        }
        p.radius[i] = e.radius(i);
        p.mass[i] = e.mass(i);
    }
    return p;
}

template <int D, class Queue>
typename EdmdRun<D, Queue>::Measurement EdmdRun<D, Queue>::measure(const Engine& e, bool clusters) const {
    Measurement m;
    m.points = snapshotPoints(e);
    m.density = analysis::densityDistribution(m.points);
    if (clusters)
        m.clusters = analysis::computeClusterStats(analysis::findClusters(m.points, m_scene.edmd.clusterDelta).sizes, e.size());
    return m;
}

template <int D, class Queue>
void EdmdRun<D, Queue>::seriesRow(const Engine& e, io::SeriesWriter& series, const Measurement& m) {
    const auto& points = m.points;
    const auto vel = analysis::velocityStats(points);
    const Real n = static_cast<Real>(e.size());
    const Real t = e.time();
    const Real kinetic = e.kineticEnergy();
    const auto& st = e.stats();
    const Real dt = t - m_book.lastTime;
    const Real dC = static_cast<Real>(st.collisions - m_book.lastCollisions);
    const Real frequency = dt > 0 ? 2 * dC / (n * dt) : std::numeric_limits<Real>::quiet_NaN();  // f_E = 2 dC/(N dt), spec 5.2
    // Collisional virial (spec 7 item 27): P = (2 <E_kin> + sum r.J / dt) / (D V) over the interval.
    const Real meanKinetic = 0.5 * (kinetic + m_book.lastKinetic);
    const Real pressure = dt > 0 ? (2 * meanKinetic + (e.collisionalVirial() - m_book.lastVirial) / dt) / (D * m_totalVolume)
                                 : std::numeric_limits<Real>::quiet_NaN();
    const Real meanT = 2 * meanKinetic / (D * n);
    const Real reduced = pressure * m_totalVolume / (n * meanT) - 1;
    // Mean free path from the measured E and f_E, thesis mean-speed convention (Eq. 5.9 with the
    // audit fix sqrt(2E/(D m)) = sqrt(T/m)).
    const Real meanSpeed = std::sqrt(std::pow(2.0, D) / kPi) * std::sqrt(vel.temperature / m_meanMass);
    const Real tau = m_setup.lambda > 0 ? m_setup.lambda * t / (2 * D * m_setup.tE) : 0;
    const Real tHaff = m_setup.lambda > 0 ? m_scene.edmd.temperature / ((1 + tau) * (1 + tau)) : m_scene.edmd.temperature;
    // Volume fraction with the current radii (growing spheres change it), averaged over the row
    // interval like the pressure, so that an equation of state can be read off one row.
    Real particleVolume = 0;
    for (const Real r : points.radius) particleVolume += edmd::ballVolume(D, r);
    const Real fractionNow = particleVolume / m_totalVolume;
    const Real fraction = m_book.lastVolumeFraction >= 0 ? 0.5 * (fractionNow + m_book.lastVolumeFraction) : fractionNow;
    std::vector<double> row = {t,
                               tau,
                               static_cast<double>(st.events),
                               static_cast<double>(st.collisions),
                               2 * static_cast<double>(st.collisions) / n,
                               static_cast<double>(st.wallCollisions),
                               kinetic,
                               e.rotationalEnergy(),
                               e.potentialEnergy(),
                               kinetic + e.rotationalEnergy() + e.potentialEnergy(),
                               e.dissipatedEnergy(),
                               fraction,
                               vel.kineticEnergy,
                               vel.temperature,
                               tHaff,
                               frequency,
                               frequency > 0 ? meanSpeed / frequency : std::numeric_limits<Real>::quiet_NaN(),
                               pressure,
                               reduced,
                               st.collisions ? static_cast<double>(st.tcElastic) / static_cast<double>(st.collisions) : 0.0,
                               vel.pooled.kurtosis};
    for (int d = 0; d < D; ++d) row.push_back(vel.axis[d].kurtosis);
    for (const Real q : m.density.quantiles) row.push_back(q);
    m_lastRow = {{"time", t}, {"tau", tau}, {"temperature", vel.temperature}, {"collision_frequency", frequency},
                 {"reduced_pressure", reduced}, {"kurtosis", vel.pooled.kurtosis}};
    if (m.clusters) {
        const auto& cs = *m.clusters;
        for (const double v : {static_cast<double>(cs.clusterCount), cs.moment[1], cs.moment[2], cs.reducedMoment[1],
                               cs.reducedMoment[2], static_cast<double>(cs.largest), cs.largestFraction})
            row.push_back(v);
        m_lastRow["M1"] = cs.moment[1];
        m_lastRow["q_x"] = cs.largestFraction;
    }
    series.row(row);
    m_book.lastTime = t;
    m_book.lastCollisions = st.collisions;
    m_book.lastVirial = e.collisionalVirial();
    m_book.lastKinetic = kinetic;
    m_book.lastVolumeFraction = fractionNow;
}

template <int D, class Queue>
void EdmdRun<D, Queue>::snapshot(const Engine& e, io::PvdWriter& pvd, Measurement& m) {
    const int index = static_cast<int>(m_book.nextSnapshot++);
    if (m_scene.output.vtk) {
        std::vector<std::uint64_t> ids(e.size());
        std::vector<double> collisions(e.size());
        for (std::uint32_t i = 0; i < e.size(); ++i) {
            ids[i] = i;
            collisions[i] = static_cast<double>(e.collisions(i));
        }
        const std::string file = io::snapshotFileName("gas", index);
        io::writeGasVtp(m_dir + "/" + file, m.points, ids, collisions, e.time());
        pvd.add(e.time(), 0, file);
        pvd.write();
    }
    if (!m_scene.edmd.analysisFiles) return;
    // Analysis files (spec 5.2): g(r), p(v), local density distribution, cluster sizes.
    fs::create_directories(m_dir + "/analysis");
    if (!m.clusters)
        m.clusters = analysis::computeClusterStats(analysis::findClusters(m.points, m_scene.edmd.clusterDelta).sizes, e.size());
    io::GasAnalysisSettings settings;
    settings.radius = m_setup.init.radius;
    settings.clusterDelta = m_scene.edmd.clusterDelta;
    io::writeGasAnalysisFiles(fmt::format("{}/analysis/{{}}_{:06d}.csv", m_dir, index), m.points, m.density, *m.clusters,
                              settings, e.time());
}

template <int D, class Queue>
void EdmdRun<D, Queue>::writeCheckpoint(const Engine& e) const {
    const std::string path = m_dir + "/checkpoint.bin", tmp = path + ".tmp";
    {
        std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
        writePod(os, kCheckpointMagic);
        writeString(os, m_scene.edmd.queue);
        writePod<std::uint64_t>(os, e.size());
        writePod(os, m_book);
        e.saveState(os);
        if (!os) throw std::runtime_error("cannot write " + tmp);
    }
    fs::rename(tmp, path);
}

template <int D, class Queue>
void EdmdRun<D, Queue>::readCheckpoint(Engine& e) {
    const std::string path = m_opt.resumeDir + "/checkpoint.bin";
    std::ifstream is(path, std::ios::binary);
    if (!is) throw std::runtime_error("no checkpoint at " + path);
    if (readPod<std::uint64_t>(is) != kCheckpointMagic)
        throw std::runtime_error(path + " is not an edmd checkpoint of this version");
    if (readString(is) != m_scene.edmd.queue) throw std::runtime_error(path + " was written with another edmd.queue");
    if (readPod<std::uint64_t>(is) != e.size()) throw std::runtime_error(path + " holds another number of particles");
    m_book = readPod<Bookkeeping>(is);
    e.loadState(is);
}

template <int D, class Queue>
int EdmdRun<D, Queue>::run() {
    const double startWall = wallSeconds();
    const auto& E = m_scene.edmd;
    auto state = io::makeEdmdState<D>(m_scene, m_setup);
    const std::uint32_t n = static_cast<std::uint32_t>(state.x.size());
    m_totalVolume = 1;
    for (int d = 0; d < D; ++d) m_totalVolume *= m_setup.config.box[d];
    m_meanMass = 0;
    for (const Real m : state.mass) m_meanMass += m / n;
    // The elastic pre-run (spec 4.2 step 3) uses the same box, walls and gravity, eps = 1, no TC.
    edmd::EngineConfig elastic = m_setup.config;
    elastic.restitution = {};
    elastic.wallRestitution = 1;
    Engine engine(elastic, std::move(state.x), std::move(state.v), std::move(state.radius), std::move(state.mass));
    const bool resumed = !m_opt.resumeDir.empty();
    if (resumed) {
        try {
            readCheckpoint(engine);
        } catch (const std::runtime_error& err) {
            throw SceneError(makeDiagnostic(m_opt.resumeDir, 0, "--resume", err.what()));
        }
    } else {
        if (m_setup.equilibrationCollisions > 0) {
            if (!m_opt.quiet)
                fmt::print(stderr, "equilibrating: elastic pre-run of {} collisions per particle ...\n", E.equilibrate);
            const double t0 = wallSeconds();
            engine.runCollisions(m_setup.equilibrationCollisions);
            m_book.equilibrationWall = wallSeconds() - t0;
        }
        engine.restartClock();
        engine.setCollisionRules(m_setup.config.restitution, m_setup.config.wallRestitution, m_setup.config.tc);
        m_book.lastKinetic = engine.kineticEnergy();
    }
    const Real endTime = m_setup.endTime;
    const bool byCollisions = m_setup.endCollisions > 0;
    const Real snapEvery = m_scene.output.snapshotInterval;
    const Real checkpointEvery = m_scene.output.checkpointInterval > 0 ? m_scene.output.checkpointInterval
                                 : std::isfinite(endTime)                ? endTime / 10
                                                                         : 0;
    if (resumed && engine.time() >= endTime)
        throw SceneError(makeDiagnostic(m_scene.run.loc.file, m_scene.run.loc.line, "run.end_time",
                                        fmt::format("the checkpoint in {} is at t = {:.6g} s; the run ends there already",
                                                    m_opt.resumeDir, engine.time())));

    io::SeriesWriter series(m_dir + "/series.csv", columns(), resumed ? engine.time() : -1.0);
    io::PvdWriter pvd(m_dir + "/snapshots.pvd");
    if (resumed && fs::exists(m_dir + "/snapshots.pvd")) {
        pvd.load();
        pvd.truncateAfter(engine.time());
    }
    if (!resumed) {
        Measurement m = measure(engine, E.clusters);
        seriesRow(engine, series, m);
        snapshot(engine, pvd, m);
        m_book.nextSnapshotTime = snapEvery > 0 ? snapEvery : std::numeric_limits<Real>::infinity();
        m_book.nextCheckpointTime = checkpointEvery > 0 ? checkpointEvery : std::numeric_limits<Real>::infinity();
        series.flush();
    }
    if (std::isfinite(endTime) && E.series == "log" && m_scene.output.seriesInterval == 0 && rowTime(1) >= endTime)
        fmt::print(stderr, "note: edmd.series_first is not before the end; series.csv has one row at the end\n");
    if (!m_opt.quiet) {
        fmt::print(stderr, "granulab {}: edmd {}D, {} {}, volume fraction {:.4f}, eps {}, t_E = {:.4g} s, TC t_c = {:.3g} s, ",
                   kVersion, D, n, D == 2 ? "disks" : "spheres", m_setup.volumeFraction, E.restitution, m_setup.tE,
                   m_setup.config.tc);
        if (byCollisions) fmt::print(stderr, "{} collisions -> {}\n", m_setup.endCollisions, m_dir);
        else fmt::print(stderr, "to t = {:.6g} s{} -> {}\n", endTime,
                        E.endTau > 0 ? fmt::format(" (tau = {:.4g})", E.endTau) : std::string(), m_dir);
    }

    Progress progress(byCollisions ? static_cast<double>(m_setup.endCollisions) : endTime, m_opt.quiet);
    const double loopStart = wallSeconds();
    const std::uint64_t eventsAtStart = engine.stats().events, collisionsAtStart = engine.stats().collisions;
    bool finished = false;
    while (!finished) {
        // Next stop: series row, snapshot or checkpoint, whichever comes first.
        if (byCollisions) {
            const std::uint64_t target = std::min<std::uint64_t>(
                m_setup.endCollisions,
                static_cast<std::uint64_t>(m_book.nextRow) * m_setup.endCollisions / static_cast<std::uint64_t>(E.seriesPoints));
            engine.runCollisions(target > engine.stats().collisions ? target - engine.stats().collisions : 0);
            finished = engine.stats().collisions >= m_setup.endCollisions;
            ++m_book.nextRow;
        } else {
            const Real tRow = std::min(rowTime(m_book.nextRow), endTime);
            const Real stop = std::min({tRow, m_book.nextSnapshotTime, m_book.nextCheckpointTime});
            engine.runUntil(stop);
            finished = stop >= endTime;
            if (stop < tRow) {  // a snapshot or checkpoint only
                const double t0 = wallSeconds();
                if (stop >= m_book.nextSnapshotTime) {
                    Measurement m = measure(engine, false);
                    snapshot(engine, pvd, m);
                    m_book.nextSnapshotTime += snapEvery;
                }
                if (stop >= m_book.nextCheckpointTime) {
                    writeCheckpoint(engine);
                    m_book.nextCheckpointTime += checkpointEvery;
                }
                m_outputSeconds += wallSeconds() - t0;
                progress.update(engine.time(), static_cast<std::int64_t>(engine.stats().events));
                continue;
            }
            ++m_book.nextRow;
        }
        const double t0 = wallSeconds();
        Measurement m = measure(engine, E.clusters);
        seriesRow(engine, series, m);
        if (!finished && engine.time() >= m_book.nextSnapshotTime) {
            snapshot(engine, pvd, m);
            while (m_book.nextSnapshotTime <= engine.time()) m_book.nextSnapshotTime += snapEvery;
        }
        // Collision-count runs without an interval: a checkpoint every tenth of the rows.
        const bool rowCheckpoint = byCollisions && m_scene.output.checkpointInterval == 0 &&
                                   (m_book.nextRow - 1) % std::max<std::int64_t>(1, E.seriesPoints / 10) == 0;
        if (finished || rowCheckpoint || engine.time() >= m_book.nextCheckpointTime) {
            if (finished) snapshot(engine, pvd, m);
            series.flush();
            writeCheckpoint(engine);
            while (m_book.nextCheckpointTime <= engine.time()) m_book.nextCheckpointTime += checkpointEvery;
        }
        m_outputSeconds += wallSeconds() - t0;
        progress.update(byCollisions ? static_cast<double>(engine.stats().collisions) : engine.time(),
                        static_cast<std::int64_t>(engine.stats().events));
    }
    const double loopSeconds = wallSeconds() - loopStart;
    progress.finish(byCollisions ? static_cast<double>(engine.stats().collisions) : engine.time(),
                    static_cast<std::int64_t>(engine.stats().events));

    // final.csv: one row per particle, streamed (a million-particle text would not fit a string).
    {
        const std::string path = m_dir + "/final.csv", tmp = path + ".tmp";
        std::FILE* f = std::fopen(tmp.c_str(), "w");
        if (!f) throw std::runtime_error("cannot write " + tmp);
        fmt::print(f, "{}", D == 2 ? "id,shape,x,y,vx,vy,omega,radius,mass,collisions\n"
                                   : "id,shape,x,y,z,vx,vy,vz,omega_x,omega_y,omega_z,radius,mass,collisions\n");
        for (std::uint32_t i = 0; i < n; ++i) {
            const auto x = engine.positionNow(i);
            const auto v = engine.velocityNow(i);
            const auto w = engine.omega(i);
            fmt::print(f, "{},{}", i, D == 2 ? "disk" : "sphere");
            for (int d = 0; d < D; ++d) fmt::print(f, ",{:.17g}", x[d]);
            for (int d = 0; d < D; ++d) fmt::print(f, ",{:.17g}", v[d]);
            if (D == 2) fmt::print(f, ",{:.17g}", w[2]);
            else fmt::print(f, ",{:.17g},{:.17g},{:.17g}", w[0], w[1], w[2]);
            fmt::print(f, ",{:.17g},{:.17g},{}\n", engine.radius(i), engine.mass(i), engine.collisions(i));
        }
        if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + tmp);
        fs::rename(tmp, path);
    }
    // Kinetic-theory reference curves (spec 7 item 31) for comparison plots.
    nlohmann::json theory;
    if (m_setup.lambda > 0 && E.restitutionModel == "constant" && E.radiusMax <= E.radius) {
        analysis::ReferenceSetup ref;
        ref.dim = D;
        ref.n = n;
        ref.nu = std::min(m_setup.volumeFraction, D == 2 ? 0.69 : 0.49);
        ref.eps = E.restitution;
        ref.m = E.mass;
        ref.a = E.radius;
        ref.T0 = E.temperature;
        const auto th = analysis::referenceThresholds(ref);
        std::vector<Real> taus;
        const Real tauEnd = std::isfinite(endTime) ? std::max(1.0, m_setup.lambda * endTime / (2 * D * m_setup.tE)) : 1e5;
        for (Real tau = 1e-3; tau <= tauEnd * 1.0001; tau *= std::pow(10.0, 0.05)) taus.push_back(tau);
        io::writeFileAtomically(m_dir + "/theory.csv", analysis::referenceCurvesCsv(ref, taus));
        theory = {{"g_2a", th.g2a}, {"l_opt", th.lOpt}, {"lambda", th.lambda}, {"lambda_cl", th.lambdaCl},
                  {"lambda_sh", th.lambdaSh}, {"eps_ic", th.epsIc}, {"eps_cl", th.epsCl}, {"t_E", th.tE},
                  {"f_E0", th.fE0}, {"l_E", th.lE}, {"tau_hc", th.tauHc}, {"tau_cs", th.tauCs}, {"tau_p_fit", th.tauPFit}};
    }

    const auto& st = engine.stats();
    const double events = static_cast<double>(st.events - eventsAtStart);
    const double collisions = static_cast<double>(st.collisions - collisionsAtStart);
    const double engineSeconds = std::max(1e-9, loopSeconds - m_outputSeconds);
    nlohmann::json js;
    js["engine"] = "edmd";
    js["version"] = kVersion;
    js["scene"] = m_opt.scene;
    js["status"] = "completed";
    js["dimension"] = D;
    js["particles"] = n;
    js["volume_fraction"] = m_setup.volumeFraction;
    js["box"] = std::vector<Real>(m_setup.config.box.begin(), m_setup.config.box.begin() + D);
    js["periodic"] = std::vector<bool>(m_setup.config.periodic.begin(), m_setup.config.periodic.begin() + D);
    js["radius"] = E.radius;
    js["queue"] = E.queue;
    const auto cells = engine.cellsPerAxis();
    js["cells_per_axis"] = std::vector<int>(cells.begin(), cells.begin() + D);
    js["sim_time"] = engine.time();
    js["t_E"] = m_setup.tE;
    js["tau"] = m_setup.lambda > 0 ? m_setup.lambda * engine.time() / (2 * D * m_setup.tE) : 0.0;
    js["tc"] = m_setup.config.tc;
    js["resumed"] = resumed;
    js["events"] = st.events;
    js["collisions"] = st.collisions;
    js["annulled"] = st.annulled;
    js["cell_crossings"] = st.cellCrossings;
    js["wall_collisions"] = st.wallCollisions;
    js["tc_elastic"] = st.tcElastic;
    js["regrids"] = st.regrids;
    js["wall_time_s"] = wallSeconds() - startWall;
    js["equilibration_time_s"] = m_book.equilibrationWall;
    js["loop_time_s"] = loopSeconds;
    js["output_time_s"] = m_outputSeconds;
    // Throughput of the event loop alone (outputs and measurements excluded), this session.
    js["events_per_s"] = events / engineSeconds;
    js["collisions_per_s"] = collisions / engineSeconds;
    js["energy"] = {{"kinetic", engine.kineticEnergy()}, {"rotational", engine.rotationalEnergy()},
                    {"potential", engine.potentialEnergy()}, {"dissipated", engine.dissipatedEnergy()}};
    const auto p = engine.momentum();
    std::vector<Real> momentum(p.c, p.c + D);
    js["momentum"] = momentum;
    js["last_row"] = m_lastRow;
    js["memory_bytes"] = engine.memoryBytes();
    js["bytes_per_particle"] = static_cast<double>(engine.memoryBytes()) / n;
    js["peak_rss_bytes"] = peakRssBytes();
    if (!theory.is_null()) js["theory"] = theory;
    js["warnings"] = m_setup.warnings;
    io::writeFileAtomically(m_dir + "/summary.json", js.dump(2) + "\n");
    if (!m_opt.quiet) {
        fmt::print(stderr, "done: {} collisions, {} events in {:.3g} s ({:.3g} collisions/s, {:.3g} events/s)\n", collisions,
                   events, engineSeconds, js["collisions_per_s"].get<double>(), js["events_per_s"].get<double>());
        fmt::print("results in {}/ : summary.json, series.csv, final.csv{}{}, checkpoint.bin{}\n", m_dir,
                   m_scene.output.vtk ? ", snapshots.pvd" : "", E.analysisFiles ? ", analysis/" : "",
                   theory.is_null() ? "" : ", theory.csv");
        if (m_scene.output.vtk)
            fmt::print("view in ParaView: paraview {}/snapshots.pvd  (Glyph filter, type Sphere, scale array 'radius', "
                       "factor 2; colour by 'collisions')\n",
                       m_dir);
        fmt::print("measure the final state: granulab analyze {}\n", m_dir);
    }
    return kExitOk;
}

template <int D>
int runWithQueue(const RunOptions& opt, const model::SceneDef& scene, const io::EdmdSetup& setup, const std::string& dir) {
    if (scene.edmd.queue == "heap") return EdmdRun<D, edmd::AddressableHeap>(opt, scene, setup, dir).run();
    if (scene.edmd.queue == "tree") return EdmdRun<D, edmd::TournamentTree>(opt, scene, setup, dir).run();
    return EdmdRun<D, edmd::CalendarQueue>(opt, scene, setup, dir).run();
}

}  // namespace

int runEdmdCommand(const RunOptions& opt, const model::SceneDef& scene) {
    const io::EdmdSetup setup = io::validateEdmd(scene);  // SceneError -> exit 2 in main
    for (const auto& w : setup.warnings) fmt::print(stderr, "warning: {}\n", w);
    const std::string dir = !opt.outDir.empty() ? opt.outDir : (!opt.resumeDir.empty() ? opt.resumeDir : defaultOutDir(opt.scene));
    fs::create_directories(dir);
    return setup.dim == 2 ? runWithQueue<2>(opt, scene, setup, dir) : runWithQueue<3>(opt, scene, setup, dir);
}

}  // namespace granulab::app
