// SPDX-License-Identifier: MIT
// World construction from Defs; contact-time analysis of the linear law (docs/physics).
#include "dem/setup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/parallel.hpp"
#include "core/suggest.hpp"
#include "dem/contact/registry.hpp"
#include "dem/machine_setup.hpp"
#include "model/material_names.hpp"

namespace granulab::dem {

LawTable buildLawTable(const model::SceneDef& scene, Diagnostics& diags) {
    const auto names = model::materialNames(scene);
    const auto n = static_cast<std::uint32_t>(names.size());
    LawTable table(n);
    std::vector<int> priority(static_cast<std::size_t>(n) * n, -1);  // 0 wildcard, 1 half, 2 exact
    std::vector<std::string> reported;  // a law's problems are reported once, not per material pair
    const auto merge = [&](const Diagnostics& local) {
        for (const auto& d : local.list())
            if (std::find(reported.begin(), reported.end(), d.str()) == reported.end()) {
                reported.push_back(d.str());
                diags.error(d.loc, d.key, d.message);
            }
    };
    const auto pairMaterials = [&](std::uint32_t a, std::uint32_t b) {
        const auto& ma = scene.materials[a];
        const auto& mb = scene.materials[b];
        return PairMaterials{ma.name, mb.name, ma.youngsModulus, mb.youngsModulus, ma.poisson, mb.poisson};
    };
    for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
        const auto& def = scene.contacts[c];
        const std::string ctx = fmt::format("contact[{}]", c);
        const auto matches = [&](const std::string& pattern, std::uint32_t m) {
            return pattern == "*" || pattern == names[m];
        };
        for (const auto* pattern : {&def.materialA, &def.materialB}) {
            if (*pattern == "*") continue;
            if (std::find(names.begin(), names.end(), *pattern) == names.end())
                diags.error(def.loc, ctx + ".materials",
                            fmt::format("unknown material '{}'; defined: {}", *pattern, joinList(names)));
        }
        const int prio = (def.materialA != "*") + (def.materialB != "*");
        bool anyPair = false;
        for (std::uint32_t a = 0; a < n; ++a)
            for (std::uint32_t b = 0; b < n; ++b) {
                if (!(matches(def.materialA, a) && matches(def.materialB, b))) continue;
                anyPair = true;
                auto& p = priority[static_cast<std::size_t>(a) * n + b];
                if (p == prio && prio == 2)
                    diags.error(def.loc, ctx,
                                fmt::format("second law for materials {}/{}", names[a], names[b]));
                if (prio >= p) {
                    p = prio;
                    priority[static_cast<std::size_t>(b) * n + a] = prio;
                    Diagnostics local;
                    table.set(a, b, buildContactLaw(def, ctx, local, pairMaterials(a, b)));
                    merge(local);
                }
            }
        if (!anyPair) {  // still check the law's keywords and parameters
            Diagnostics local;
            buildContactLaw(def, ctx, local, PairMaterials{"", "", 1, 1, 0, 0});
            merge(local);
        }
    }
    table.finalize();
    return table;
}

