// SPDX-License-Identifier: MIT
// Scene validation: static checks, law table, generation, overlaps, time step.
#include "io/validate.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

#include "core/suggest.hpp"
#include "dem/broad_phase.hpp"
#include "dem/integrator.hpp"
#include "geom/polygon.hpp"
#include "geom/segment.hpp"
#include "io/shape_checks.hpp"

namespace granulab::io {

namespace {

class Checker {
public:
    explicit Checker(Diagnostics& d) : m_diags(d) {}

    void positive(const SourceLoc& loc, const std::string& key, Real v, const std::string& unit) {
        if (!(v > 0) || !std::isfinite(v))
            m_diags.error(loc, key, fmt::format("must be > 0 [{}], got {}; allowed (0, inf)", unit, v));
    }
    void nonNegative(const SourceLoc& loc, const std::string& key, Real v, const std::string& unit) {
        if (!(v >= 0) || !std::isfinite(v))
            m_diags.error(loc, key, fmt::format("must be >= 0 [{}], got {}; allowed [0, inf)", unit, v));
    }
    void material(const SourceLoc& loc, const std::string& key, const std::string& name,
                  const std::vector<std::string>& names) {
        if (name.empty()) {
            m_diags.error(loc, key, fmt::format("missing material; defined: {}", joinList(names)));
        } else if (std::find(names.begin(), names.end(), name) == names.end()) {
            m_diags.error(loc, key, fmt::format("unknown material '{}'{}; defined: {}", name, didYouMean(name, names),
                                                joinList(names)));
        }
    }
    void oneOf(const SourceLoc& loc, const std::string& key, const std::string& v, const std::vector<std::string>& allowed) {
        if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
            m_diags.error(loc, key, fmt::format("'{}' is not allowed{}; allowed: {}", v, didYouMean(v, allowed), joinList(allowed)));
    }
    Diagnostics& diags() { return m_diags; }

private:
    Diagnostics& m_diags;
};

void checkSize(Checker& c, const model::SizeDistDef& s, const SourceLoc& loc, const std::string& key) {
    using K = model::SizeDistDef::Kind;
    if (s.kind == K::Constant) {
        c.positive(loc, key, s.value, "m");
        return;
    }
    c.positive(loc, key + ".min", s.min, "m");
    if (!(s.max >= s.min))
        c.diags().error(loc, key + ".max", fmt::format("max ({}) must be >= min ({})", s.max, s.min));
    if (s.kind == K::Gaussian) {
        c.positive(loc, key + ".sigma", s.sigma, "m");
        if (!(s.mean >= s.min && s.mean <= s.max))
            c.diags().error(loc, key + ".mean", fmt::format("mean {} must lie in [min, max] = [{}, {}]", s.mean, s.min, s.max));
    }
}

void checkStatic(const model::SceneDef& sc, Checker& c, const std::vector<std::string>& names) {
    auto& d = c.diags();
    if (sc.run.engine != "dem")
        d.error(sc.run.loc, "run.engine", fmt::format("engine '{}' is not validated here (edmd scenes go through validateEdmd); allowed: dem",
                                                      sc.run.engine));
    if (sc.run.dimension != 2)
        d.error(sc.run.loc, "run.dimension", fmt::format("the dem engine is two-dimensional; allowed: 2, got {}", sc.run.dimension));
    c.positive(sc.run.loc, "run.end_time", sc.run.endTime, "s");
    c.positive(sc.dem.loc.file.empty() ? sc.run.loc : sc.dem.loc, "dem.dt", sc.dem.dt, "s");
    if (sc.dem.dt > 0 && sc.run.endTime > 0 && sc.dem.dt > sc.run.endTime)
        d.error(sc.dem.loc, "dem.dt", fmt::format("dt = {} s exceeds run.end_time = {} s", sc.dem.dt, sc.run.endTime));
    c.oneOf(sc.dem.loc, "dem.integrator", sc.dem.integrator, dem::integratorNames());
    c.positive(sc.dem.loc, "dem.pc_tolerance", sc.dem.pcTolerance, "m/s^2");
    if (sc.dem.pcIterations < 0 || sc.dem.pcIterations > 1000)
        d.error(sc.dem.loc, "dem.pc_iterations", fmt::format("must be in [0, 1000] (0: modified Euler), got {}", sc.dem.pcIterations));
    if (!(sc.dem.pcCorrector > 0 && sc.dem.pcCorrector <= 1))
        d.error(sc.dem.loc, "dem.pc_corrector", fmt::format("must be in (0, 1], got {}", sc.dem.pcCorrector));
    if (!(sc.dem.gearC0 > 0 && sc.dem.gearC0 < 1))
        d.error(sc.dem.loc, "dem.gear_c0", fmt::format("must be in (0, 1) (3/20 textbook, 3/16 velocity-dependent), got {}", sc.dem.gearC0));
    c.oneOf(sc.dem.loc, "dem.broad_phase", sc.dem.broadPhase, dem::broadPhaseNames());
    c.oneOf(sc.dem.loc, "dem.mass_model", sc.dem.massModel, {"disk", "sphere"});
    if (sc.dem.sortEvery < 0 || sc.dem.sortEvery > 1000000)
        d.error(sc.dem.loc, "dem.sort_every", fmt::format("must be in [0, 1000000] (0: never), got {}", sc.dem.sortEvery));
    if (sc.dem.skin != -1) c.nonNegative(sc.dem.loc, "dem.skin", sc.dem.skin, "m");
    for (std::size_t k = 0; k < sc.dem.damping.size(); ++k) {
        const auto& w = sc.dem.damping[k];
        const std::string key = fmt::format("dem.damping[{}]", k);
        c.nonNegative(w.loc, key + ".gamma", w.gamma, "kg/s");
        c.nonNegative(w.loc, key + ".gamma_rotation", w.gammaRotation, "kg m^2/s");
        if (!(w.to > w.from)) d.error(w.loc, key, fmt::format("window must have to > from, got [{}, {})", w.from, w.to));
    }
    for (std::size_t k = 0; k < sc.materials.size(); ++k) {
        const auto& m = sc.materials[k];
        if (m.youngsModulus != 0) c.positive(m.loc, fmt::format("material[{}].youngs_modulus", k), m.youngsModulus, "Pa");
        if (!(m.poisson >= 0 && m.poisson < 0.5))
            d.error(m.loc, fmt::format("material[{}].poisson", k), fmt::format("must be in [0, 0.5), got {}", m.poisson));
        if (m.name.empty() || m.name == "*")
            d.error(m.loc, fmt::format("material[{}].name", k),
                    fmt::format("'{}' cannot name a material (\"*\" is the wildcard of [[contact]] materials)", m.name));
        for (std::size_t j = 0; j < k; ++j)
            if (sc.materials[j].name == m.name)
                d.error(m.loc, fmt::format("material[{}].name", k), fmt::format("duplicate material name '{}'", m.name));
    }
    for (std::size_t k = 0; k < sc.particles.size(); ++k) {
        const auto& p = sc.particles[k];
        const std::string key = fmt::format("particle[{}]", k);
        c.material(p.loc, key + ".material", p.material, names);  // shape and radius: checkShapes()
    }
    for (std::size_t k = 0; k < sc.blocks.size(); ++k) {
        const auto& b = sc.blocks[k];
        const std::string key = fmt::format("block[{}]", k);
        const bool disks = b.shape == "disk";  // polygon shapes: checkShapes()
        if (!(b.xmax > b.xmin) || !(b.ymax > b.ymin))
            d.error(b.loc, key + ".region", fmt::format("region [{}, {}, {}, {}] must have xmax > xmin and ymax > ymin",
                                                        b.xmin, b.ymin, b.xmax, b.ymax));
        if (disks) checkSize(c, b.radius, b.radius.loc.file.empty() ? b.loc : b.radius.loc, key + ".radius");
        c.material(b.loc, key + ".material", b.material, names);
        c.nonNegative(b.loc, key + ".temperature", b.temperature, "J");
        if (b.lattice == model::BlockDef::Lattice::Random) {
            if (b.count <= 0) d.error(b.loc, key + ".count", fmt::format("random blocks need count > 0, got {}", b.count));
        } else {
            c.positive(b.loc, key + ".spacing", b.spacing, "m");
            const Real dmax = 2 * model::maxRadius(b.radius);
            if (disks && b.spacing > 0 && dmax > b.spacing)
                d.error(b.loc, key + ".spacing",
                        fmt::format("spacing {} m is smaller than the largest diameter {} m: neighbours would overlap", b.spacing, dmax));
            if (b.count < -1 || b.count == 0)
                d.error(b.loc, key + ".count", fmt::format("count must be > 0 (or omitted for a full lattice), got {}", b.count));
        }
    }
    for (std::size_t k = 0; k < sc.walls.size(); ++k) {
        const auto& w = sc.walls[k];
        const std::string key = fmt::format("wall[{}]", k);
        c.material(w.loc, key + ".material", w.material, names);
        if (w.points.size() < 2) {
            d.error(w.loc, key + ".points", fmt::format("a wall needs at least 2 points, got {}", w.points.size()));
            continue;
        }
        if (w.closed && w.points.size() < 3) d.error(w.loc, key + ".closed", "a closed wall needs at least 3 points");
        const std::size_t segs = w.closed ? w.points.size() : w.points.size() - 1;
        for (std::size_t s = 0; s < segs; ++s)
            if (norm2(w.points[(s + 1) % w.points.size()] - w.points[s]) <= 0)
                d.error(w.loc, key + ".points", fmt::format("points {} and {} coincide (zero-length segment)", s, (s + 1) % w.points.size()));
    }
    for (std::size_t k = 0; k < sc.springs.size(); ++k) {
        const auto& sp = sc.springs[k];
        const std::string key = fmt::format("spring[{}]", k);
        c.positive(sp.loc, key + ".k", sp.stiffness, "N/m");
        c.nonNegative(sp.loc, key + ".speed", sp.speed, "m/s");
        c.nonNegative(sp.loc, key + ".from", sp.from, "s");
        if (!(sp.to >= sp.from))
            d.error(sp.loc, key + ".to", fmt::format("to = {} s must be >= from = {} s", sp.to, sp.from));
        for (Real v : {sp.attach.x, sp.attach.y, sp.pullStart.x, sp.pullStart.y, sp.direction})
            if (!std::isfinite(v)) d.error(sp.loc, key, "attach, pull_start and direction must be finite numbers");
    }
    c.nonNegative(sc.output.loc, "output.snapshot_interval", sc.output.snapshotInterval, "s");
    c.nonNegative(sc.output.loc, "output.series_interval", sc.output.seriesInterval, "s");
    c.nonNegative(sc.output.loc, "output.checkpoint_interval", sc.output.checkpointInterval, "s");
}

/// Start overlaps between particles, and between particles and walls (reports the first 10).
void checkOverlaps(const model::SceneDef& scene, const model::InitialParticles& init, Diagnostics& d) {
    model::ParticleStore s;
    s.reserve(init.particles.size());
    for (std::size_t k = 0; k < init.particles.size(); ++k) {
        const auto& p = init.particles[k];
        s.add(static_cast<ParticleId>(k), p.position, {}, 0, 0, p.radius, 1, 1, 0);
    }
    std::size_t reported = 0;
    const auto report = [&](const SourceLoc& loc, const std::string& message) {
        if (reported == 10) d.error(loc, "particle", "... more overlaps not listed");
        if (reported++ < 10) d.error(loc, "particle", message);
    };
    // Candidates: pairs whose (circum)circles overlap; polygons are then tested exactly.
    std::vector<std::vector<Vec2>> corners(init.particles.size());
    for (std::size_t k = 0; k < init.particles.size(); ++k)
        if (init.particles[k].shape != model::kDiskShape) corners[k] = worldCorners(init, init.particles[k]);
    std::vector<std::uint64_t> pairs;
    dem::CellGrid grid;
    grid.findPairs(s, 0.0, pairs);
    for (const auto key : pairs) {
        const auto i = dem::keyFirst(key), j = dem::keySecond(key);
        const auto& pi = init.particles[i];
        const auto& pj = init.particles[j];
        const std::string where = init.origins[pj.origin].str();
        if (!corners[i].empty() && !corners[j].empty()) {
            const Real area = geom::convexOverlap(corners[i], corners[j]).area;
            const Real smaller = std::min(init.shapes.area[pi.shape], init.shapes.area[pj.shape]);
            if (area <= 1e-9 * smaller) continue;  // touching (rounding slivers) is allowed
            report(init.origins[pi.origin],
                   fmt::format("polygon particles {} and {} overlap at start (overlap area {:.4g} m^2, {:.3g} % of the "
                               "smaller; the other is defined at {})",
                               i, j, area, 100 * area / smaller, where));
            continue;
        }
        Real overlap = 0, scale = pi.radius + pj.radius;
        if (corners[i].empty() && corners[j].empty()) {
            overlap = pi.radius + pj.radius - std::sqrt(norm2(pi.position - pj.position));
        } else {
            const bool iDisk = corners[i].empty();
            const auto& disk = iDisk ? pi : pj;
            overlap = diskPolygonOverlap(disk.position, disk.radius, corners[iDisk ? j : i]);
            scale = disk.radius;
        }
        if (overlap <= 1e-12 * scale) continue;
        report(init.origins[pi.origin],
               fmt::format("particles {} and {} overlap by {:.4g} m at start (the other is defined at {})", i, j, overlap, where));
    }
    model::WallSet walls;
    for (const auto& w : scene.walls) walls.addPolyline(w.name, w.points, w.closed, 0, {});
    grid.findWallPairs(s, walls, 0.0, pairs);
    for (const auto key : pairs) {
        const auto i = dem::keyFirst(key);
        const auto& seg = walls.segments[dem::keySecond(key)];
        const auto& p = init.particles[i];
        std::string depth;
        if (corners[i].empty()) {
            const Vec2 q = seg.a + (seg.b - seg.a) * geom::closestParameter(seg.a, seg.b, p.position);
            const Real overlap = p.radius - std::sqrt(norm2(p.position - q));
            if (overlap <= 1e-12 * p.radius) continue;
            depth = fmt::format(" by {:.4g} m", overlap);
        } else if (!segmentEntersPolygon(seg.a, seg.b, corners[i])) {
            continue;
        }
        report(init.origins[p.origin],
               fmt::format("particle {} at ({:.6g}, {:.6g}) overlaps wall[{}]{} at start (the wall is defined at {}); "
                           "block regions bound the particle centres, so keep them a radius away from walls",
                           i, p.position.x, p.position.y, seg.wall, depth, scene.walls[seg.wall].loc.str()));
    }
}

}  // namespace

ValidatedScene validate(const model::SceneDef& scene) {
    Diagnostics diags;
    Checker checker(diags);
    const auto names = dem::materialNames(scene);
    checkStatic(scene, checker, names);
    ValidatedScene out;
    checkShapes(scene, diags, out.warnings);
    const dem::LawTable laws = dem::buildLawTable(scene, diags);
    out.initial = model::generateParticles(scene, names, diags);
    if (!diags.empty()) diags.throwIfAny();  // later checks need consistent materials and sizes

    const std::size_t nm = names.size();
    const model::MassModel massModel = model::massModelOf(scene.dem.massModel);
    std::vector<Real> minMass(nm, 0), minRadius(nm, 0);
    Real speed = 0, ylo = 1e300, yhi = -1e300;
    std::vector<bool> usedByWalls(nm, false);
    std::vector<bool> usedByParticles(nm, false);
    for (const auto& p : out.initial.particles) {
        const Real rho = scene.materials[p.material].density;
        const Real m = p.shape == model::kDiskShape ? model::particleMass(massModel, rho, p.radius)
                                                    : rho * out.initial.shapes.area[p.shape];  // areal density
        minMass[p.material] = minMass[p.material] > 0 ? std::min(minMass[p.material], m) : m;
        minRadius[p.material] = minRadius[p.material] > 0 ? std::min(minRadius[p.material], p.radius) : p.radius;
        speed = std::max(speed, norm(p.velocity));
        ylo = std::min(ylo, p.position.y);
        yhi = std::max(yhi, p.position.y);
        usedByParticles[p.material] = true;
    }
    for (const auto& w : scene.walls)
        usedByWalls[static_cast<std::size_t>(std::find(names.begin(), names.end(), w.material) - names.begin())] = true;
    if (out.initial.particles.empty()) diags.error({scene.path, 0, 0}, "", "the scene has no particles ([[particle]] or [[block]])");
    for (std::size_t m = 0; m < nm; ++m) {
        if (usedByParticles[m] && !(scene.materials[m].density > 0))
            diags.error(scene.materials[m].loc, fmt::format("material[{}].density", m),
                        fmt::format("material '{}' is used by particles and needs density > 0 [{}], got {}", names[m],
                                    massModel == model::MassModel::Sphere ? "kg/m^3" : "kg/m^2", scene.materials[m].density));
        for (std::size_t o = 0; o < nm; ++o) {
            // Particle pairs are unordered (report m <= o once); particle-wall pairs are ordered.
            const bool occurs = usedByParticles[m] && ((usedByParticles[o] && o >= m) || usedByWalls[o]);
            if (occurs && !laws.has(static_cast<std::uint32_t>(m), static_cast<std::uint32_t>(o)))
                diags.error({scene.path, 0, 0}, "contact",
                            fmt::format("no [[contact]] law for materials {}/{} (add one, or use \"*\")", names[m], names[o]));
        }
    }
    for (std::size_t k = 0; k < scene.springs.size(); ++k) {
        const auto& sp = scene.springs[k];
        if (sp.particle < 0 || sp.particle >= static_cast<std::int64_t>(out.initial.particles.size()))
            diags.error(sp.loc, fmt::format("spring[{}].particle", k),
                        fmt::format("particle id {} does not exist; allowed [0, {}] (generation order: [[particle]]s, "
                                    "then [[block]]s)",
                                    sp.particle, static_cast<std::int64_t>(out.initial.particles.size()) - 1));
    }
    checkOverlaps(scene, out.initial, diags);
    diags.throwIfAny();

    // Characteristic impact speed for nonlinear contacts: the fastest start velocity or a free
    // fall over the height of the packing, at least 1 cm/s.
    for (const auto& w : scene.walls) {
        speed = std::max(speed, norm(w.velocity));
        for (const auto& q : w.points) ylo = std::min(ylo, q.y);  // fall height down to the walls
    }
    if (!out.initial.particles.empty()) speed = std::max(speed, std::sqrt(2 * norm(scene.dem.gravity) * (yhi - ylo)));
    speed = std::max(speed, 0.01);
    out.advice = dem::adviseTimeStep(laws, names, minMass, minRadius, usedByWalls, speed);
    out.impactSpeed = speed;
    const Real dt = scene.dem.dt;
    if (out.advice.stabilityLimit > 0 && dt > out.advice.stabilityLimit)
        diags.error(scene.dem.loc, "dem.dt",
                    fmt::format("dt = {:.4g} s is above the stability limit {:.4g} s of the {} contact (contact time {:.4g} s); "
                                "allowed (0, {:.4g}], advised {:.4g} s",
                                dt, out.advice.stabilityLimit, out.advice.pair, out.advice.contactTime,
                                out.advice.stabilityLimit, out.advice.advisedDt));
    else if (out.advice.contactTime > 0 && dt > out.advice.contactTime / 20)
        out.warnings.push_back(fmt::format("dt = {:.4g} s resolves the {} contact time {:.4g} s with only {:.1f} steps; "
                                           "advised dt = {:.4g} s (50 steps)",
                                           dt, out.advice.pair, out.advice.contactTime, out.advice.contactTime / dt,
                                           out.advice.advisedDt));
    std::vector<Real> density(nm, 0);
    for (std::size_t m = 0; m < scene.materials.size(); ++m) density[m] = scene.materials[m].density;
    dem::adviseFaceTimeStep(laws, out.initial, density, out.advice);
    if (out.advice.areaAdvisedDt > 0 && dt > out.advice.areaAdvisedDt)  // gc2d Eq. 2.9
        out.warnings.push_back(fmt::format("dt = {:.4g} s exceeds the gc2d rule (pi/10) sqrt(m/E) = {:.4g} s of the {} "
                                           "contact (lightest particle); advised dt <= {:.4g} s",
                                           dt, out.advice.areaAdvisedDt, out.advice.areaPair, out.advice.faceAdvisedDt));
    else if (out.advice.faceAdvisedDt > 0 && dt > out.advice.faceAdvisedDt)
        out.warnings.push_back(fmt::format(
            "dt = {:.4g} s is within the gc2d rule but above (pi/10) sqrt(m/k_face) = {:.4g} s for flat faces of {} "
            "(face stiffness E L_max / (r_in / 2)); flat contacts may rattle or bounce: advised dt <= {:.4g} s",
            dt, out.advice.faceAdvisedDt, out.advice.faceParticle, out.advice.faceAdvisedDt));
    diags.throwIfAny();
    return out;
}

}  // namespace granulab::io
