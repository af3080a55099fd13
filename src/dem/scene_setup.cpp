// SPDX-License-Identifier: MIT
// The dem engine's set-up from a checked scene (DESIGN.md: engines are built from Defs): the
// contact-law table, particle generation, law coverage of every material pair, start overlaps
// (gc2d spec section 2.3) and the time-step limits (cfddem spec section 3.5, gc2d Eq. 2.9).
#include "dem/scene_setup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/limits.hpp"
#include "core/suggest.hpp"
#include "dem/broad_phase.hpp"
#include "dem/integrator.hpp"
#include "dem/machine_setup.hpp"
#include "geom/overlap_tests.hpp"
#include "geom/polygon.hpp"
#include "geom/rotation.hpp"
#include "geom/segment.hpp"
#include "model/material_names.hpp"
#include "model/particle_store.hpp"
#include "model/walls.hpp"

namespace granulab::dem {

namespace {

/// World corners [m] of particle p: position + R(angle) * body corners (counter-clockwise).
std::vector<Vec2> worldCorners(const InitialParticles& init, const InitialParticle& p) {
    std::vector<Vec2> w = init.shapes.shapeCorners(p.shape);
    const auto [c, s] = geom::rotationOf(p.angle);  // as the force kernel's corners
    for (Vec2& v : w) v = p.position + Vec2{c * v.x - s * v.y, s * v.x + c * v.y};
    return w;
}

/// Start overlaps between particles, and between particles and walls (reports the first 10).
void checkStartOverlaps(const model::SceneDef& scene, const InitialParticles& init, Diagnostics& d) {
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
    CellGrid grid;
    grid.findPairs(s, 0.0, pairs);
    for (const auto key : pairs) {
        const auto i = keyFirst(key), j = keySecond(key);
        const auto& pi = init.particles[i];
        const auto& pj = init.particles[j];
        const std::string where = init.origins[pj.origin].str();
        if (!corners[i].empty() && !corners[j].empty()) {
            const Real area = geom::convexOverlap(corners[i], corners[j]).area;
            const Real smaller = std::min(init.shapes.area[pi.shape], init.shapes.area[pj.shape]);
            if (area <= 1e-9 * smaller) continue;  // touching (rounding slivers) is allowed
            report(
                init.origins[pi.origin],
                fmt::format(
                    "polygon particles {} and {} overlap at start (overlap area {:.4g} m^2, {:.3g} % of the "
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
            overlap = geom::diskPolygonOverlap(disk.position, disk.radius, corners[iDisk ? j : i]);
            scale = disk.radius;
        }
        if (overlap <= 1e-12 * scale) continue;
        report(init.origins[pi.origin],
               fmt::format("particles {} and {} overlap by {:.4g} m at start (the other is defined at {})", i,
                           j, overlap, where));
    }
    const model::WallSet walls = buildWalls(scene, model::materialNames(scene));
    grid.findWallPairs(s, walls, 0.0, pairs);
    std::uint64_t lastBodyPair = ~std::uint64_t{0};
    for (const auto key : pairs) {
        const auto i = keyFirst(key);
        const auto& seg = walls.segments[keySecond(key)];
        const auto& wall = walls.walls[seg.wall];
        const auto& p = init.particles[i];
        std::string depth;
        if (wall.body) {  // one report per particle and body: inside it, or an edge crossing it
            if (pairKey(i, seg.wall) == lastBodyPair) continue;
            const Vec2* bc = walls.corners.data() + wall.firstSegment;
            const int bn = static_cast<int>(wall.segmentCount);
            bool hit = false;
            if (corners[i].empty()) {
                const auto g = geom::diskConvexContact(p.position, p.radius, bc, bn);
                hit = g.touching && g.overlap > 1e-12 * p.radius;
            } else {
                hit = geom::diskConvexContact(p.position, 0, bc, bn).touching;  // centre inside
                for (std::uint32_t k = 0; k < wall.segmentCount && !hit; ++k) {
                    const auto& e = walls.segments[wall.firstSegment + k];
                    hit = geom::segmentEntersPolygon(e.a, e.b, corners[i]);
                }
            }
            if (!hit) continue;
            lastBodyPair = pairKey(i, seg.wall);
        } else if (corners[i].empty()) {
            const Vec2 q = seg.a + (seg.b - seg.a) * geom::closestParameter(seg.a, seg.b, p.position);
            const Real overlap = p.radius - std::sqrt(norm2(p.position - q));
            if (overlap <= 1e-12 * p.radius) continue;
            depth = fmt::format(" by {:.4g} m", overlap);
        } else if (!geom::segmentEntersPolygon(seg.a, seg.b, corners[i])) {
            continue;
        }
        report(
            init.origins[p.origin],
            fmt::format(
                "particle {} at ({:.6g}, {:.6g}) overlaps wall[{}]{} at start (the wall is defined at {}); "
                "block regions bound the particle centres, so keep them a radius away from walls",
                i, p.position.x, p.position.y, seg.wall, depth,
                seg.wall < scene.walls.size() ? scene.walls[seg.wall].loc.str() : "'" + wall.name + "'"));
    }
}

/// Particles the scene asks for, before generating any: explicit ones, blocks' counts, lattice
/// blocks' and heaps' estimates (may be inf).
double plannedParticles(const model::SceneDef& scene) {
    double n = static_cast<double>(scene.particles.size());
    for (const auto& b : scene.blocks)
        n += b.count >= 0 || b.lattice == model::BlockDef::Lattice::Random
                 ? static_cast<double>(std::max<std::int64_t>(b.count, 0))
                 : latticeSiteEstimate(b);
    for (const auto& h : scene.heaps) n += model::heapSiteEstimate(h, scene.shapes);
    return n;
}

/// The particle count and its memory fit this machine (before generation allocates anything).
void checkParticleBudget(const model::SceneDef& scene, Diagnostics& d) {
    const double n = plannedParticles(scene);
    const SourceLoc& where = !scene.blocks.empty()  ? scene.blocks.front().loc
                             : !scene.heaps.empty() ? scene.heaps.front().loc
                                                    : SourceLoc{scene.path, 0, 0};
    if (n > kMaxParticleCount) {
        d.error(where, "block",
                fmt::format("the scene asks for about {:.3g} particles; allowed at most {:.0f} (32-bit ids)",
                            n, kMaxParticleCount));
        return;
    }
    checkMemoryFits(d, where, "block", n * kDiskBytesPerParticle, fmt::format("{:.3g} particles", n));
}

/// Every particle has a positive finite mass and sits where double precision resolves its size:
/// the coordinate step at |x| must stay below 1e-8 of the radius, or contacts become round-off.
void checkParticleNumbers(const model::SceneDef& scene, const InitialParticles& init, Diagnostics& d) {
    const model::MassModel massModel = model::massModelOf(scene.dem.massModel);
    std::size_t reported = 0;
    const auto report = [&](const InitialParticle& p, const std::string& message) {
        if (reported++ < 10) d.error(init.origins[p.origin], "particle", message);
    };
    for (std::size_t k = 0; k < init.particles.size(); ++k) {
        const auto& p = init.particles[k];
        const Real rho = scene.materials[p.material].density;
        const Real m = initialMass(init, p, massModel, rho);
        if (rho > 0 && !(m > 0 && std::isfinite(m) && m * p.radius * p.radius > 0 &&
                         std::isfinite(m * p.radius * p.radius))) {
            report(p,
                   fmt::format("particle {}: mass {:.4g} kg (density {:.4g}, radius {:.4g} m) or its moment "
                               "of inertia ~ m r^2 is zero or infinite in double precision; choose a radius "
                               "and density whose mass and m r^2 are positive finite numbers",
                               k, m, rho, p.radius));
            continue;
        }
        const Real step = resolutionAt(std::max(std::abs(p.position.x), std::abs(p.position.y)));
        if (!(step <= 1e-8 * p.radius))
            report(p, fmt::format(
                          "particle {} at ({:.6g}, {:.6g}) m: double precision resolves only {:.3g} m "
                          "there, more than 1e-8 of its radius {:.4g} m; keep |x| and |y| below {:.3g} m "
                          "(move the scene towards the origin)",
                          k, p.position.x, p.position.y, step, p.radius, 4.5e7 * p.radius));
    }
    if (reported > 10)
        d.error({scene.path, 0, 0}, "particle", fmt::format("... {} more not listed", reported - 10));
}

}  // namespace

double bytesPerParticleEstimate(const InitialParticles& init) {
    double corners = 0, polygons = 0;
    for (const auto& p : init.particles)
        if (p.shape != model::kDiskShape) {
            corners += static_cast<double>(init.shapes.count[p.shape]);
            ++polygons;
        }
    if (polygons == 0) return kDiskBytesPerParticle;
    // Gear state (15 more columns), world corners, per-pair area and feature cache.
    return kDiskBytesPerParticle + 15 * 8 + 16.0 * corners / static_cast<double>(init.particles.size()) + 4 +
           3 * 18;
}

PreparedScene prepareScene(const model::SceneDef& scene, Diagnostics& diags) {
    const auto names = model::materialNames(scene);
    checkOneOf(diags, scene.dem.loc, "dem.integrator", scene.dem.integrator, integratorNames());
    checkOneOf(diags, scene.dem.loc, "dem.broad_phase", scene.dem.broadPhase, broadPhaseNames());
    PreparedScene out;
    const LawTable laws = buildLawTable(scene, diags);
    checkParticleBudget(scene, diags);
    if (!diags.empty()) diags.throwIfAny();  // never generate what cannot fit
    out.initial = generateParticles(scene, names, diags);
    if (!diags.empty()) diags.throwIfAny();  // later checks need consistent materials and sizes
    checkParticleNumbers(scene, out.initial, diags);

    const std::size_t nm = names.size();
    const model::MassModel massModel = model::massModelOf(scene.dem.massModel);
    std::vector<Real> minMass(nm, 0), minRadius(nm, 0);
    Real speed = 0, ylo = 1e300, yhi = -1e300;
    std::vector<bool> usedByWalls(nm, false);
    std::vector<bool> usedByParticles(nm, false);
    for (const auto& p : out.initial.particles) {
        const Real rho = scene.materials[p.material].density;
        const Real m = initialMass(out.initial, p, massModel, rho);
        minMass[p.material] = minMass[p.material] > 0 ? std::min(minMass[p.material], m) : m;
        minRadius[p.material] =
            minRadius[p.material] > 0 ? std::min(minRadius[p.material], p.radius) : p.radius;
        speed = std::max(speed, norm(p.velocity));
        ylo = std::min(ylo, p.position.y);
        yhi = std::max(yhi, p.position.y);
        usedByParticles[p.material] = true;
    }
    const auto materialOf = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    const auto& machines = scene.machines;
    for (const auto& w : scene.walls) usedByWalls[materialOf(w.material)] = true;
    for (const auto& d : machines.drums) usedByWalls[materialOf(d.material)] = true;
    for (const auto& b : machines.boundaries)
        if (!b.material.empty() && materialOf(b.material) < nm) usedByWalls[materialOf(b.material)] = true;
    for (const auto& o : machines.outlets)
        if (o.openAt > 0 && !o.material.empty() && materialOf(o.material) < nm)
            usedByWalls[materialOf(o.material)] = true;
    // Particles that sources and inlets insert take part in the law coverage and time-step advice.
    const std::vector<const model::InsertDef*> inserts = machines.inserts();
    for (const model::InsertDef* in : inserts) {
        const std::size_t m = materialOf(in->material);
        if (m >= nm) continue;  // reported by validation
        usedByParticles[m] = true;
        speed = std::max(speed, norm(in->velocity));
        if (in->shape != "disk") continue;
        const Real r =
            in->radius.kind == model::SizeDistDef::Kind::Constant ? in->radius.value : in->radius.min;
        if (!(r > 0)) continue;
        const Real mass = model::particleMass(massModel, scene.materials[m].density, r);
        minMass[m] = minMass[m] > 0 ? std::min(minMass[m], mass) : mass;
        minRadius[m] = minRadius[m] > 0 ? std::min(minRadius[m], r) : r;
    }
    if (out.initial.particles.empty() && inserts.empty())
        diags.error({scene.path, 0, 0}, "",
                    "the scene has no particles ([[particle]], [[block]], [[heap]], or a [[source]] or "
                    "[[inlet]] that inserts them)");
    for (std::size_t m = 0; m < nm; ++m) {
        if (usedByParticles[m] && !(scene.materials[m].density > 0))
            diags.error(scene.materials[m].loc, fmt::format("material[{}].density", m),
                        fmt::format("material '{}' is used by particles and needs density > 0 [{}], got {}",
                                    names[m], massModel == model::MassModel::Sphere ? "kg/m^3" : "kg/m^2",
                                    scene.materials[m].density));
        for (std::size_t o = 0; o < nm; ++o) {
            // Particle pairs are unordered (report m <= o once); particle-wall pairs are ordered.
            const bool occurs = usedByParticles[m] && ((usedByParticles[o] && o >= m) || usedByWalls[o]);
            if (occurs && !laws.has(static_cast<std::uint32_t>(m), static_cast<std::uint32_t>(o)))
                diags.error({scene.path, 0, 0}, "contact",
                            fmt::format("no [[contact]] law for materials {}/{} (add one, or use \"*\")",
                                        names[m], names[o]));
        }
    }
    for (std::size_t k = 0; k < scene.springs.size(); ++k) {
        const auto& sp = scene.springs[k];
        if (sp.particle < 0 || sp.particle >= static_cast<std::int64_t>(out.initial.particles.size()))
            diags.error(
                sp.loc, fmt::format("spring[{}].particle", k),
                fmt::format(
                    "particle id {} does not exist; allowed [0, {}] (generation order: [[particle]]s, "
                    "then [[block]]s, then [[heap]]s)",
                    sp.particle, static_cast<std::int64_t>(out.initial.particles.size()) - 1));
    }
    // A gc2d restart (a gso: the state of a running system, TIME t0 > 0) starts with its contacts.
    const bool restart = scene.run.startTime > 0 || !scene.rememberedContacts.empty() ||
                         std::any_of(scene.particles.begin(), scene.particles.end(),
                                     [](const model::ParticleDef& p) { return !p.gear.empty(); });
    if (!restart) checkStartOverlaps(scene, out.initial, diags);
    diags.throwIfAny();

    // Characteristic impact speed for nonlinear contacts: the fastest start velocity or a free
    // fall over the height of the packing, at least 1 cm/s.
    for (const auto& w : scene.walls) {
        speed = std::max(speed, norm(w.velocity));
        for (const auto& q : w.points) ylo = std::min(ylo, q.y);  // fall height down to the walls
    }
    if (!out.initial.particles.empty())
        speed = std::max(speed, std::sqrt(2 * norm(scene.dem.gravity) * (yhi - ylo)));
    speed = std::max(speed, 0.01);
    out.advice = adviseTimeStep(laws, names, minMass, minRadius, usedByWalls, speed);
    out.impactSpeed = speed;
    const Real dt = scene.dem.dt;
    if (out.advice.stabilityLimit > 0 && dt > out.advice.stabilityLimit)
        diags.error(scene.dem.loc, "dem.dt",
                    fmt::format("dt = {:.4g} s is above the stability limit {:.4g} s of the {} contact "
                                "(contact time {:.4g} s); "
                                "allowed (0, {:.4g}], advised {:.4g} s",
                                dt, out.advice.stabilityLimit, out.advice.pair, out.advice.contactTime,
                                out.advice.stabilityLimit, out.advice.advisedDt));
    else if (out.advice.contactTime > 0 && dt > out.advice.contactTime / 20)
        out.warnings.push_back(fmt::format(
            "dt = {:.4g} s resolves the {} contact time {:.4g} s with only {:.1f} steps; "
            "advised dt = {:.4g} s (50 steps)",
            dt, out.advice.pair, out.advice.contactTime, out.advice.contactTime / dt, out.advice.advisedDt));
    std::vector<Real> density(nm, 0);
    for (std::size_t m = 0; m < scene.materials.size(); ++m) density[m] = scene.materials[m].density;
    adviseFaceTimeStep(laws, out.initial, density, out.advice);
    if (out.advice.areaAdvisedDt > 0 && dt > out.advice.areaAdvisedDt)  // gc2d Eq. 2.9
        out.warnings.push_back(
            fmt::format("dt = {:.4g} s exceeds the gc2d rule (pi/10) sqrt(m/E) = {:.4g} s of the {} "
                        "contact (lightest particle); advised dt <= {:.4g} s",
                        dt, out.advice.areaAdvisedDt, out.advice.areaPair, out.advice.faceAdvisedDt));
    else if (out.advice.faceAdvisedDt > 0 && dt > out.advice.faceAdvisedDt)
        out.warnings.push_back(
            fmt::format("dt = {:.4g} s is within the gc2d rule but above (pi/10) sqrt(m/k_face) = {:.4g} s "
                        "for flat faces of {} "
                        "(face stiffness E L_max / (r_in / 2)); flat contacts may rattle or bounce: advised "
                        "dt <= {:.4g} s",
                        dt, out.advice.faceAdvisedDt, out.advice.faceParticle, out.advice.faceAdvisedDt));
    diags.throwIfAny();
    return out;
}

}  // namespace granulab::dem
