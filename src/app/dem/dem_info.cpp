// SPDX-License-Identifier: MIT
// `granulab info` of a dem scene: integrator, particles, materials, contact laws, contact time,
// advised time step (cfddem spec section 3.5, gc2d Eq. 2.9) and a memory estimate.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/dem/dem_engine.hpp"
#include "dem/machine_setup.hpp"
#include "dem/setup.hpp"
#include "dem/step_clock.hpp"
#include "model/material_names.hpp"
#include "model/particle_store.hpp"

namespace granulab::app {

namespace {

/// True if a source, an inlet or a boundary inlet inserts particles of `material`.
bool insertedMaterial(const model::SceneDef& scene, const std::string& material) {
    const auto inserts = scene.machines.inserts();
    return std::any_of(inserts.begin(), inserts.end(),
                       [&](const auto* x) { return x->material == material; });
}

/// One line per scene machine (docs/scene-format.md "Scene machines").
void printMachines(const model::SceneDef& scene) {
    const auto& m = scene.machines;
    for (const auto& src : m.sources) {
        const auto drops = static_cast<long long>(std::floor((src.to - src.from) / src.interval)) + 1;
        fmt::print("source       '{}': {} drops of {} every {:.4g} s from {:.4g} s, {} placement\n", src.name,
                   drops, src.insert.shape, src.interval, src.from, src.placement);
    }
    for (const auto& in : m.inlets)
        fmt::print("inlet        '{}': {:.4g} particles/s from {:.4g} s\n", in.name, in.rate, in.from);
    for (const auto& b : m.boundaries)
        fmt::print("boundary     '{}': {} points, {} edges\n", b.name.empty() ? "boundary" : b.name,
                   b.points.size(), b.edges.size());
    for (const auto& o : m.outlets)
        fmt::print("outlet       '{}': {}, open from {:.4g} s\n", o.name, o.isRegion ? "region" : "edge",
                   o.openAt);
    if (m.gravity.present)
        fmt::print("gravity      {} from {:.4g} to {:.4g} m/s^2 over [{:.4g}, {:.4g}] s\n", m.gravity.type,
                   m.gravity.g1, m.gravity.g2, m.gravity.t1, m.gravity.t2);
    if (m.sizeScaling.present)
        fmt::print("size scaling amplitude {:.4g}, frequency {:.4g} 1/s, slope {:.4g}\n",
                   m.sizeScaling.amplitude, m.sizeScaling.frequency, m.sizeScaling.slope);
    for (const auto& c : m.changes) fmt::print("change       contact[{}] at {:.4g} s\n", c.contact, c.at);
}

}  // namespace

int demInfo(const std::string& scenePath, const model::SceneDef& scene) {
    const dem::PreparedScene v = checkAndPrepareDem(scene);
    const auto names = model::materialNames(scene);
    const auto& ps = v.initial.particles;
    fmt::print("scene        {}\n", scenePath);
    if (!scene.run.title.empty()) fmt::print("title        {}\n", scene.run.title);
    fmt::print("engine       {} ({}D), integrator {}, broad phase {}\n", scene.run.engine,
               scene.run.dimension, dem::integratorOf(scene), dem::broadPhaseOf(scene));
    const char* kind = scene.dem.massModel == "sphere" ? "spheres (moving in the plane)" : "disks";
    std::size_t polygons = 0;
    for (const auto& p : ps) polygons += p.shape != model::kDiskShape;
    if (polygons == 0)
        fmt::print("particles    {} {}\n", ps.size(), kind);
    else
        fmt::print("particles    {} ({} polygons, {} {}), {} shapes\n", ps.size(), polygons,
                   ps.size() - polygons, kind, v.initial.shapes.size());
    if (scene.fluid.present)
        fmt::print("fluid        rho_f = {:.6g} kg/m^3, drag {}{}; {}\n", scene.fluid.density,
                   scene.fluid.drag, scene.fluid.buoyancy ? ", buoyancy" : "", v.fieldsNote);
    for (std::size_t m = 0; m < names.size(); ++m) {
        std::size_t count = 0;
        Real rmin = 1e300, rmax = 0, mass = 0;
        for (const auto& p : ps)
            if (p.material == m) {
                ++count;
                rmin = std::min(rmin, p.radius);
                rmax = std::max(rmax, p.radius);
                mass += dem::initialMass(v.initial, p, model::massModelOf(scene.dem.massModel),
                                         scene.materials[m].density);
            }
        if (count)
            fmt::print(
                "  material {:<12} {:>9} particles, radius {:.4g}..{:.4g} m{}, density {:.4g} kg/m^{}, total "
                "mass {:.4g} kg\n",
                names[m], count, rmin, rmax, polygons ? " (polygons: circumradius)" : "",
                scene.materials[m].density, scene.dem.massModel == "sphere" ? 3 : 2, mass);
        else if (insertedMaterial(scene, names[m]))
            fmt::print("  material {:<12} (inserted by sources or inlets), density {:.4g} kg/m^{}\n",
                       names[m], scene.materials[m].density, scene.dem.massModel == "sphere" ? 3 : 2);
        else
            fmt::print("  material {:<12} (walls only)\n", names[m]);
    }
    const model::WallSet walls = dem::buildWalls(scene, names);  // walls, drums, boundaries, outlet lids
    const auto bodies =
        std::count_if(walls.walls.begin(), walls.walls.end(), [](const auto& w) { return w.body; });
    const auto moving = std::count_if(walls.walls.begin(), walls.walls.end(), [](const auto& w) {
        return w.driver.kind != model::WallDriver::Kind::Fixed;
    });
    fmt::print("walls        {} ({} segments; {} polygon bodies, {} moving)\n", walls.walls.size(),
               walls.segments.size(), bodies, moving);
    printMachines(scene);
    fmt::print("contact laws {}\n", scene.contacts.size());
    for (const auto& c : scene.contacts)
        fmt::print("  {}/{}: normal {}, damping {}, tangential {}, rolling {}\n", c.materialA, c.materialB,
                   c.normal, c.damping, c.tangential, c.rolling);
    fmt::print("time step    dt = {:.4g} s, end time {:.6g} s, {} steps\n", scene.dem.dt, scene.run.endTime,
               static_cast<long long>(dem::stepsIn(scene.run.endTime, scene.dem.dt)));
    if (v.advice.contactTime > 0) {
        fmt::print(
            "contact time {:.4g} s ({}, impact at {:.3g} m/s for nonlinear laws), {:.1f} steps per contact\n",
            v.advice.contactTime, v.advice.pair, v.impactSpeed, v.advice.contactTime / scene.dem.dt);
        fmt::print(
            "advised dt   {:.4g} s (contact time / 50, at most stability limit / 10); stability limit {:.4g} "
            "s\n",
            v.advice.advisedDt, v.advice.stabilityLimit);
    }
    if (v.advice.areaAdvisedDt > 0)
        fmt::print(
            "area law dt  {:.4g} s by the gc2d rule (pi/10) sqrt(m/E) of the {} contact, lightest particle; "
            "an upper bound: confirm with a smaller dt\n",
            v.advice.areaAdvisedDt, v.advice.areaPair);
    if (v.advice.faceAdvisedDt > 0)
        fmt::print(
            "face dt      {:.4g} s with the flat-face stiffness E L_max/(r_in/2) of {}: advised for "
            "polygons\n",
            v.advice.faceAdvisedDt, v.advice.faceParticle);
    const double perParticle = dem::bytesPerParticleEstimate(v.initial);
    fmt::print(
        "memory       ~{:.3g} MB ({:.0f} bytes per particle, estimate; summary.json reports the measured "
        "value)\n",
        perParticle * static_cast<double>(ps.size()) / 1e6, perParticle);
    for (const auto& w : v.warnings) fmt::print("warning      {}\n", w);
    return 0;
}

}  // namespace granulab::app