namespace {
/// Undamped angular frequency [1/s] and damping rate c/(2 meff) [1/s] of a contact, and its
/// duration [s]. Nonlinear springs are linearised at the largest overlap of an impact at `speed`.
struct Oscillator {
    Real omega0 = 0;  ///< normal spring
    Real rate = 0;
    Real omegaMax = 0;  ///< largest of normal and tangential (stability)
    Real contactTime = 0;
};

Oscillator oscillatorOf(const ContactLaw& law, Real meff, Real reff, Real speed) {
    Oscillator o;
    Real kn = 0, kTangentNormal = 0, overlapMax = 0;
    if (const auto* hooke = std::get_if<HookeNormal>(&law.normal)) {
        kn = kTangentNormal = hooke->kn;
    } else if (const auto* hertz = std::get_if<HertzNormal>(&law.normal)) {
        // Elastic Hertz impact: delta_max = (5 meff v^2 / (4 k_Hz))^(2/5), t_c = 2.9432 delta_max / v.
        const Real kHz = hertz->fourThirdsE * std::sqrt(reff);
        overlapMax = std::pow(5 * meff * speed * speed / (4 * kHz), 0.4);
        kn = hertz->stiffness(overlapMax, reff);
        kTangentNormal = 1.5 * kn;
        o.contactTime = 2.9432 * overlapMax / speed;
    }
    o.omega0 = std::sqrt(kn / meff);
    Real c = 0;
    std::visit([&](const auto& d) { c = d.coefficient(meff, kn); }, law.damping);
    o.rate = c / (2 * meff);
    if (o.contactTime == 0) {
        const Real omegaD2 = o.omega0 * o.omega0 - o.rate * o.rate;
        o.contactTime = omegaD2 > 0 ? kPi / std::sqrt(omegaD2) : kPi / o.omega0;
    }
    o.omegaMax = std::sqrt(kTangentNormal / meff);
    // The tangential spring sees the reduced mass meff/3 (disks) to meff/3.5 (spheres): translation
    // plus rolling of both bodies; use the smaller.
    Real kt = 0;
    if (const auto* cs = std::get_if<CundallStrack>(&law.tangential)) kt = cs->kt;
    if (const auto* mi = std::get_if<MindlinTangential>(&law.tangential))
        kt = mi->stiffness(overlapMax, reff);
    o.omegaMax = std::max(o.omegaMax, std::sqrt(3.5 * kt / meff));
    return o;
}
}  // namespace

TimeStepAdvice adviseTimeStep(const LawTable& laws, const std::vector<std::string>& names,
                              const std::vector<Real>& minMass, const std::vector<Real>& minRadius,
                              const std::vector<bool>& usedByWalls, Real speed) {
    TimeStepAdvice advice;
    Real worst = 0;
    const auto n = laws.materialCount();
    const auto consider = [&](std::uint32_t a, std::uint32_t b, Real meff, Real reff,
                              const std::string& label) {
        if (!laws.has(a, b) || !(meff > 0)) return;
        if (const Real* areaE = areaModulus(laws.law(a, b).normal)) {
            // gc2d Eq. 2.9: about ten steps per harmonic half period, m the lighter body. Called
            // with the reduced mass for pairs: the lighter body is at most 2 meff.
            const bool pair = label.find("wall(") == std::string::npos;
            const Real m = pair ? std::min(minMass[a], minMass[b]) : meff;
            const Real dt = kPi / 10.0 * std::sqrt(m / *areaE);
            if (advice.areaAdvisedDt == 0 || dt < advice.areaAdvisedDt) {
                advice.areaAdvisedDt = dt;
                advice.areaPair = label;
            }
            return;
        }
        const Oscillator o = oscillatorOf(laws.law(a, b), meff, reff, speed);
        if (!(o.omegaMax > worst)) return;
        worst = o.omegaMax;
        advice.contactTime = o.contactTime;
        advice.stabilityLimit = 2.0 / o.omegaMax;
        advice.advisedDt = std::min(advice.contactTime / 50.0, advice.stabilityLimit / 10.0);
        advice.pair = label;
    };
    for (std::uint32_t a = 0; a < n; ++a) {
        if (!(minMass[a] > 0)) continue;
        for (std::uint32_t b = a; b < n; ++b) {
            if (minMass[b] > 0)
                consider(a, b, minMass[a] * minMass[b] / (minMass[a] + minMass[b]),
                         minRadius[a] * minRadius[b] / (minRadius[a] + minRadius[b]),
                         names[a] + "-" + names[b]);
        }
        for (std::uint32_t b = 0; b < n; ++b)
            if (usedByWalls[b])
                consider(a, b, minMass[a], minRadius[a], names[a] + "-wall(" + names[b] + ")");
    }
    return advice;
}

