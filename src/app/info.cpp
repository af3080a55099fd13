// SPDX-License-Identifier: MIT
// Scene information and help texts.
#include "app/info.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "app/scene_input.hpp"
#include "dem/contact/hertz_restitution.hpp"
#include "dem/contact/registry.hpp"
#include "dem/setup.hpp"
#include "analysis/kinetic_theory.hpp"
#include "io/validate.hpp"
#include "io/validate_edmd.hpp"
#include "model/particle_store.hpp"

namespace granulab::app {

namespace {

/// `granulab info` for an event-driven gas: the resolved setup and the kinetic-theory scales
/// and thresholds of edmd spec 4.3-4.6.
int infoEdmd(const std::string& scenePath, const model::SceneDef& scene) {
    const io::EdmdSetup s = io::validateEdmd(scene);
    const auto& e = scene.edmd;
    const int D = s.dim;
    fmt::print("scene        {}\n", scenePath);
    if (!scene.run.title.empty()) fmt::print("title        {}\n", scene.run.title);
    fmt::print("engine       edmd ({}D event-driven hard {}), queue {}\n", D, D == 2 ? "disks" : "spheres", e.queue);
    fmt::print("particles    {}  radius {} m{}, mass {} kg, placement {}\n", s.init.count, e.radius,
               e.radiusMax > e.radius ? fmt::format(" .. {} m", e.radiusMax) : std::string(), e.mass, e.placement);
    fmt::print("box          {}  ({}), volume fraction {:.5f}\n",
               D == 2 ? fmt::format("{:.6g} x {:.6g} m", s.config.box[0], s.config.box[1])
                      : fmt::format("{:.6g} x {:.6g} x {:.6g} m", s.config.box[0], s.config.box[1], s.config.box[2]),
               e.periodic.empty() ? "periodic" : "per-axis boundaries as given", s.volumeFraction);
    fmt::print("collisions   eps {} ({}), walls {}, phi {}, TC t_c = {:.4g} s\n", e.restitution, e.restitutionModel,
               e.wallRestitution, e.tangentialRestitution, s.config.tc);
    fmt::print("start        T0 = {} J, elastic pre-run of {} collisions per particle\n", e.temperature, e.equilibrate);
    fmt::print("kinetics     t_E = {:.6g} s (Enskog, Eq. 4.33), end t = {:.6g} s{}\n", s.tE, s.endTime,
               s.lambda > 0 && std::isfinite(s.endTime) ? fmt::format(" = tau {:.4g}", s.lambda * s.endTime / (2 * D * s.tE))
                                                       : std::string());
    const Real nu = std::min(s.volumeFraction, D == 2 ? 0.69 : 0.49);
    const Real lOpt = analysis::opticalDepth(D, static_cast<Real>(s.init.count), nu);
    fmt::print("thresholds   g_2a {:.4f}, l_opt {:.4g}, lambda {:.4g}, lambda_cl {:.4g} (clusters above), lambda_sh {:.4g}, "
               "eps_ic {:.4f}\n",
               analysis::contactValue(D, nu), lOpt, s.lambda, analysis::clusteringLambda(D, lOpt), analysis::shearLambda(D, lOpt),
               analysis::collapseRestitution(lOpt));
    for (const auto& w : s.warnings) fmt::print("warning      {}\n", w);
    return 0;
}

}  // namespace

int infoCommand(const std::string& scenePath, const std::vector<io::Override>& overrides) {
    const model::SceneDef scene = app::readScene(scenePath, overrides);
    if (scene.run.engine == "edmd") return infoEdmd(scenePath, scene);
    const io::ValidatedScene v = io::validate(scene);
    const auto names = dem::materialNames(scene);
    const auto& ps = v.initial.particles;
    fmt::print("scene        {}\n", scenePath);
    if (!scene.run.title.empty()) fmt::print("title        {}\n", scene.run.title);
    fmt::print("engine       {} ({}D), integrator {}, broad phase {}\n", scene.run.engine, scene.run.dimension,
               dem::integratorOf(scene), dem::broadPhaseOf(scene));
    const char* kind = scene.dem.massModel == "sphere" ? "spheres (moving in the plane)" : "disks";
    std::size_t polygons = 0;
    for (const auto& p : ps) polygons += p.shape != model::kDiskShape;
    if (polygons == 0)
        fmt::print("particles    {} {}\n", ps.size(), kind);
    else
        fmt::print("particles    {} ({} polygons, {} {}), {} shapes\n", ps.size(), polygons, ps.size() - polygons, kind,
                   v.initial.shapes.size());
    for (std::size_t m = 0; m < names.size(); ++m) {
        std::size_t count = 0;
        Real rmin = 1e300, rmax = 0, mass = 0;
        for (const auto& p : ps)
            if (p.material == m) {
                ++count;
                rmin = std::min(rmin, p.radius);
                rmax = std::max(rmax, p.radius);
                mass += p.shape == model::kDiskShape
                            ? model::particleMass(model::massModelOf(scene.dem.massModel), scene.materials[m].density, p.radius)
                            : scene.materials[m].density * v.initial.shapes.area[p.shape];
            }
        if (count)
            fmt::print("  material {:<12} {:>9} particles, radius {:.4g}..{:.4g} m{}, density {:.4g} kg/m^{}, total mass {:.4g} kg\n",
                       names[m], count, rmin, rmax, polygons ? " (polygons: circumradius)" : "", scene.materials[m].density,
                       scene.dem.massModel == "sphere" ? 3 : 2, mass);
        else
            fmt::print("  material {:<12} (walls only)\n", names[m]);
    }
    std::size_t segments = 0;
    for (const auto& w : scene.walls) segments += w.closed ? w.points.size() : w.points.size() - 1;
    fmt::print("walls        {} ({} segments)\n", scene.walls.size(), segments);
    fmt::print("contact laws {}\n", scene.contacts.size());
    for (const auto& c : scene.contacts)
        fmt::print("  {}/{}: normal {}, damping {}, tangential {}, rolling {}\n", c.materialA, c.materialB, c.normal,
                   c.damping, c.tangential, c.rolling);
    fmt::print("time step    dt = {:.4g} s, end time {:.6g} s, {} steps\n", scene.dem.dt, scene.run.endTime,
               static_cast<long long>(scene.run.endTime / scene.dem.dt + 0.5));
    if (v.advice.contactTime > 0) {
        fmt::print("contact time {:.4g} s ({}, impact at {:.3g} m/s for nonlinear laws), {:.1f} steps per contact\n",
                   v.advice.contactTime, v.advice.pair, v.impactSpeed, v.advice.contactTime / scene.dem.dt);
        fmt::print("advised dt   {:.4g} s (contact time / 50, at most stability limit / 10); stability limit {:.4g} s\n",
                   v.advice.advisedDt, v.advice.stabilityLimit);
    }
    if (v.advice.areaAdvisedDt > 0)
        fmt::print("area law dt  {:.4g} s by the gc2d rule (pi/10) sqrt(m/E) of the {} contact, lightest particle; "
                   "an upper bound: confirm with a smaller dt\n",
                   v.advice.areaAdvisedDt, v.advice.areaPair);
    if (v.advice.faceAdvisedDt > 0)
        fmt::print("face dt      {:.4g} s with the flat-face stiffness E L_max/(r_in/2) of {}: advised for polygons\n",
                   v.advice.faceAdvisedDt, v.advice.faceParticle);
    // Estimate: particle store + Verlet half-step velocities (24 B) + neighbour-list reference
    // positions (16 B) + cell grid (12 B) + ~3 candidate pairs per disk (16 B each, history included).
    double perParticle = static_cast<double>(model::ParticleStore::kBytesPerParticle) + 24 + 16 + 12 + 3 * 16;
    if (polygons) {  // Gear state (15 more columns), world corners, per-pair area and feature cache
        std::size_t corners = 0;
        for (const auto& p : ps)
            if (p.shape != model::kDiskShape) corners += v.initial.shapes.count[p.shape];
        perParticle += 15 * 8 + 16.0 * static_cast<double>(corners) / static_cast<double>(ps.size()) + 4 + 3 * 18;
    }
    fmt::print("memory       ~{:.3g} MB ({:.0f} bytes per particle, estimate; summary.json reports the measured value)\n",
               perParticle * static_cast<double>(ps.size()) / 1e6, perParticle);
    for (const auto& w : v.warnings) fmt::print("warning      {}\n", w);
    return 0;
}

std::string helpText(const std::string& topic) {
    if (topic == "restitution") {  // the e <-> D helper of spec/cfddem.md section 3.5
        std::string s =
            "Restitution coefficient e versus damping ratio D (damping = \"lehr\", D_n = D):\n"
            "  linear spring: e = exp(-pi D / sqrt(1 - D^2)) (Eq. 3.78, exact without clipping)\n"
            "  Hertz spring:  e(D) of the Hertz-Lehr collision, computed (depends on D only)\n\n"
            "     D    e linear   e Hertz   e Hertz clipped\n";
        for (const Real d : {0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}) {
            const Real lin = d < 1 ? std::exp(-kPi * d / std::sqrt(1 - d * d)) : 0.0;
            s += fmt::format("  {:4.2f}   {:8.4f}  {:8.4f}  {:8.4f}\n", d, lin, dem::hertzRestitution(d),
                             dem::hertzRestitution(d, true));
        }
        s += "\ndamping = \"restitution\" with e = ... uses the inverse of the matching column.\n";
        return s;
    }
    if (topic == "laws") {
        std::string s = "Contact laws ([[contact]] keys normal, damping, tangential and their parameters):\n";
        for (const auto& e : dem::lawRegistry()) {
            s += fmt::format("\n  {} = \"{}\": {}\n", dem::axisKey(e.axis), e.keyword, e.doc);
            for (const auto& p : e.params)
                s += fmt::format("      {:<10} [{}] {}; allowed {}; default {}\n", p.key, p.unit, p.doc, p.rangeText(),
                                 p.defaultText);
        }
        s += "\n  any law:\n";
        for (const auto& p : dem::commonLawParams())
            s += fmt::format("      {:<16} {}; default {}\n", p.key, p.doc, p.defaultText);
        return s;
    }
    return R"(granulab - granular matter simulation

usage:
  granulab run SCENE [--out DIR] [--set key=value]... [--resume DIR] [--quiet]
      simulate; writes summary.json, series.csv, final.csv, VTK snapshots (snapshots.pvd)
      and checkpoint.bin into DIR (default out/<scene name>)
  granulab info SCENE [--set key=value]...
      particles, materials, contact time, advised time step, memory estimate
  granulab render DIR --png [--width PIXELS]
      one PNG per snapshot of a finished or running simulation, into DIR/png/
  granulab help [laws | restitution]
      this text, the table of contact laws and their parameters, or the e <-> D table
  granulab --version

exit status: 0 success, 2 bad input (scene errors are listed with file:line),
             3 run stopped because it became numerically unstable, 1 other failure.
docs: docs/getting-started.md, docs/scene-format.md, docs/physics/contact-laws.md
)";
}

}  // namespace granulab::app
