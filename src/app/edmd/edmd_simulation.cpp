// SPDX-License-Identifier: MIT
// The edmd engine behind the Simulation seam (app/simulation.hpp; edmd spec sections 2, 4.2,
// 5.2; checklist items 16-30): initial state and elastic pre-run, the event loop stopped at
// output times or collision counts (the engine extrapolates, the schedule is untouched),
// series.csv with the gas measurements, VTK snapshots, analysis files, kinetic-theory reference
// curves, the engine state for checkpoints. The gas runs on one process (SerialGas: Engine<D,
// Queue>, the queue chosen once, here) or on the MPI ranks of mpirun (ParallelGas, edmd spec
// section 3); both fill one GasView, from which the root rank writes every output.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include "analysis/gas_clusters.hpp"
#include "analysis/gas_structure.hpp"
#include "analysis/gas_velocity.hpp"
#include "app/edmd/edmd_engine.hpp"
#include "app/edmd/parallel_gas.hpp"
#include "app/edmd/serial_gas.hpp"
#include "app/progress.hpp"
#include "app/simulation_options.hpp"
#include "core/binary_io.hpp"
#include "core/communicator.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "core/version.hpp"
#include "edmd/kinetic_theory.hpp"
#include "io/atomic_file.hpp"
#include "io/final_csv.hpp"
#include "io/gas_analysis_files.hpp"
#include "io/validate_edmd.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Values at the previous series row, for interval averages (collision frequency, pressure);
/// part of the checkpoint.
struct SeriesMemory {
    Real lastTime = 0;
    std::uint64_t lastCollisions = 0;
    Real lastVirial = 0;
    Real lastKinetic = 0;
    Real lastVolumeFraction = -1;  ///< at the previous row (growing spheres), -1 before the first row
    Real equilibrationWall = 0;    ///< [s] wall time of the elastic pre-run
};

/// The snapshot and the measurements that series rows and snapshots share, made once per stop.
struct Measurement {
    std::uint64_t events = 0;  ///< engine state it was made at (events, time)
    Real time = -1;
    analysis::PointSet points;
    analysis::DensityDistribution density;
    std::optional<analysis::ClusterStats> clusters;
};

/// The gas at time 0 with the elastic pre-run's rules (spec 4.2 step 3: the same box, walls and
/// gravity, eps = 1, no TC, fixed radii; start() switches to the run's rules).
template <int D>
edmd::EngineConfig preRunConfig(const edmd::Setup& setup) {
    edmd::EngineConfig elastic = setup.config;
    elastic.restitution = {};
    elastic.wallRestitution = 1;
    elastic.growthRate = 0;
    return elastic;
}

template <class Gas>
struct GasFactory;
template <int D, class Queue>
struct GasFactory<SerialGas<D, Queue>> {
    static SerialGas<D, Queue> make(const model::SceneDef& scene, const edmd::Setup& setup) {
        return SerialGas<D, Queue>(preRunConfig<D>(setup), edmd::makeGasState<D>(scene, setup));
    }
};
template <int D>
struct GasFactory<ParallelGas<D>> {
    static ParallelGas<D> make(const model::SceneDef& scene, const edmd::Setup& setup) {
        return ParallelGas<D>(worldCommunicator(), preRunConfig<D>(setup), edmd::ParallelConfig{},
                              edmd::makeGasState<D>(scene, setup));
    }
};

template <int D, class Gas>
class EdmdSimulation final : public Simulation {
public:
    EdmdSimulation(const model::SceneDef& scene, edmd::Setup setup, const SimulationOptions& options)
        : m_scene(scene),
          m_setup(std::move(setup)),
          m_options(options),
          m_totalVolume(boxVolume(m_setup)),
          m_engine(GasFactory<Gas>::make(scene, m_setup)) {
        const auto& view = m_engine.view();  // the mean mass (root); the same on every rank below
        std::array<double, 1> mean{0};
        for (const Real m : view.mass) mean[0] += m / static_cast<Real>(view.size());
        worldCommunicator().allSum(mean);
        m_meanMass = mean[0];
    }

    double time() const override { return m_engine.time(); }
    std::uint64_t count() const override { return m_engine.stats().collisions; }
    std::uint64_t progressCounter() const override { return m_engine.stats().events; }
    std::string progressUnit() const override { return "events"; }
    std::size_t particles() const override { return m_engine.size(); }
    std::size_t memoryBytes() const override { return m_engine.memoryBytes(); }
    std::vector<std::string> warnings() const override { return m_setup.warnings; }

