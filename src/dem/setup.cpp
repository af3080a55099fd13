// SPDX-License-Identifier: MIT
// World construction from Defs; contact-time analysis of the linear law (docs/physics).
#include "dem/setup.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/suggest.hpp"
#include "dem/contact/registry.hpp"

namespace granulab::dem {

std::vector<std::string> materialNames(const model::SceneDef& scene) {
    std::vector<std::string> names;
    for (const auto& m : scene.materials) names.push_back(m.name);
    return names;
}

LawTable buildLawTable(const model::SceneDef& scene, Diagnostics& diags) {
    const auto names = materialNames(scene);
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
                    diags.error(def.loc, ctx, fmt::format("second law for materials {}/{}", names[a], names[b]));
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
    Real omega0 = 0;    ///< normal spring
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
    if (const auto* mi = std::get_if<MindlinTangential>(&law.tangential)) kt = mi->stiffness(overlapMax, reff);
    o.omegaMax = std::max(o.omegaMax, std::sqrt(3.5 * kt / meff));
    return o;
}
}  // namespace

TimeStepAdvice adviseTimeStep(const LawTable& laws, const std::vector<std::string>& names, const std::vector<Real>& minMass,
                              const std::vector<Real>& minRadius, const std::vector<bool>& usedByWalls, Real speed) {
    TimeStepAdvice advice;
    Real worst = 0;
    const auto n = laws.materialCount();
    const auto consider = [&](std::uint32_t a, std::uint32_t b, Real meff, Real reff, const std::string& label) {
        if (!laws.has(a, b) || !(meff > 0)) return;
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
                         minRadius[a] * minRadius[b] / (minRadius[a] + minRadius[b]), names[a] + "-" + names[b]);
        }
        for (std::uint32_t b = 0; b < n; ++b)
            if (usedByWalls[b]) consider(a, b, minMass[a], minRadius[a], names[a] + "-wall(" + names[b] + ")");
    }
    return advice;
}

WorldConfig makeWorldConfig(const model::SceneDef& scene, Real maxRadius) {
    WorldConfig c;
    c.dt = scene.dem.dt;
    c.gravity = scene.dem.gravity;
    c.skin = scene.dem.skin >= 0 ? scene.dem.skin : 0.2 * maxRadius;
    c.integrator.name = scene.dem.integrator;
    c.integrator.tolerance = scene.dem.pcTolerance;
    c.integrator.maxIterations = static_cast<int>(scene.dem.pcIterations);
    c.integrator.corrector = scene.dem.pcCorrector;
    c.integrator.gearC0 = scene.dem.gearC0;
    c.broadPhase = scene.dem.broadPhase;
    c.sortEveryRebuilds = static_cast<int>(scene.dem.sortEvery);
    c.overlapGuard = scene.dem.overlapGuard ? 0.01 : 0.0;
    for (const auto& w : scene.dem.damping) {
        DampingWindow d;
        d.gamma = w.gamma;
        d.gammaRotation = w.gammaRotation;
        // Window [from, to) in time -> force evaluations at steps k with from <= k dt < to.
        d.fromStep = static_cast<std::int64_t>(std::ceil(w.from / c.dt - 1e-9));
        d.toStep = w.to >= 1e299 ? INT64_MAX : static_cast<std::int64_t>(std::ceil(w.to / c.dt - 1e-9));
        c.damping.push_back(d);
    }
    return c;
}

World makeWorld(const model::SceneDef& scene, const model::InitialParticles& initial) {
    Diagnostics ignored;  // the scene was validated before
    LawTable laws = buildLawTable(scene, ignored);
    const auto names = materialNames(scene);
    std::vector<Real> density(names.size(), 0);
    for (std::size_t m = 0; m < scene.materials.size(); ++m) density[m] = scene.materials[m].density;
    const model::MassModel massModel = model::massModelOf(scene.dem.massModel);
    model::ParticleStore store;
    store.reserve(initial.particles.size());
    Real rmax = 0;
    for (std::size_t k = 0; k < initial.particles.size(); ++k) {
        const auto& p = initial.particles[k];
        const Real m = model::particleMass(massModel, density[p.material], p.radius);
        store.add(static_cast<ParticleId>(k), p.position, p.velocity, p.angle, p.omega, p.radius, m,
                  model::particleInertia(massModel, m, p.radius), p.material);
        rmax = std::max(rmax, p.radius);
    }
    model::WallSet walls;
    for (std::size_t w = 0; w < scene.walls.size(); ++w) {
        const auto& def = scene.walls[w];
        const auto it = std::find(names.begin(), names.end(), def.material);
        const auto mat = static_cast<std::uint32_t>(it - names.begin());
        walls.addPolyline(def.name.empty() ? fmt::format("wall{}", w) : def.name, def.points, def.closed, mat,
                          def.velocity);
    }
    return World(makeWorldConfig(scene, rmax), std::move(store), std::move(walls), std::move(laws));
}

}  // namespace granulab::dem
