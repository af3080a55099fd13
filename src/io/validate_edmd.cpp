// SPDX-License-Identifier: MIT
// [edmd] validation (edmd spec 2.4-2.8, 4.1-4.3): ranges, the box/count/volume-fraction
// triangle, run length, TC default 1e-5 t_E(0) (spec 4.3 [I]) and collapse/clustering warnings.
#include "io/validate_edmd.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <stdexcept>
#include <utility>

#include "analysis/kinetic_theory.hpp"

namespace granulab::io {

namespace {

/// Mean of r^D for radii uniform in [a, b] (= a^D when b <= a).
Real meanPower(int dim, Real a, Real b) {
    if (!(b > a)) return std::pow(a, dim);
    return (std::pow(b, dim + 1) - std::pow(a, dim + 1)) / ((dim + 1) * (b - a));
}

}  // namespace

EdmdSetup validateEdmd(const model::SceneDef& sc) {
    Diagnostics d;
    const model::EdmdDef& e = sc.edmd;
    const SourceLoc& loc = e.loc.file.empty() ? sc.run.loc : e.loc;
    auto positive = [&](const char* key, Real v, const char* unit) {
        if (!(v > 0) || !std::isfinite(v)) d.error(loc, key, fmt::format("must be > 0 [{}], got {}; allowed (0, inf)", unit, v));
    };
    auto inRange = [&](const char* key, Real v, Real lo, Real hi, const char* what) {
        if (!(v >= lo && v <= hi)) d.error(loc, key, fmt::format("must be in [{}, {}] ({}), got {}", lo, hi, what, v));
    };
    EdmdSetup s;
    s.dim = sc.run.dimension;
    if (s.dim != 2 && s.dim != 3)
        d.error(sc.run.loc, "run.dimension", fmt::format("the edmd engine simulates disks (2) or spheres (3); got {}", s.dim));
    const int D = s.dim == 2 ? 2 : 3;
    positive("edmd.radius", e.radius, "m");
    if (e.radiusMax != 0 && !(e.radiusMax >= e.radius))
        d.error(loc, "edmd.radius_max", fmt::format("must be >= edmd.radius = {} m (radii uniform in [radius, radius_max]), got {}",
                                                    e.radius, e.radiusMax));
    positive("edmd.mass", e.mass, "kg");
    positive("edmd.temperature", e.temperature, "J");
    if (!(e.equilibrate >= 0)) d.error(loc, "edmd.equilibrate", fmt::format("must be >= 0 collisions per particle, got {}", e.equilibrate));
    inRange("edmd.restitution", e.restitution, 0, 1, "normal restitution eps");
    inRange("edmd.wall_restitution", e.wallRestitution, 0, 1, "normal restitution at the walls");
    inRange("edmd.tangential_restitution", e.tangentialRestitution, -1, 1, "phi: -1 smooth, +1 perfectly rough");
    if (e.inertiaFactor != 0) inRange("edmd.inertia_factor", e.inertiaFactor, 1e-6, 1, "z = I/(m a^2): 0.4 solid sphere, 0.5 solid disk");
    if (e.restitutionModel != "constant") positive("edmd.restitution_speed", e.restitutionSpeed, "m/s");
    if (!(e.tc == -1 || e.tc >= 0)) d.error(loc, "edmd.tc", fmt::format("must be >= 0 [s] (0: off) or -1 (automatic), got {}", e.tc));
    if (!(e.cellSize >= 0)) d.error(loc, "edmd.cell_size", fmt::format("must be >= 0 [m] (0: automatic), got {}", e.cellSize));
    if (e.seriesPoints < 2 || e.seriesPoints > 1000000)
        d.error(loc, "edmd.series_points", fmt::format("must be in [2, 1000000], got {}", e.seriesPoints));
    if (!(e.seriesFirst >= 0)) d.error(loc, "edmd.series_first", fmt::format("must be >= 0 [s], got {}", e.seriesFirst));
    if (!(e.clusterDelta > 0 && e.clusterDelta <= 1)) d.error(loc, "edmd.cluster_delta", fmt::format("must be in (0, 1] (delta/2a; thesis: 0.1), got {}", e.clusterDelta));
    if (!e.box.empty() && e.box.size() != static_cast<std::size_t>(D))
        d.error(loc, "edmd.box", fmt::format("has {} edges; run.dimension = {} needs {}", e.box.size(), D, D));
    for (std::size_t k = 0; k < e.box.size(); ++k) positive("edmd.box", e.box[k], "m");
    if (!e.periodic.empty() && e.periodic.size() != static_cast<std::size_t>(D))
        d.error(loc, "edmd.periodic", fmt::format("has {} entries; run.dimension = {} needs {}", e.periodic.size(), D, D));
    if (!e.gravity.empty() && e.gravity.size() != static_cast<std::size_t>(D))
        d.error(loc, "edmd.gravity", fmt::format("has {} components; run.dimension = {} needs {}", e.gravity.size(), D, D));
    const std::pair<const char*, Real> intervals[] = {{"output.snapshot_interval", sc.output.snapshotInterval},
                                                      {"output.series_interval", sc.output.seriesInterval},
                                                      {"output.checkpoint_interval", sc.output.checkpointInterval}};
    for (const auto& [key, value] : intervals)
        if (!(value >= 0)) d.error(sc.output.loc, key, fmt::format("must be >= 0 [s], got {}", value));
    // The box / count / volume-fraction triangle: exactly two of the three.
    const int given = (!e.box.empty() ? 1 : 0) + (e.count > 0 ? 1 : 0) + (e.volumeFraction > 0 ? 1 : 0);
    if (e.count < 0) d.error(loc, "edmd.count", fmt::format("must be > 0, got {}", e.count));
    if (e.volumeFraction < 0 || e.volumeFraction >= (D == 2 ? 0.9069 : 0.7405))
        d.error(loc, "edmd.volume_fraction", fmt::format("must be in (0, {}) (close packing), got {}", D == 2 ? 0.9069 : 0.7405, e.volumeFraction));
    if (given != 2)
        d.error(loc, "edmd", fmt::format("give exactly two of box, count and volume_fraction (the third follows); got {}", given));
    d.throwIfAny();

    const Real meanVolume = edmd::ballVolume(D, 1.0) * meanPower(D, e.radius, e.radiusMax);
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
    if (count == 0) count = static_cast<std::uint64_t>(std::llround(e.volumeFraction * volume / meanVolume));
    if (count == 0 || count > (std::uint64_t{1} << 31))
        d.error(loc, "edmd.count", fmt::format("resolves to {} particles; allowed [1, 2^31]", count));
    s.volumeFraction = static_cast<Real>(count) * meanVolume / volume;
    if (s.volumeFraction >= (D == 2 ? 0.9069 : 0.7405))
        d.error(loc, "edmd.volume_fraction", fmt::format("the particles fill {:.4f} of the box, beyond close packing", s.volumeFraction));
    s.init.box = box;
    for (int k = 0; k < 3; ++k) s.init.periodic[k] = e.periodic.empty() ? true : (k < D ? static_cast<bool>(e.periodic[k]) : true);
    s.init.count = count;
    s.init.radius = e.radius;
    s.init.radiusMax = e.radiusMax;
    s.init.mass = e.mass;
    s.init.placement = e.placement == "random" ? edmd::Placement::Random : edmd::Placement::Lattice;
    s.init.temperature = e.temperature;
    s.init.seed = sc.run.seed;

    auto& c = s.config;
    c.box = box;
    c.periodic = s.init.periodic;
    c.restitution.model = e.restitutionModel == "mcnamara_falcon" ? edmd::RestitutionModel::McNamaraFalcon
                          : e.restitutionModel == "viscoelastic"  ? edmd::RestitutionModel::Viscoelastic
                                                                  : edmd::RestitutionModel::Constant;
    c.restitution.eps = e.restitution;
    c.restitution.speed = e.restitutionSpeed > 0 ? e.restitutionSpeed : 1;
    c.wallRestitution = e.wallRestitution;
    c.tangentialRestitution = e.tangentialRestitution;
    c.inertiaFactor = e.inertiaFactor > 0 ? e.inertiaFactor : (D == 3 ? 0.4 : 0.5);
    for (std::size_t k = 0; k < e.gravity.size() && k < 3; ++k) c.gravity[k] = e.gravity[k];
    c.growthRate = e.growthRate;
    c.cellSize = e.cellSize;

    // Kinetic-theory scales (edmd spec 4.4) at the initial state, monodisperse formulas with
    // the mean radius for polydisperse gases.
    const Real meanRadius = std::pow(meanPower(D, e.radius, e.radiusMax), 1.0 / D);
    const Real nuForTheory = std::min(s.volumeFraction, D == 2 ? 0.69 : 0.49);  // g_2a diverges past freezing
    s.tE = analysis::enskogCollisionTime(D, nuForTheory, e.temperature, e.mass, meanRadius);
    s.lambda = 1 - e.restitution * e.restitution;
    const bool dissipative = e.restitution < 1 || e.restitutionModel != "constant" || e.wallRestitution < 1;
    c.tc = e.tc >= 0 ? e.tc : (dissipative ? 1e-5 * s.tE : 0);

    // Growth needs a periodic box; shrinking must stay above zero radius.
    if (e.growthRate != 0)
        for (int k = 0; k < D; ++k)
            if (!c.periodic[k]) d.error(loc, "edmd.growth_rate", "growing spheres need a periodic box (all edmd.periodic true)");
    // Run length: exactly one of run.end_time, edmd.end_tau, edmd.end_collisions.
    const int ends = (sc.run.endTime > 0 ? 1 : 0) + (e.endTau > 0 ? 1 : 0) + (e.endCollisions > 0 ? 1 : 0);
    if (ends != 1)
        d.error(sc.run.loc, "run.end_time", fmt::format("give exactly one run length: run.end_time [s], edmd.end_tau (scaled time, "
                                                        "Eq. 4.57) or edmd.end_collisions (per particle); got {}", ends));
    if (sc.run.endTime < 0) d.error(sc.run.loc, "run.end_time", fmt::format("must be > 0 [s], got {}", sc.run.endTime));
    if (e.endTau < 0) d.error(loc, "edmd.end_tau", fmt::format("must be > 0, got {}", e.endTau));
    if (e.endCollisions < 0) d.error(loc, "edmd.end_collisions", fmt::format("must be > 0, got {}", e.endCollisions));
    if (e.endTau > 0 && !(s.lambda > 0 && e.restitutionModel == "constant"))
        d.error(loc, "edmd.end_tau", "tau = lambda t/(2 D t_E) needs a constant restitution below 1 (edmd.restitution < 1)");
    s.endTime = sc.run.endTime > 0 ? sc.run.endTime
                : e.endTau > 0 && s.lambda > 0 ? e.endTau * 2 * D * s.tE / s.lambda
                                               : std::numeric_limits<Real>::infinity();
    s.endCollisions = e.endCollisions > 0 ? static_cast<std::uint64_t>(std::llround(e.endCollisions * count / 2.0)) : 0;
    s.equilibrationCollisions = static_cast<std::uint64_t>(std::llround(e.equilibrate * count / 2.0));
    if (e.growthRate < 0 && std::isfinite(s.endTime) && !(e.radius + e.growthRate * s.endTime > 0))
        d.error(loc, "edmd.growth_rate", fmt::format("the radius {} m shrinks to zero before the end at t = {} s", e.radius, s.endTime));
    if (e.series == "log" && !std::isfinite(s.endTime))
        d.error(loc, "edmd.series", "a logarithmic series needs an end time (run.end_time or edmd.end_tau)");
    // The box must hold 3 cells of the largest diameter per periodic axis (at the end when growing).
    Real amax = std::max(e.radius, e.radiusMax);
    if (e.growthRate > 0 && std::isfinite(s.endTime)) amax += e.growthRate * s.endTime;
    for (int k = 0; k < D; ++k)
        if (c.periodic[k] && box[k] < 6 * amax)
            d.error(loc, "edmd.box", fmt::format("axis {}: the periodic edge {:.6g} m must hold 3 diameters ({:.6g} m){}", k, box[k],
                                                 6 * amax, e.growthRate > 0 ? " at the end of the growth" : ""));
    d.throwIfAny();

    // Warnings: inelastic collapse without the TC model (spec 4.3), clustering regime (4.6).
    const Real lOpt = analysis::opticalDepth(D, static_cast<Real>(count), std::min(s.volumeFraction, 0.6));
    if (lOpt > 1 && e.restitution < analysis::collapseRestitution(lOpt) && c.tc == 0)
        s.warnings.push_back(fmt::format("restitution {} is below the inelastic-collapse threshold eps_ic = {:.4f} (edmd Eq. 4.8) and "
                                         "the TC model is off (edmd.tc = 0): the run may stall in infinitely many collisions",
                                         e.restitution, analysis::collapseRestitution(lOpt)));
    return s;
}

template <int D>
edmd::GasState<D> makeEdmdState(const model::SceneDef& scene, const EdmdSetup& setup) {
    try {
        return edmd::makeInitialState<D>(setup.init);
    } catch (const std::invalid_argument& e) {
        const auto& loc = scene.edmd.loc.file.empty() ? scene.run.loc : scene.edmd.loc;
        throw SceneError(makeDiagnostic(loc.file, loc.line, scene.edmd.volumeFraction > 0 ? "edmd.volume_fraction" : "edmd.count",
                                        fmt::format("cannot place {} particles: {}", setup.init.count, e.what())));
    }
}

template edmd::GasState<2> makeEdmdState<2>(const model::SceneDef&, const EdmdSetup&);
template edmd::GasState<3> makeEdmdState<3>(const model::SceneDef&, const EdmdSetup&);

}  // namespace granulab::io