    RunPlan plan() const override {
        using U = Schedule::Unit;
        const auto& E = m_scene.edmd;
        const auto& out = m_scene.output;
        const Real endTime = m_setup.endTime;
        RunPlan p;
        p.snapshots = Schedule::periodic(U::Time, out.snapshotInterval);
        p.progress = Schedule::never();
        p.benchmark = Schedule::never();
        if (m_setup.endCollisions == 0) {
            p.end = Schedule::once(U::Time, endTime);
            p.series = Schedule::points(
                U::Time, [this, endTime](std::int64_t k) { return std::min(rowTime(k), endTime); });
            p.checkpoints = Schedule::periodic(
                U::Time, out.checkpointInterval > 0 ? out.checkpointInterval : endTime / 10);
            p.progressEnd = endTime;
            return p;
        }
        // Collision-count runs: rows at equal collision steps; time schedules fire at the first row after.
        const std::uint64_t endC = m_setup.endCollisions, points = static_cast<std::uint64_t>(E.seriesPoints);
        const auto rowTarget = [endC, points](std::int64_t k) {
            return static_cast<double>(
                std::min<std::uint64_t>(endC, static_cast<std::uint64_t>(k) * endC / points));
        };
        p.end = Schedule::once(U::Count, static_cast<double>(endC));
        p.series = Schedule::points(U::Count, rowTarget);
        p.snapshots.exact = false;
        if (out.checkpointInterval > 0) {
            p.checkpoints = Schedule::periodic(U::Time, out.checkpointInterval, false);
        } else {  // a checkpoint every tenth of the rows
            const std::int64_t every = std::max<std::int64_t>(1, E.seriesPoints / 10);
            p.checkpoints = Schedule::points(
                U::Count, [rowTarget, every](std::int64_t k) { return rowTarget(k * every); });
        }
        p.progressEnd = static_cast<double>(endC);
        p.progressByCount = true;
        return p;
    }

    std::uint32_t start() override {
        if (m_setup.equilibrationCollisions > 0) {
            if (!m_options.quiet)
                fmt::print(stderr, "equilibrating: elastic pre-run of {} collisions per particle ...\n",
                           m_scene.edmd.equilibrate);
            const double t0 = wallSeconds();
            // In slices, so that the pre-run reports progress and its watchdog verdict.
            const std::uint64_t total = m_setup.equilibrationCollisions;
            Progress progress(static_cast<double>(total), m_options.quiet, "events", true);
            // Several ranks: tenths (every slice ends with an exact collision-count stop, which
            // repeats a section).
            const std::uint64_t slice = std::max<std::uint64_t>(1, total / (m_engine.ranks() > 1 ? 10 : 100));
            for (std::uint64_t done = 0; done < total;) {
                const std::uint64_t before = m_engine.stats().collisions;
                m_engine.runCollisions(std::min(slice, total - done));
                if (m_engine.interrupted()) return kSimInterrupted;  // a pre-run is not resumable
                if (m_engine.stalled() != edmd::Stall::None) {
                    m_stalledInPreRun = true;
                    return kSimStalled;
                }
                done += m_engine.stats().collisions - before;
                progress.update(static_cast<double>(done),
                                static_cast<std::int64_t>(m_engine.stats().events));
            }
            progress.finish(static_cast<double>(total), static_cast<std::int64_t>(m_engine.stats().events));
            m_memory.equilibrationWall = wallSeconds() - t0;
        }
        // The pre-run keeps the radii (the volume fraction at t = 0 is the scene's); growth starts now.
        m_engine.startRun(m_setup.config);
        m_memory.lastKinetic = energies().kinetic;
        return kSimOk;
    }

    void beginLoop() override {
        m_eventsAtStart = m_engine.stats().events;
        m_collisionsAtStart = m_engine.stats().collisions;
        if (std::isfinite(m_setup.endTime) && m_scene.edmd.series == "log" &&
            m_scene.output.seriesInterval == 0 && rowTime(1) >= m_setup.endTime)
            fmt::print(stderr,
                       "note: edmd.series_first is not before the end; series.csv has one row at the end\n");
    }