void adviseFaceTimeStep(const LawTable& laws, const InitialParticles& initial,
                        const std::vector<Real>& density, TimeStepAdvice& advice) {
    const auto n = laws.materialCount();
    // Largest modulus E [N/m] any contact of material m can have, gc2d law and energy-conserving law.
    std::vector<Real> stiffest(n, 0), stiffestPotential(n, 0);
    for (std::uint32_t a = 0; a < n; ++a)
        for (std::uint32_t b = 0; b < n; ++b)
            if (laws.has(a, b)) {
                const NormalLaw& normal = laws.law(a, b).normal;
                if (const auto* area = std::get_if<AreaNormal>(&normal))
                    stiffest[a] = std::max(stiffest[a], area->E);
                if (const auto* pot = std::get_if<AreaPotentialNormal>(&normal))
                    stiffestPotential[a] = std::max(stiffestPotential[a], pot->E);
            }
    const auto& pool = initial.shapes;
    std::vector<Real> faceRatio(pool.size(), 1);       // k_face / E per shape, gc2d law
    std::vector<Real> potentialRatio(pool.size(), 1);  // k_face / E per shape, area_potential
    for (std::uint32_t k = 0; k < pool.size(); ++k) {
        Real edge = 0;  // longest edge [m]: the longest possible face contact
        const auto first = pool.start[k], count = pool.count[k];
        for (std::uint32_t c = 0; c < count; ++c)
            edge = std::max(edge, norm(pool.corners[first + (c + 1) % count] - pool.corners[first + c]));
        const Real bound = pool.circumradius[k];  // [m] the store's radius of the shape
        if (pool.inradius[k] > 0)
            faceRatio[k] = std::max<Real>(1, 2 * edge / pool.inradius[k]);  // round: the gc2d rule
        // W = E A^2/(2 l0^2): a face of length L has k = E (L / l0)^2, and l0 >= R/2 for a partner
        // at least as large (smaller partners have their own, lighter bound).
        if (bound > 0) potentialRatio[k] = std::max<Real>(1, 4 * edge * edge / (bound * bound));
    }
    for (std::size_t k = 0; k < initial.particles.size(); ++k) {
        const auto& p = initial.particles[k];
        if (p.shape == model::kDiskShape || !(pool.inradius[p.shape] > 0)) continue;
        const Real kGc2d = stiffest[p.material] * faceRatio[p.shape];
        const Real kPotential = stiffestPotential[p.material] * potentialRatio[p.shape];
        const Real kFace = std::max(kGc2d, kPotential);
        if (!(kFace > 0)) continue;
        const Real m = density[p.material] * pool.area[p.shape];
        const Real dt = kPi / 10.0 * std::sqrt(m / kFace);
        if (advice.faceAdvisedDt == 0 || dt < advice.faceAdvisedDt) {
            advice.faceAdvisedDt = dt;
            advice.faceParticle = kPotential > kGc2d
                                      ? fmt::format("particle {} (k_face = {:.3g} E, area_potential)", k,
                                                    potentialRatio[p.shape])
                                      : fmt::format("particle {} (k_face = {:.3g} E)", k, faceRatio[p.shape]);
        }
    }
}

bool hasPolygons(const model::SceneDef& scene) {
    for (const auto& p : scene.particles)
        if (p.shape != "disk") return true;
    for (const auto& b : scene.blocks)
        if (b.shape != "disk") return true;
    for (const model::InsertDef* in : scene.machines.inserts())
        if (in->shape != "disk") return true;
    for (const auto& h : scene.heaps)  // a named shape or plain rectangles (size)
        if (h.shape != "disk" || h.size.x != 0 || h.size.y != 0) return true;
    return false;
}

std::string integratorOf(const model::SceneDef& scene) {
    if (scene.dem.integrator != "auto") return scene.dem.integrator;
    return hasPolygons(scene) ? "gear" : "verlet";
}

std::string broadPhaseOf(const model::SceneDef& scene) {
    if (scene.dem.broadPhase != "auto") return scene.dem.broadPhase;
    return hasPolygons(scene) ? "sort_and_sweep" : "cell_grid";
}

