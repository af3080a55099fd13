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
    for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
        const auto& def = scene.contacts[c];
        const std::string ctx = fmt::format("contact[{}]", c);
        const ContactLaw law = buildContactLaw(def, ctx, diags);
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
        for (std::uint32_t a = 0; a < n; ++a)
            for (std::uint32_t b = 0; b < n; ++b) {
                if (!(matches(def.materialA, a) && matches(def.materialB, b))) continue;
                auto& p = priority[static_cast<std::size_t>(a) * n + b];
                if (p == prio && prio == 2)
                    diags.error(def.loc, ctx, fmt::format("second law for materials {}/{}", names[a], names[b]));
                if (prio >= p) {
                    p = prio;
                    priority[static_cast<std::size_t>(b) * n + a] = prio;
                    table.set(a, b, law);
                }
            }
    }
    table.finalize();
    return table;
}

namespace {
/// Undamped angular frequency [1/s] and damping rate c/(2 meff) [1/s] of a contact.
struct Oscillator {
    Real omega0 = 0;  ///< normal spring
    Real rate = 0;
    Real omegaMax = 0;  ///< largest of normal and tangential (stability)
};

Oscillator oscillatorOf(const ContactLaw& law, Real meff) {
    Oscillator o;
    Real kn = 0;
    std::visit([&](const auto& normal) { kn = normal.stiffness(0); }, law.normal);
    o.omega0 = std::sqrt(kn / meff);
    Real c = 0;
    std::visit([&](const auto& d) { c = d.coefficient(meff, kn); }, law.damping);
    o.rate = c / (2 * meff);
    // A disk's tangential spring sees the reduced mass meff/3 (translation + rolling).
    o.omegaMax = o.omega0;
    if (const auto* cs = std::get_if<CundallStrack>(&law.tangential))
        o.omegaMax = std::max(o.omega0, std::sqrt(3 * cs->kt / meff));
    return o;
}
}  // namespace

TimeStepAdvice adviseTimeStep(const LawTable& laws, const std::vector<std::string>& names,
                              const std::vector<Real>& minMass, const std::vector<bool>& usedByWalls) {
    TimeStepAdvice advice;
    Real worst = 0;
    const auto n = laws.materialCount();
    const auto consider = [&](std::uint32_t a, std::uint32_t b, Real meff, const std::string& label) {
        if (!laws.has(a, b) || !(meff > 0)) return;
        const Oscillator o = oscillatorOf(laws.law(a, b), meff);
        if (o.omegaMax <= worst) return;
        worst = o.omegaMax;
        const Real omegaD2 = o.omega0 * o.omega0 - o.rate * o.rate;
        advice.contactTime = omegaD2 > 0 ? kPi / std::sqrt(omegaD2) : kPi / o.omega0;
        advice.stabilityLimit = 2.0 / o.omegaMax;
        advice.advisedDt = advice.contactTime / 50.0;
        advice.pair = label;
    };
    for (std::uint32_t a = 0; a < n; ++a) {
        if (!(minMass[a] > 0)) continue;
        for (std::uint32_t b = a; b < n; ++b) {
            if (minMass[b] > 0)
                consider(a, b, minMass[a] * minMass[b] / (minMass[a] + minMass[b]), names[a] + "-" + names[b]);
        }
        for (std::uint32_t b = 0; b < n; ++b)
            if (usedByWalls[b]) consider(a, b, minMass[a], names[a] + "-wall(" + names[b] + ")");
    }
    return advice;
}

WorldConfig makeWorldConfig(const model::SceneDef& scene, Real maxRadius) {
    WorldConfig c;
    c.dt = scene.dem.dt;
    c.gravity = scene.dem.gravity;
    c.skin = scene.dem.skin >= 0 ? scene.dem.skin : 0.2 * maxRadius;
    c.integrator = scene.dem.integrator;
    c.broadPhase = scene.dem.broadPhase;
    c.sortEveryRebuilds = static_cast<int>(scene.dem.sortEvery);
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
    model::ParticleStore store;
    store.reserve(initial.particles.size());
    Real rmax = 0;
    for (std::size_t k = 0; k < initial.particles.size(); ++k) {
        const auto& p = initial.particles[k];
        const Real m = model::diskMass(density[p.material], p.radius);
        store.add(static_cast<ParticleId>(k), p.position, p.velocity, p.angle, p.omega, p.radius, m,
                  model::diskInertia(m, p.radius), p.material);
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