    std::uint32_t advance(const Stop& stop) override {
        if (stop.count != std::numeric_limits<std::uint64_t>::max()) {
            // Whichever comes first: the collision count, or the time (then the clock is at it).
            const std::uint64_t now = m_engine.stats().collisions;
            m_engine.runCollisions(stop.count > now ? stop.count - now : 0, stop.time);
            if (m_engine.stats().collisions < stop.count && m_engine.stalled() == edmd::Stall::None &&
                !m_engine.interrupted())
                m_engine.runUntil(stop.time);
        } else {
            m_engine.runUntil(stop.time);
        }
        if (m_engine.interrupted()) return kSimInterrupted;
        return m_engine.stalled() == edmd::Stall::None ? kSimOk : kSimStalled;
    }

    /// A non-finite energy at a series row (a collision rule or a growth rate out of range).
    std::uint32_t health() const override { return m_finiteEnergy ? kSimOk : kSimNonFinite; }

    std::string diagnose(std::uint32_t status) const override {
        if (status & kSimStalled) return stallDiagnosis();
        return fmt::format(
            "the kinetic energy became NaN or infinite at t = {:.6g} s ({} collisions). Likely causes: a "
            "restitution model or growth rate outside its range, or overlapping particles at the start.",
            m_engine.time(), m_engine.stats().collisions);
    }

    std::vector<std::string> seriesColumns() const override {
        std::vector<std::string> c = {"time",
                                      "tau",
                                      "events",
                                      "collisions",
                                      "collisions_per_particle",
                                      "wall_collisions",
                                      "kinetic_energy",
                                      "rotational_energy",
                                      "potential_energy",
                                      "total_energy",
                                      "dissipated_energy",
                                      "volume_fraction",
                                      "energy_per_particle",
                                      "temperature",
                                      "temperature_haff",
                                      "collision_frequency",
                                      "mean_free_path",
                                      "pressure",
                                      "reduced_pressure",
                                      "tc_elastic_fraction",
                                      "kurtosis"};
        for (int d = 0; d < D; ++d) c.push_back(std::string("kurtosis_") + "xyz"[d]);
        for (const char* q : {"nu_q01", "nu_q10", "nu_q25", "nu_q50", "nu_q75", "nu_q90", "nu_q99"})
            c.push_back(q);
        if (m_scene.edmd.clusters)
            for (const char* k :
                 {"clusters", "M1", "M2", "M1_reduced", "M2_reduced", "largest_cluster", "q_x"})
                c.push_back(k);
        return c;
    }

    std::vector<double> seriesRow() override;

    void snapshot(const std::string& dir, int index, io::PvdWriter& pvd) override;

    void writeFinal(const std::string& dir) override;

    nlohmann::json summaryKeys(const RunReport& report) override;

    std::string banner(const std::string& dir) const override {
        const auto& E = m_scene.edmd;
        std::string s = fmt::format(
            "granulab {}: edmd {}D, {} {}, volume fraction {:.4f}, eps {}, t_E = {:.4g} s, TC t_c = {:.3g} "
            "s, ",
            kVersion, D, m_engine.size(), D == 2 ? "disks" : "spheres", m_setup.volumeFraction, E.restitution,
            m_setup.tE, m_setup.config.tc);
        if (m_engine.ranks() > 1) {
            const auto cells = m_engine.cellsPerAxis();
            s += fmt::format("{} MPI ranks ({} cells per axis), ", m_engine.ranks(), cells[0]);
        }
        if (m_setup.endCollisions > 0)
            return s + fmt::format("{} collisions -> {}", m_setup.endCollisions, dir);
        return s + fmt::format("to t = {:.6g} s{} -> {}", m_setup.endTime,
                               E.endTau > 0 ? fmt::format(" (tau = {:.4g})", E.endTau) : std::string(), dir);
    }