WorldConfig makeWorldConfig(const model::SceneDef& scene, Real maxRadius) {
    WorldConfig c;
    c.dt = scene.dem.dt;
    c.gravity = scene.dem.gravity;
    c.skin = scene.dem.skin >= 0 ? scene.dem.skin : 0.2 * maxRadius;
    c.integrator.name = integratorOf(scene);
    c.integrator.tolerance = scene.dem.pcTolerance;
    c.integrator.maxIterations = static_cast<int>(scene.dem.pcIterations);
    c.integrator.corrector = scene.dem.pcCorrector;
    c.integrator.gearC0 = scene.dem.gearC0;
    c.broadPhase = broadPhaseOf(scene);
    c.threads = scene.run.threads > 0 ? scene.run.threads : defaultThreads();
    c.autoThreads = scene.run.threads == 0;  // the count chosen by measurement (core/thread_governor.hpp)
    c.sortEveryRebuilds = static_cast<int>(scene.dem.sortEvery);
    c.overlapGuard = scene.dem.overlapGuard ? 0.01 : 0.0;
    c.weight = scene.dem.weight;
    c.particleContacts = scene.dem.particleContacts;
    c.wallContacts = scene.dem.wallContacts;
    if (scene.attraction.present)
        c.attraction = WorldConfig::Attraction{scene.attraction.constant, scene.attraction.cutoff};
    for (const auto& w : scene.dem.damping) {
        DampingWindow d;
        d.gamma = w.gamma;
        d.gammaRotation = w.gammaRotation;
        // Window [from, to) in time -> force evaluations at steps k with from <= k dt < to.
        d.fromStep = firstStepAtOrAfter(w.from, c.dt);
        d.toStep = w.to >= 1e299 ? INT64_MAX : firstStepAtOrAfter(w.to, c.dt);
        c.damping.push_back(d);
    }
    return c;
}

FluidForceConfig fluidForceConfig(const model::FluidDef& def) {
    FluidForceConfig c;
    c.drag = fluid::makeDragLaw(def.drag, def.cw);
    c.fluid.density = def.density;
    c.fluid.viscosity = def.viscosity;
    c.buoyancy = def.buoyancy;
    c.pressureGradient = def.pressureGradient;
    c.pressureToPascal = def.pressure == "kinematic" ? def.density : 1.0;
    c.depth = def.depth;
    c.voidageCell = def.voidageCell;
    return c;
}

