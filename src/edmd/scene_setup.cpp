// SPDX-License-Identifier: MIT
// The edmd engine's set-up from a checked [edmd] scene (edmd spec 2.4-2.8, 4.1-4.3): box, count
// and volume fraction resolved, engine configuration, run length, TC default 1e-5 t_E(0) (spec
// 4.3 [I]), the kinetic scales and the collapse warning; the initial state with the scene location.
#include "edmd/scene_setup.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/limits.hpp"
#include "edmd/kinetic_theory.hpp"

namespace granulab::edmd {

namespace {

/// Mean of r^D for radii uniform in [a, b] (= a^D when b <= a).
Real meanPower(int dim, Real a, Real b) {
    if (!(b > a)) return std::pow(a, dim);
    return (std::pow(b, dim + 1) - std::pow(a, dim + 1)) / ((dim + 1) * (b - a));
}

/// The scene names used by every step of the set-up.
struct Context {
    const model::SceneDef& sc;
    const model::EdmdDef& e;
    const SourceLoc& loc;  ///< [edmd], or [run] when the section has no location
    int D;
};

/// Box, count and volume fraction (two given, the third follows; edmd Eq. 4.2-4.4) and the
/// initial-state spec.
/// Returns false when the box or the count cannot be used for the further checks (reported).
bool resolveParticles(const Context& x, Setup& s, Diagnostics& d) {
    const auto& [sc, e, loc, D] = x;
    const Real meanVolume = ballVolume(D, 1.0) * meanPower(D, e.radius, e.radiusMax);
    std::array<Real, 3> box{1, 1, 1};
    std::uint64_t count = static_cast<std::uint64_t>(std::max<std::int64_t>(e.count, 0));
    if (e.box.empty()) {
        const Real L = std::pow(static_cast<Real>(count) * meanVolume / e.volumeFraction, 1.0 / D);
        for (int k = 0; k < D; ++k) box[k] = L;
    } else {
        for (int k = 0; k < D; ++k) box[k] = e.box[k];
    }
    Real volume = 1;
    for (int k = 0; k < D; ++k) volume *= box[k];
    // Every derived size must be a positive finite number (a radius of 1e300 or a fraction of
    // 5e-324 overflows the box; issue 11).
    if (!(meanVolume > 0 && std::isfinite(meanVolume) && volume > 0 && std::isfinite(volume))) {
        const bool particleTooLarge = !(meanVolume > 0 && std::isfinite(meanVolume));
        d.error(loc,
                particleTooLarge ? "edmd.radius"
                : e.box.empty()  ? "edmd.volume_fraction"
                                 : "edmd.box",
                fmt::format("radius {:.4g} m gives a particle volume of {:.4g} m^{} and the box edges of "
                            "{:.4g} m (volume {:.4g} m^{}): outside the range of double precision; choose "
                            "radius, count and volume fraction whose volumes are finite",
                            std::max(e.radius, e.radiusMax), meanVolume, D, box[0], volume, D));
        return false;
    }
    const Real resolvedCount =
        count > 0 ? static_cast<Real>(count) : std::round(e.volumeFraction * volume / meanVolume);
    if (!(resolvedCount >= 2 && resolvedCount <= kMaxParticleCount)) {
        d.error(loc, "edmd.count",
                fmt::format("resolves to {:.6g} particles; allowed [2, {:.0f}] (a gas and its measurements "
                            "need two particles; ids are 32-bit)",
                            resolvedCount, kMaxParticleCount));
        if (!(resolvedCount >= 1 && resolvedCount <= kMaxParticleCount)) return false;
    }
    count = static_cast<std::uint64_t>(resolvedCount);
    // Engine state, the initial-state arrays and the queue: about 160 (2D) / 220 (3D) bytes each.
    checkMemoryFits(d, loc, "edmd.count", resolvedCount * (D == 2 ? 160.0 : 220.0),
                    fmt::format("{} particles", count));
    s.volumeFraction = static_cast<Real>(count) * meanVolume / volume;
    if (s.volumeFraction >= (D == 2 ? 0.9069 : 0.7405))
        d.error(loc, "edmd.volume_fraction",
                fmt::format("the particles fill {:.4f} of the box, beyond close packing", s.volumeFraction));
    s.init.box = box;
    for (int k = 0; k < 3; ++k)
        s.init.periodic[k] = e.periodic.empty() ? true : (k < D ? static_cast<bool>(e.periodic[k]) : true);
    s.init.count = count;
    s.init.radius = e.radius;
    s.init.radiusMax = e.radiusMax;
    s.init.mass = e.mass;
    s.init.placement = e.placement == "random" ? Placement::Random : Placement::Lattice;
    s.init.temperature = e.temperature;
    s.init.seed = sc.run.seed;
    return true;
}

/// The engine configuration and the kinetic-theory scales of the initial state (t_E, lambda,
/// the TC contact time default 1e-5 t_E, edmd spec 4.3 [I]).
void configureEngine(const Context& x, Setup& s) {
    const auto& [sc, e, loc, D] = x;
    const auto& box = s.init.box;
    auto& c = s.config;
    c.box = box;
    c.periodic = s.init.periodic;
    c.restitution.model = e.restitutionModel == "mcnamara_falcon" ? RestitutionModel::McNamaraFalcon
                          : e.restitutionModel == "viscoelastic"  ? RestitutionModel::Viscoelastic
                                                                  : RestitutionModel::Constant;
    c.restitution.eps = e.restitution;
    c.restitution.speed = e.restitutionSpeed > 0 ? e.restitutionSpeed : 1;
    c.wallRestitution = e.wallRestitution;
    c.tangentialRestitution = e.tangentialRestitution;
    c.inertiaFactor = e.inertiaFactor > 0 ? e.inertiaFactor : (D == 3 ? 0.4 : 0.5);
    for (std::size_t k = 0; k < e.gravity.size() && k < 3; ++k) c.gravity[k] = e.gravity[k];
    c.growthRate = e.growthRate;
    c.cellSize = e.cellSize;
    // Cell grid (edmd spec 2.4, AT-6): target C/N; "free" and "auto" (the default) the count
    // nearest the target on each axis, "morton" the power of two nearest it, which can be up to
    // 2^D times coarser at high density. The parallel engine takes the same grid (its Morton
    // numbering spreads the padding, spec 3.1), so a run on any number of ranks executes the
    // serial run's events on either.
    c.cellsPerParticle = e.cellsPerParticle;
    c.powerOfTwoCells = e.cellGrid == "morton";

    // Kinetic-theory scales (edmd spec 4.4) at the initial state, monodisperse formulas with
    // the mean radius for polydisperse gases.
    const Real meanRadius = std::pow(meanPower(D, e.radius, e.radiusMax), 1.0 / D);
    const Real nuForTheory = std::min(s.volumeFraction, D == 2 ? 0.69 : 0.49);  // g_2a diverges past freezing
    s.tE = enskogCollisionTime(D, nuForTheory, e.temperature, e.mass, meanRadius);
    s.lambda = 1 - e.restitution * e.restitution;
    const bool dissipative = e.restitution < 1 || e.restitutionModel != "constant" || e.wallRestitution < 1;
    c.tc = e.tc >= 0 ? e.tc : (dissipative ? 1e-5 * s.tE : 0);
}

/// Run length (exactly one of run.end_time, edmd.end_tau, edmd.end_collisions), growth limits
/// and the cell grid's demand on the box.
void resolveRunLength(const Context& x, Setup& s, Diagnostics& d) {
    const auto& [sc, e, loc, D] = x;
    const auto& c = s.config;
    const std::uint64_t count = s.init.count;
    const auto& box = s.init.box;
    // Growth needs a periodic box; shrinking must stay above zero radius.
    if (e.growthRate != 0)
        for (int k = 0; k < D; ++k)
            if (!c.periodic[k])
                d.error(loc, "edmd.growth_rate",
                        "growing spheres need a periodic box (all edmd.periodic true)");
    // Run length: exactly one of run.end_time, edmd.end_tau, edmd.end_collisions.
    const int ends = (sc.run.endTime > 0 ? 1 : 0) + (e.endTau > 0 ? 1 : 0) + (e.endCollisions > 0 ? 1 : 0);
    if (ends != 1)
        d.error(sc.run.loc, "run.end_time",
                fmt::format("give exactly one run length: run.end_time [s], edmd.end_tau (scaled time, "
                            "Eq. 4.57) or edmd.end_collisions (per particle); got {}",
                            ends));
    if (sc.run.endTime < 0)
        d.error(sc.run.loc, "run.end_time", fmt::format("must be > 0 [s], got {}", sc.run.endTime));
    if (e.endTau < 0) d.error(loc, "edmd.end_tau", fmt::format("must be > 0, got {}", e.endTau));
    if (e.endCollisions < 0)
        d.error(loc, "edmd.end_collisions", fmt::format("must be > 0, got {}", e.endCollisions));
    if (e.endTau > 0 && !(s.lambda > 0 && e.restitutionModel == "constant"))
        d.error(loc, "edmd.end_tau",
                "tau = lambda t/(2 D t_E) needs a constant restitution below 1 (edmd.restitution < 1)");
    s.endTime = sc.run.endTime > 0             ? sc.run.endTime
                : e.endTau > 0 && s.lambda > 0 ? e.endTau * 2 * D * s.tE / s.lambda
                                               : std::numeric_limits<Real>::infinity();
    // Collision counts (per particle x N/2) and the run's clock scales must be representable.
    const Real endCollisions = e.endCollisions > 0 ? std::round(e.endCollisions * count / 2.0) : 0;
    const Real equilibration = std::round(e.equilibrate * count / 2.0);
    if (!(endCollisions <= kExactIntegerLimit))
        d.error(loc, "edmd.end_collisions",
                fmt::format("{} per particle x {} particles / 2 = {:.3g} collisions; allowed at most 2^53",
                            e.endCollisions, count, endCollisions));
    if (!(equilibration <= kExactIntegerLimit))
        d.error(loc, "edmd.equilibrate",
                fmt::format("{} per particle x {} particles / 2 = {:.3g} collisions; allowed at most 2^53",
                            e.equilibrate, count, equilibration));
    if (!(s.tE > 0 && std::isfinite(s.tE)) || !std::isfinite(static_cast<Real>(count) * e.temperature))
        d.error(loc, "edmd.temperature",
                fmt::format(
                    "T = {:.4g} J with m = {:.4g} kg and {} particles gives a collision time t_E = {:.4g} s "
                    "and a total energy N T = {:.4g} J; both must be finite and positive",
                    e.temperature, e.mass, count, s.tE, static_cast<Real>(count) * e.temperature));
    if (!(s.endTime > 0))
        d.error(loc, "run.end_time",
                fmt::format("the run's end resolves to t = {:.4g} s; it must be > 0", s.endTime));
    s.endCollisions = endCollisions <= kExactIntegerLimit ? static_cast<std::uint64_t>(endCollisions) : 0;
    s.equilibrationCollisions =
        equilibration <= kExactIntegerLimit ? static_cast<std::uint64_t>(equilibration) : 0;
    if (e.growthRate < 0 && std::isfinite(s.endTime) && !(e.radius + e.growthRate * s.endTime > 0))
        d.error(
            loc, "edmd.growth_rate",
            fmt::format("the radius {} m shrinks to zero before the end at t = {} s", e.radius, s.endTime));
    if (e.series == "log" && !std::isfinite(s.endTime))
        d.error(loc, "edmd.series", "a logarithmic series needs an end time (run.end_time or edmd.end_tau)");
    // The box must hold 3 cells of the largest diameter per periodic axis (at the end when growing).
    Real amax = std::max(e.radius, e.radiusMax);
    if (e.growthRate > 0 && std::isfinite(s.endTime)) amax += e.growthRate * s.endTime;
    for (int k = 0; k < D; ++k)
        if (c.periodic[k] && !(box[k] >= 6 * amax))
            d.error(loc, "edmd.box",
                    fmt::format("axis {}: the periodic edge {:.6g} m must hold 3 diameters ({:.6g} m){}", k,
                                box[k], 6 * amax, e.growthRate > 0 ? " at the end of the growth" : ""));
    // A cell size given by hand: at least the largest diameter, 3 cells per periodic axis, and
    // fewer than 2^31 cells (the engine's cell heads are 32-bit and 4 bytes each).
    if (e.cellSize > 0) {
        Real cells = 1, smallest = kNoEvent;
        for (int k = 0; k < D; ++k) {
            cells *= std::min(std::floor(box[k] / e.cellSize), 65535.0);
            if (c.periodic[k]) smallest = std::min(smallest, box[k]);
        }
        if (!(e.cellSize <= smallest / 3))
            d.error(
                loc, "edmd.cell_size",
                fmt::format("{:.4g} m leaves fewer than 3 cells on a periodic axis of {:.6g} m; allowed (0, "
                            "{:.6g}] m, or 0 (automatic)",
                            e.cellSize, smallest, smallest / 3));
        else if (!(cells < 2147483648.0))
            d.error(loc, "edmd.cell_size",
                    fmt::format(
                        "{:.4g} m makes {:.3g} cells; allowed fewer than 2^31: raise it, or 0 (automatic)",
                        e.cellSize, cells));
    }
}

/// Cells per axis of the grid at the largest radius amax [m], or {0, 0, 0} where a periodic
/// axis would hold fewer than 3 cells.
std::array<int, 3> cellGridOrNone(int D, const EngineConfig& c, std::uint64_t count, Real amax) {
    try {
        const auto n = static_cast<std::uint32_t>(count);
        return D == 2 ? chooseCellGrid<2>(c, n, amax) : chooseCellGrid<3>(c, n, amax);
    } catch (const std::invalid_argument&) {
        return {0, 0, 0};
    }
}

/// The cell grid (edmd spec 2.4, 3.1, AT-6): a "morton" grid that a small periodic box cannot
/// hold (4 cells of one diameter, at the end of the growth when growing) falls back to the free
/// grid with a warning; a target C/N given by hand must give fewer than 2^31 cells that fit in
/// memory (4 bytes per cell head).
void resolveCellGrid(const Context& x, Setup& s, Diagnostics& d) {
    const auto& [sc, e, loc, D] = x;
    auto& c = s.config;
    const std::uint64_t count = s.init.count;
    if (count < 2) return;
    const Real a0 = std::max(e.radius, e.radiusMax);
    Real aEnd = a0;
    if (e.growthRate > 0 && std::isfinite(s.endTime)) aEnd += e.growthRate * s.endTime;
    if (c.powerOfTwoCells &&
        (cellGridOrNone(D, c, count, a0)[0] == 0 || cellGridOrNone(D, c, count, aEnd)[0] == 0)) {
        EngineConfig free = c;
        free.powerOfTwoCells = false;
        if (cellGridOrNone(D, free, count, a0)[0] > 0 && cellGridOrNone(D, free, count, aEnd)[0] > 0) {
            c.powerOfTwoCells = false;
            s.warnings.push_back(
                "edmd.cell_grid = \"morton\": a periodic axis holds fewer than 4 cells of one diameter" +
                std::string(e.growthRate > 0 ? " at the end of the growth" : "") +
                ", too few for a power of two; the run uses the free grid (edmd.cell_grid = \"free\")");
        }
    }
    if (e.cellsPerParticle > 0) {
        const auto grid = cellGridOrNone(D, c, count, a0);
        Real cells = 1;
        for (int k = 0; k < D; ++k) cells *= grid[k];
        if (!(cells < 2147483648.0))
            d.error(loc, "edmd.cells_per_particle",
                    fmt::format("{:.4g} cells per particle x {} particles makes {:.3g} cells; allowed fewer "
                                "than 2^31: lower it, or 0 (automatic)",
                                e.cellsPerParticle, count, cells));
        else
            checkMemoryFits(d, loc, "edmd.cells_per_particle", 4 * cells,
                            fmt::format("{:.3g} cells ({} cells per particle)", cells, e.cellsPerParticle));
    }
}

/// Warnings: inelastic collapse without the TC model (spec 4.3).
void addWarnings(const Context& x, Setup& s) {
    const auto& [sc, e, loc, D] = x;
    const auto& c = s.config;
    const Real lOpt = opticalDepth(D, static_cast<Real>(s.init.count), std::min(s.volumeFraction, 0.6));
    if (lOpt > 1 && e.restitution < collapseRestitution(lOpt) && c.tc == 0)
        s.warnings.push_back(fmt::format(
            "restitution {} is below the inelastic-collapse threshold eps_ic = {:.4f} (edmd Eq. 4.8) and "
            "the TC model is off (edmd.tc = 0): the run may stall in infinitely many collisions",
            e.restitution, collapseRestitution(lOpt)));
}

}  // namespace

Setup resolveScene(const model::SceneDef& sc) {
    Diagnostics d;
    const SourceLoc& loc = sc.edmd.loc.file.empty() ? sc.run.loc : sc.edmd.loc;
    const Context x{sc, sc.edmd, loc, sc.run.dimension == 2 ? 2 : 3};
    Setup s;
    s.dim = sc.run.dimension;
    if (!resolveParticles(x, s, d)) d.throwIfAny();  // the rest needs a finite box and count
    configureEngine(x, s);
    resolveRunLength(x, s, d);
    d.throwIfAny();
    resolveCellGrid(x, s, d);
    d.throwIfAny();
    addWarnings(x, s);
    return s;
}

template <int D>
GasState<D> makeGasState(const model::SceneDef& scene, const Setup& setup) {
    try {
        return makeInitialState<D>(setup.init);
    } catch (const std::invalid_argument& e) {
        const auto& loc = scene.edmd.loc.file.empty() ? scene.run.loc : scene.edmd.loc;
        throw SceneError(makeDiagnostic(
            loc.file, loc.line, scene.edmd.volumeFraction > 0 ? "edmd.volume_fraction" : "edmd.count",
            fmt::format("cannot place {} particles: {}", setup.init.count, e.what())));
    }
}

template GasState<2> makeGasState<2>(const model::SceneDef&, const Setup&);
template GasState<3> makeGasState<3>(const model::SceneDef&, const Setup&);

}  // namespace granulab::edmd