    void printDone(const std::string& dir, const RunReport& report) const override {
        const auto& st = m_engine.stats();
        const double engineSeconds = std::max(1e-9, report.loopSeconds - report.outputSeconds);
        const double collisions = static_cast<double>(st.collisions - m_collisionsAtStart);
        const double events = static_cast<double>(st.events - m_eventsAtStart);
        fmt::print(stderr,
                   "done: {} collisions, {} events in {:.3g} s ({:.3g} collisions/s, {:.3g} events/s)\n",
                   collisions, events, engineSeconds, collisions / engineSeconds, events / engineSeconds);
        fmt::print("results in {}/ : summary.json, series.csv, final.csv{}{}, checkpoint.bin{}\n", dir,
                   m_scene.output.vtk ? ", snapshots.pvd" : "",
                   m_scene.edmd.analysisFiles ? ", analysis/" : "", m_theory.is_null() ? "" : ", theory.csv");
        if (m_scene.output.vtk)
            fmt::print(
                "view in ParaView: paraview {}/snapshots.pvd  (Glyph filter, type Sphere, scale array "
                "'radius', "
                "factor 2; colour by 'collisions')\n",
                dir);
        fmt::print("measure the final state: granulab analyze {}\n", dir);
    }

    io::SceneIdentity identity() const override {
        return {{"edmd.queue", m_scene.edmd.queue},
                {"dimension", std::to_string(D)},
                {"particles", std::to_string(m_engine.size())}};
    }
    void saveState(std::ostream& out) override {
        writePod(out, m_memory);
        m_engine.saveState(out);
    }
    void loadState(std::istream& in) override {
        m_memory = readPod<SeriesMemory>(in);
        m_engine.loadState(in, m_setup.config);
    }

private:
    static Real boxVolume(const edmd::Setup& setup) {
        Real volume = 1;
        for (int d = 0; d < D; ++d) volume *= setup.config.box[d];
        return volume;
    }

    /// Energies of the current state (root; zero elsewhere), once per state; every rank learns
    /// whether they are finite (the run loop branches on health() alike on every rank).
    GasEnergies energies() {
        const auto& view = m_engine.view();
        if (m_energiesAt != std::pair{view.time, view.events}) {
            m_energies = gasEnergies(view, m_setup.config);
            m_energiesAt = {view.time, view.events};
        }
        std::array<double, 1> sum{m_energies.kinetic + m_energies.rotational};
        worldCommunicator().allSum(sum);
        m_finiteEnergy = std::isfinite(sum[0]);
        return m_energies;
    }

    /// Time of series row `row` (row 0 is t = 0): series_interval, or linear/log over the run.
    Real rowTime(std::int64_t row) const {
        const Real end = m_setup.endTime;
        const auto points = m_scene.edmd.seriesPoints;
        if (!std::isfinite(end)) return kInf;  // collision-count rows
        if (m_scene.output.seriesInterval > 0)
            return std::min(end, m_scene.output.seriesInterval * static_cast<Real>(row));
        if (m_scene.edmd.series == "log") {
            const Real first = m_scene.edmd.seriesFirst > 0 ? m_scene.edmd.seriesFirst : m_setup.tE / 100;
            if (first >= end) return end;
            return first * std::pow(end / first, static_cast<Real>(row - 1) / static_cast<Real>(points - 1));
        }
        return end * static_cast<Real>(row) / static_cast<Real>(points);
    }

    /// Why the watchdog stopped the engine (issue 11): what stood still, and the likely cause.
    std::string stallDiagnosis() const {
        const auto& E = m_scene.edmd;
        const auto& st = m_engine.stats();
        const std::string where = m_stalledInPreRun ? " in the elastic pre-run (edmd.equilibrate)" : "";
        const std::string sofar =
            fmt::format("{} particle and {} wall collisions so far", st.collisions, st.wallCollisions);
        if (m_engine.stalled() == edmd::Stall::NoCollision)
            return fmt::format(
                "the run stalled{}: no collision in {} events at t = {:.6g} s ({}); the particles do not "
                "meet (too dilute a gas, or speeds near zero: edmd.temperature = {:g}). Raise the volume "
                "fraction or the temperature, or set edmd.equilibrate = 0.",
                where, 64 * m_engine.watchdogWindow(), m_engine.time(), sofar, E.temperature);
        std::string cause;
        const Real thermalSpeed = std::sqrt(E.temperature / E.mass);
        if (E.growthRate > 0)
            cause = fmt::format(
                "growing spheres jammed: the growth rate {:g} m/s is {:.3g} times the thermal speed "
                "sqrt(T/m) = {:.3g} m/s, so the packing locks before the particles can rearrange; lower "
                "edmd.growth_rate or raise edmd.temperature",
                E.growthRate, E.growthRate / thermalSpeed, thermalSpeed);
        else if (m_setup.config.tc == 0 && !m_stalledInPreRun)
            cause =
                "inelastic collapse (edmd spec 4.3): infinitely many collisions in finite time; switch the "
                "TC model on (remove edmd.tc = 0, or set edmd.tc > 0) or raise edmd.restitution and "
                "edmd.wall_restitution";
        else
            cause = fmt::format(
                "particles locked in contact (a collision sequence that does not end); a TC time t_c = "
                "{:.3g} "
                "s longer than the contact sequence, or a higher edmd.restitution, resolves it",
                m_setup.config.tc);
        return fmt::format(
            "the run stalled{}: simulated time stood still at t = {:.6g} s for {} events ({}). "
            "Likely cause: {}.",
            where, m_engine.time(), m_engine.watchdogWindow(), sofar, cause);
    }