namespace {

/// gc2d restart (a gso's TIME t0 and PARTICLE derivatives; gc2d spec 9.4): the clock at t0 and the
/// Gear predictor's state. [[particle]]s come first in generation order, so particle j is slot j.
void restartState(const model::SceneDef& scene, World& world) {
    if (scene.run.startTime > 0) world.setStartStep(stepsIn(scene.run.startTime, scene.dem.dt));
    const bool gear = std::any_of(scene.particles.begin(), scene.particles.end(),
                                  [](const model::ParticleDef& p) { return !p.gear.empty(); });
    if (!gear) return;
    std::vector<Real> perSlot(model::ParticleDef::kGearValues * world.store().size(), 0.0);
    for (std::size_t j = 0; j < scene.particles.size(); ++j)
        std::copy(scene.particles[j].gear.begin(), scene.particles[j].gear.end(),
                  perSlot.begin() + static_cast<std::ptrdiff_t>(model::ParticleDef::kGearValues * j));
    world.restoreDerivatives(perSlot);
}

/// The gci's contacts (scene.rememberedContacts) in slots and wall indices: gc2d ids are a WALL's or
/// PARTICLE's ID, or else io/gc2d_ids.hpp's numbering (walls 0 .. W - 1, particle j W + j). The
/// spring xi = Summ_Friction / k_t with the k_t of the pair's gc2d friction law (of this scene: a
/// restart with another E keeps gc2d's stored force). Pairs of unknown ids are dropped (counted).
std::vector<RememberedContact> rememberedContacts(const model::SceneDef& scene, const LawTable& laws,
                                                  const std::vector<std::string>& names) {
    std::vector<RememberedContact> out;
    if (scene.rememberedContacts.empty()) return out;
    std::map<std::int64_t, std::pair<bool, std::uint32_t>> objects;  // id -> (wall?, index)
    const auto wallCount = static_cast<std::int64_t>(scene.walls.size());
    for (std::size_t k = 0; k < scene.walls.size(); ++k)
        objects[scene.walls[k].gc2dId >= 0 ? scene.walls[k].gc2dId : static_cast<std::int64_t>(k)] = {
            true, static_cast<std::uint32_t>(k)};
    for (std::size_t j = 0; j < scene.particles.size(); ++j)
        objects[scene.particles[j].gc2dId >= 0 ? scene.particles[j].gc2dId
                                               : wallCount + static_cast<std::int64_t>(j)] = {
            false, static_cast<std::uint32_t>(j)};
    const auto materialOf = [&](const std::string& name) {
        return static_cast<std::uint32_t>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    for (const auto& c : scene.rememberedContacts) {
        auto a = objects.find(c.id1), b = objects.find(c.id2);
        if (a == objects.end() || b == objects.end() || (a->second.first && b->second.first)) {
            RememberedContact skipped;
            skipped.unknown = true;
            out.push_back(skipped);
            continue;
        }
        if (a->second.first) std::swap(a, b);  // the particle first
        const auto& pa = scene.particles[a->second.second];
        const std::string& otherMaterial = b->second.first ? scene.walls[b->second.second].material
                                                           : scene.particles[b->second.second].material;
        const auto* friction = std::get_if<AreaFriction>(
            &laws.law(materialOf(pa.material), materialOf(otherMaterial)).tangential);
        const Real kt = friction ? friction->kt : 0;  // other laws: no gc2d spring to restore
        RememberedContact r;
        r.a = a->second.second;
        r.b = b->second.second;
        r.wall = b->second.first;
        r.xi = kt > 0 ? c.friction / kt : 0;
        r.areaOld = c.oldArea;
        out.push_back(r);
    }
    return out;
}

}  // namespace

World makeWorld(const model::SceneDef& scene, const InitialParticles& initial, fluid::FieldSource fields) {
    Diagnostics ignored;  // the scene was validated before
    LawTable laws = buildLawTable(scene, ignored);
    const auto names = model::materialNames(scene);
    std::vector<Real> density(names.size(), 0);
    for (std::size_t m = 0; m < scene.materials.size(); ++m) density[m] = scene.materials[m].density;
    const model::MassModel massModel = model::massModelOf(scene.dem.massModel);
    model::ParticleStore store;
    store.reserve(initial.particles.size());
    Real rmax = 0;
    for (std::size_t k = 0; k < initial.particles.size(); ++k) {
        const auto& p = initial.particles[k];
        const Real rho = density[p.material];
        const Real m = initialMass(initial, p, massModel, rho);
        if (p.shape == model::kDiskShape) {
            store.add(static_cast<ParticleId>(k), p.position, p.velocity, p.angle, p.omega, p.radius, m,
                      model::particleInertia(massModel, m, p.radius), p.material);
        } else {  // gc2d Eq. 2.10-2.12 with the areal density [kg/m^2]
            store.add(static_cast<ParticleId>(k), p.position, p.velocity, p.angle, p.omega, p.radius, m,
                      rho * initial.shapes.secondMoment[p.shape], p.material, p.shape);
        }
        rmax = std::max(rmax, p.radius);
    }
    model::WallSet walls = buildWalls(scene, names);
    model::ShapePool pool = initial.shapes;
    FlowConfig flow = buildFlow(scene, names, pool);
    rmax = std::max(rmax, largestInsertedRadius(scene));  // the skin must cover inserted particles too
    WorldConfig config = makeWorldConfig(scene, rmax);
    config.flow = std::move(flow);
    config.gravitySchedule = buildGravitySchedule(scene);
    config.sizeCycle = buildSizeCycle(scene);
    config.lawChanges = buildLawChanges(scene, scene.dem.dt);
    if (scene.fluid.present) {
        if (!fields.load) fields.uniformVelocity = scene.fluid.velocity;
        config.fluid = WorldConfig::Fluid{std::move(fields), fluidForceConfig(scene.fluid)};
    }
    for (const auto& def : scene.springs) {  // ids are generation indices, equal to slots at t = 0
        PullSpring sp;
        sp.id = static_cast<ParticleId>(def.particle);
        sp.slot = static_cast<std::uint32_t>(def.particle);
        sp.stiffness = def.stiffness;
        sp.attach = def.attach;
        sp.pullStart = def.pullStart;
        sp.velocity = Vec2{std::cos(def.direction), std::sin(def.direction)} * def.speed;
        sp.from = def.from;
        sp.to = def.to;
        config.springs.push_back(sp);
    }
    config.rememberedContacts = rememberedContacts(scene, laws, names);
    World world(std::move(config), std::move(store), std::move(walls), std::move(laws), std::move(pool));
    restartState(scene, world);
    return world;
}

}  // namespace granulab::dem