    analysis::PointSet snapshotPoints(const GasView<D>& view) const;
    /// The measurement of the current state (the root rank's view), made once (cached until
    /// the engine moves on).
    Measurement& measure(const GasView<D>& view, bool clusters);

    const model::SceneDef& m_scene;
    edmd::Setup m_setup;
    SimulationOptions m_options;
    Real m_totalVolume = 1;
    Real m_meanMass = 1;
    Gas m_engine;
    GasEnergies m_energies;
    std::pair<Real, std::uint64_t> m_energiesAt{-1, 0};
    bool m_finiteEnergy = true;
    SeriesMemory m_memory;
    Measurement m_measurement;
    nlohmann::json m_lastRow;
    nlohmann::json m_theory;
    std::uint64_t m_eventsAtStart = 0, m_collisionsAtStart = 0;
    bool m_stalledInPreRun = false;
};

template <int D, class Gas>
analysis::PointSet EdmdSimulation<D, Gas>::snapshotPoints(const GasView<D>& view) const {
    analysis::PointSet p;
    p.dim = D;
    p.box = m_setup.config.box;
    p.periodic = m_setup.config.periodic;
    const std::uint32_t n = view.size();
    p.x.resize(static_cast<std::size_t>(D) * n);
    p.v.resize(static_cast<std::size_t>(D) * n);
    p.radius.resize(n);
    p.mass.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const auto& x = view.x[i];
        const auto& v = view.v[i];
        for (int d = 0; d < D; ++d) {
            // Inside [0, box) for the analyses (a wall contact sits exactly at the edge).
            p.x[static_cast<std::size_t>(D) * i + d] =
                std::clamp(x[d], Real(0), std::nextafter(p.box[d], Real(0)));
            p.v[static_cast<std::size_t>(D) * i + d] = v[d];
        }
        p.radius[i] = view.radius[i];
        p.mass[i] = view.mass[i];
    }
    return p;
}

template <int D, class Gas>
Measurement& EdmdSimulation<D, Gas>::measure(const GasView<D>& view, bool clusters) {
    Measurement& m = m_measurement;
    if (m.events != view.events || m.time != view.time) {
        m = Measurement{};
        m.events = view.events;
        m.time = view.time;
        m.points = snapshotPoints(view);
        m.density = analysis::densityDistribution(m.points);
    }
    if (clusters && !m.clusters)
        m.clusters = analysis::computeClusterStats(
            analysis::findClusters(m.points, m_scene.edmd.clusterDelta).sizes, m_engine.size());
    return m;
}

template <int D, class Gas>
std::vector<double> EdmdSimulation<D, Gas>::seriesRow() {
    const GasEnergies energy = energies();  // collective; the rest is the root's
    if (!m_engine.root()) return {};
    const Measurement& m = measure(m_engine.view(), m_scene.edmd.clusters);
    const auto& points = m.points;
    const auto vel = analysis::velocityStats(points);
    const Real n = static_cast<Real>(m_engine.size());
    const Real t = m_engine.time();
    const Real kinetic = energy.kinetic;
    const auto& st = m_engine.stats();
    auto& book = m_memory;
    const Real dt = t - book.lastTime;
    const Real dC = static_cast<Real>(st.collisions - book.lastCollisions);
    const Real frequency =
        dt > 0 ? 2 * dC / (n * dt) : std::numeric_limits<Real>::quiet_NaN();  // f_E = 2 dC/(N dt), spec 5.2
    // Collisional virial (spec 7 item 27): P = (2 <E_kin> + sum r.J / dt) / (D V) over the interval.
    const Real meanKinetic = 0.5 * (kinetic + book.lastKinetic);
    const Real pressure = dt > 0 ? (2 * meanKinetic + (m_engine.collisionalVirial() - book.lastVirial) / dt) /
                                       (D * m_totalVolume)
                                 : std::numeric_limits<Real>::quiet_NaN();
    const Real meanT = 2 * meanKinetic / (D * n);
    const Real reduced = pressure * m_totalVolume / (n * meanT) - 1;
    // Mean free path from the measured E and f_E, thesis mean-speed convention (Eq. 5.9 with the
    // audit fix sqrt(2E/(D m)) = sqrt(T/m)). f_E is the row interval's mean, so the speed is too:
    // sqrt(T) between the two rows taken as 1/(a + b t) (exact for Haff's law), whose mean is
    // s1 s2 ln(s1/s2)/(s1 - s2) (issue 11: the row-end speed read 12 % low at tau = 5).
    const Real s1 = std::sqrt(2 * book.lastKinetic / (D * n)), s2 = std::sqrt(2 * kinetic / (D * n));
    const Real meanRootT =
        s1 > 0 && s2 > 0 && std::abs(s1 - s2) > 1e-9 * s1 ? s1 * s2 * std::log(s1 / s2) / (s1 - s2) : s2;
    const Real meanSpeed = std::sqrt(std::pow(2.0, D) / kPi) * meanRootT / std::sqrt(m_meanMass);
    const Real tau = m_setup.lambda > 0 ? m_setup.lambda * t / (2 * D * m_setup.tE) : 0;
    const Real tHaff =
        m_setup.lambda > 0 ? m_scene.edmd.temperature / ((1 + tau) * (1 + tau)) : m_scene.edmd.temperature;
    // Volume fraction with the current radii (growing spheres change it), averaged over the row
    // interval like the pressure, so that an equation of state can be read off one row.
    Real particleVolume = 0;
    for (const Real r : points.radius) particleVolume += edmd::ballVolume(D, r);
    const Real fractionNow = particleVolume / m_totalVolume;
    const Real fraction =
        book.lastVolumeFraction >= 0 ? 0.5 * (fractionNow + book.lastVolumeFraction) : fractionNow;
    std::vector<double> row = {
        t,
        tau,
        static_cast<double>(st.events),
        static_cast<double>(st.collisions),
        2 * static_cast<double>(st.collisions) / n,
        static_cast<double>(st.wallCollisions),
        kinetic,
        energy.rotational,
        energy.potential,
        kinetic + energy.rotational + energy.potential,
        m_engine.dissipatedEnergy(),
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
    m_lastRow = {{"time", t},
                 {"tau", tau},
                 {"temperature", vel.temperature},
                 {"collision_frequency", frequency},
                 {"reduced_pressure", reduced},
                 {"kurtosis", vel.pooled.kurtosis}};
    if (m.clusters) {
        const auto& cs = *m.clusters;
        for (const double v :
             {static_cast<double>(cs.clusterCount), cs.moment[1], cs.moment[2], cs.reducedMoment[1],
              cs.reducedMoment[2], static_cast<double>(cs.largest), cs.largestFraction})
            row.push_back(v);
        m_lastRow["M1"] = cs.moment[1];
        m_lastRow["q_x"] = cs.largestFraction;
    }
    book.lastTime = t;
    book.lastCollisions = st.collisions;
    book.lastVirial = m_engine.collisionalVirial();
    book.lastKinetic = kinetic;
    book.lastVolumeFraction = fractionNow;
    return row;
}

template <int D, class Gas>
void EdmdSimulation<D, Gas>::snapshot(const std::string& dir, int index, io::PvdWriter& pvd) {
    const GasView<D>& view = m_engine.view();  // collective; the files are the root's
    if (!m_engine.root()) return;
    Measurement& m = measure(view, false);
    if (m_scene.output.vtk) {
        std::vector<std::uint64_t> ids(m_engine.size());
        std::vector<double> collisions(m_engine.size());
        for (std::uint32_t i = 0; i < m_engine.size(); ++i) {
            ids[i] = i;
            collisions[i] = static_cast<double>(view.collisions[i]);
        }
        const std::string file = io::snapshotFileName("gas", index);
        io::writeGasVtp(dir + "/" + file, m.points, ids, collisions, m_engine.time());
        pvd.add(m_engine.time(), 0, file);
        pvd.write();
    }
    if (!m_scene.edmd.analysisFiles) return;
    // Analysis files (spec 5.2): g(r), p(v), local density distribution, cluster sizes.
    measure(view, true);
    io::GasAnalysisSettings settings;
    settings.radius = m_setup.init.radius + m_setup.config.growthRate * m_engine.time();  // a(t), grown
    settings.clusterDelta = m_scene.edmd.clusterDelta;
    io::writeGasAnalysisFiles(fmt::format("{}/analysis/{{}}_{:06d}.csv", dir, index), m.points, m.density,
                              *m.clusters, settings, m_engine.time());
}

template <int D, class Gas>
void EdmdSimulation<D, Gas>::writeFinal(const std::string& dir) {
    const GasView<D>& view = m_engine.view();  // collective; the files are the root's
    if (!m_engine.root()) return;
    // Hard spheres carry no orientation: the contract's angle column is absent (io/final_csv.hpp).
    io::FinalCsvWriter out(dir + "/final.csv", {D, false, {"mass", "collisions"}});
    for (std::uint32_t i = 0; i < view.size(); ++i) {
        const auto& x = view.x[i];
        const auto& v = view.v[i];
        const auto& w = view.omega[i];
        io::FinalCsvParticle p;
        p.id = i;
        p.shape = D == 2 ? "disk" : "sphere";
        for (int d = 0; d < D; ++d) {
            p.x[d] = x[d];
            p.v[d] = v[d];
        }
        for (int d = 0; d < 3; ++d) p.omega[d] = w[d];
        p.radius = view.radius[i];
        out.row(p);
        out.extra(view.mass[i]);
        out.extra(std::uint64_t{view.collisions[i]});
        out.endRow();
    }
    out.commit();
    // Kinetic-theory reference curves (spec 7 item 31) for comparison plots.
    const auto& E = m_scene.edmd;
    if (!(m_setup.lambda > 0 && E.restitutionModel == "constant" && E.radiusMax <= E.radius)) return;
    edmd::ReferenceSetup ref;
    ref.dim = D;
    ref.n = m_engine.size();
    ref.nu = std::min(m_setup.volumeFraction, D == 2 ? 0.69 : 0.49);
    ref.eps = E.restitution;
    ref.m = E.mass;
    ref.a = E.radius;
    ref.T0 = E.temperature;
    const auto th = edmd::referenceThresholds(ref);
    std::vector<Real> taus;
    const Real endTime = m_setup.endTime;
    const Real tauEnd =
        std::isfinite(endTime) ? std::max(1.0, m_setup.lambda * endTime / (2 * D * m_setup.tE)) : 1e5;
    for (Real tau = 1e-3; tau <= tauEnd * 1.0001; tau *= std::pow(10.0, 0.05)) taus.push_back(tau);
    io::writeFileAtomically(dir + "/theory.csv", edmd::referenceCurvesCsv(ref, taus));
    m_theory = {
        {"g_2a", th.g2a},           {"l_opt", th.lOpt},   {"lambda", th.lambda}, {"lambda_cl", th.lambdaCl},
        {"lambda_sh", th.lambdaSh}, {"eps_ic", th.epsIc}, {"eps_cl", th.epsCl},  {"t_E", th.tE},
        {"f_E0", th.fE0},           {"l_E", th.lE},       {"tau_hc", th.tauHc},  {"tau_cs", th.tauCs},
        {"tau_p_fit", th.tauPFit}};
}

template <int D, class Gas>
nlohmann::json EdmdSimulation<D, Gas>::summaryKeys(const RunReport& report) {
    const auto& E = m_scene.edmd;
    const auto& st = m_engine.stats();
    const double events = static_cast<double>(st.events - m_eventsAtStart);
    const double collisions = static_cast<double>(st.collisions - m_collisionsAtStart);
    const double engineSeconds = std::max(1e-9, report.loopSeconds - report.outputSeconds);
    const GasEnergies energy = energies();                          // collective
    const nlohmann::json ranks = m_engine.rankKeys(engineSeconds);  // collective
    nlohmann::json js;
    js["dimension"] = D;
    js["volume_fraction"] = m_setup.volumeFraction;
    js["box"] = std::vector<Real>(m_setup.config.box.begin(), m_setup.config.box.begin() + D);
    js["periodic"] = std::vector<bool>(m_setup.config.periodic.begin(), m_setup.config.periodic.begin() + D);
    js["radius"] = E.radius;
    js["queue"] = E.queue;
    const auto cells = m_engine.cellsPerAxis();
    js["cells_per_axis"] = std::vector<int>(cells.begin(), cells.begin() + D);
    js["t_E"] = m_setup.tE;
    js["tau"] = m_setup.lambda > 0 ? m_setup.lambda * m_engine.time() / (2 * D * m_setup.tE) : 0.0;
    js["tc"] = m_setup.config.tc;
    js["resumed"] = report.resumed;
    js["events"] = st.events;
    js["collisions"] = st.collisions;
    js["annulled"] = st.annulled;
    js["cell_crossings"] = st.cellCrossings;
    js["wall_collisions"] = st.wallCollisions;
    js["tc_elastic"] = st.tcElastic;
    js["regrids"] = st.regrids;
    js["equilibration_time_s"] = m_memory.equilibrationWall;
    js["output_time_s"] = report.outputSeconds;
    // Throughput of the event loop alone (outputs and measurements excluded), this session.
    js["events_per_s"] = events / engineSeconds;
    js["collisions_per_s"] = collisions / engineSeconds;
    js["energy"] = {{"kinetic", energy.kinetic},
                    {"rotational", energy.rotational},
                    {"potential", energy.potential},
                    {"dissipated", m_engine.dissipatedEnergy()}};
    js["momentum"] = std::vector<Real>(energy.momentum.begin(), energy.momentum.begin() + D);
    if (!ranks.is_null()) js["parallel"] = ranks;
    js["last_row"] = m_lastRow;
    if (!m_theory.is_null()) js["theory"] = m_theory;
    return js;
}

template <int D>
std::unique_ptr<Simulation> withQueue(const model::SceneDef& scene, edmd::Setup setup,
                                      const SimulationOptions& options) {
    // Under mpirun with several ranks the parallel engine runs the gas (its kernel's queue is
    // the calendar queue; edmd.queue chooses the serial engine's).
    if (worldCommunicator().size() > 1)
        return std::make_unique<EdmdSimulation<D, ParallelGas<D>>>(scene, std::move(setup), options);
    const std::string& queue = scene.edmd.queue;
    if (queue == "heap")
        return std::make_unique<EdmdSimulation<D, SerialGas<D, edmd::AddressableHeap>>>(
            scene, std::move(setup), options);
    if (queue == "tree")
        return std::make_unique<EdmdSimulation<D, SerialGas<D, edmd::TournamentTree>>>(
            scene, std::move(setup), options);
    return std::make_unique<EdmdSimulation<D, SerialGas<D, edmd::CalendarQueue>>>(scene, std::move(setup),
                                                                                  options);
}

/// What the parallel engine does not run (edmd spec 3; issue 15), as scene errors (exit 2).
void checkSeveralRanks(const model::SceneDef& scene, const edmd::Setup& setup) {
    const int ranks = worldCommunicator().size();
    if (ranks <= 1) return;
    const auto& E = scene.edmd;
    Diagnostics diags;
    if (setup.config.growthRate != 0)
        diags.error(E.loc, "edmd.growth_rate",
                    fmt::format("growing spheres run on one process only (this run has {} MPI ranks); "
                                "allowed with several ranks: 0, or start the run without mpirun",
                                ranks));
    diags.throwIfAny();
}

}  // namespace

edmd::Setup checkAndResolveEdmd(const model::SceneDef& scene) {
    Diagnostics diags;
    io::checkEdmdDef(scene, diags);
    diags.throwIfAny();
    return edmd::resolveScene(scene);
}

std::unique_ptr<Simulation> makeEdmdSimulation(const model::SceneDef& scene,
                                               const SimulationOptions& options) {
    edmd::Setup setup = checkAndResolveEdmd(scene);
    checkSeveralRanks(scene, setup);
    return setup.dim == 2 ? withQueue<2>(scene, std::move(setup), options)
                          : withQueue<3>(scene, std::move(setup), options);
}

}  // namespace granulab::app
