// SPDX-License-Identifier: MIT
// Set-up checks of [fluid] and [attraction] that need the particles (app/dem/dem_fluid.hpp).
#include "app/dem/dem_fluid.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>

#include "fluid/drag_laws.hpp"

namespace granulab::app {

namespace {

/// Largest number of particles for which [attraction] may sum over all pairs (N^2 / 2 per force
/// evaluation); above it a cutoff is required.
constexpr std::size_t kAllPairsAttractionLimit = 5000;

/// True if p, or a point within `margin` of it, lies in the field's domain.
bool covered(const fluid::FieldInterpolator& f, Vec2 p, Real margin) {
    if (f.sample(p).inside) return true;
    if (margin <= 0) return false;
    for (int k = 0; k < 8; ++k) {
        const Real a = kPi / 4 * k;
        if (f.sample(p + Vec2{std::cos(a), std::sin(a)} * margin).inside) return true;
    }
    return false;
}

void checkCoverage(const model::SceneDef& scene, const fluid::FieldInterpolator& f,
                   const dem::PreparedScene& prepared, Diagnostics& diags) {
    const model::FluidDef& def = scene.fluid;
    const Real margin = def.checkMargin;
    const auto where = [&] {
        return fmt::format("the field {} covers x in [{:.6g}, {:.6g}], y in [{:.6g}, {:.6g}] m", f.source(),
                           f.lo().x, f.hi().x, f.lo().y, f.hi().y);
    };
    std::size_t outside = 0;
    Vec2 firstOutside;
    for (const auto& p : prepared.initial.particles)
        if (!covered(f, p.position, margin) && outside++ == 0) firstOutside = p.position;
    if (outside > 0)
        diags.error(
            def.loc, "fluid.fields",
            fmt::format(
                "{} of {} initial particles lie outside the flow field (the first at ({:.6g}, {:.6g}) m); "
                "{}. Move them, or allow a margin with fluid.check_margin [m] (outside, fluid.outside = "
                "\"{}\" applies)",
                outside, prepared.initial.particles.size(), firstOutside.x, firstOutside.y, where(),
                def.outside));
    // Inlets insert at most a radius inside their edge: check the edge's midpoint moved inwards.
    for (const auto& in : scene.machines.inlets) {
        const Vec2 d = in.b - in.a;
        const Real len = norm(d);
        if (len <= 0) continue;
        const Vec2 inward = Vec2{d.y, -d.x} / len;  // n_out = z x d points out; inward is its opposite
        const Vec2 mid = (in.a + in.b) * 0.5 + inward * (0.01 * len);
        if (!covered(f, mid, margin))
            diags.error(in.loc, "inlet",
                        fmt::format("inlet \"{}\" lies outside the flow field; {}", in.name, where()));
    }
}

/// The drag relaxes a particle's velocity to the fluid's in tau = m / (6 pi mu R) (Stokes; faster at
/// higher Re): explicit integration is unstable above dt = 2 tau and inaccurate well before. An
/// error above tau (well inside the unstable side of the accurate range), a warning above tau / 10.
void checkDragTimeStep(const model::SceneDef& scene, dem::PreparedScene& prepared, Diagnostics& diags) {
    const model::FluidDef& def = scene.fluid;
    if (!fluid::needsViscosity(fluid::makeDragLaw(def.drag, def.cw))) return;
    Real tau = 1e300, radius = 0;
    const auto consider = [&](Real r, Real rho) {
        const Real t = (4.0 / 3.0 * kPi * r * r * r * rho) / (6 * kPi * def.viscosity * r);
        if (t < tau) {
            tau = t;
            radius = r;
        }
    };
    for (const auto& p : prepared.initial.particles) consider(p.radius, scene.materials[p.material].density);
    for (const auto* ins : scene.machines.inserts()) {
        Real rho = 0;
        for (const auto& m : scene.materials)
            if (m.name == ins->material) rho = m.density;
        const auto& r = ins->radius;
        const Real rmin = r.kind == model::SizeDistDef::Kind::Constant ? r.value : r.min;
        if (rmin > 0) consider(rmin, rho);
    }
    if (tau >= 1e300) return;
    const Real dt = scene.dem.dt;
    const std::string what = fmt::format(
        "the drag relaxes the velocity of the smallest particle (R = {:.4g} m) in tau = m / (6 pi mu R) = "
        "{:.4g} s",
        radius, tau);
    if (dt > tau)
        diags.error(
            scene.dem.loc, "dem.dt",
            fmt::format("dt = {:.4g} s is above the drag's relaxation time: {}; explicit steps are unstable "
                        "above 2 tau; allowed (0, {:.4g}], advised {:.4g} s",
                        dt, what, tau, tau / 20));
    else if (dt > tau / 10)
        prepared.warnings.push_back(
            fmt::format("dem.dt = {:.4g} s is more than a tenth of the drag's relaxation time ({}); the "
                        "velocity lags the exact "
                        "solution by ~dt / (2 tau) = {:.2g} %; {:.4g} s or less is advised",
                        dt, what, 50 * dt / tau, tau / 20));
}

}  // namespace

void prepareDemFluid(const model::SceneDef& scene, io::OpenedFields fields, dem::PreparedScene& prepared,
                     Diagnostics& diags) {
    if (scene.attraction.present && scene.attraction.cutoff <= 0) {
        bool growing = !scene.machines.sources.empty() || !scene.machines.inlets.empty();
        for (const auto& b : scene.machines.boundaries)
            for (const auto& e : b.edges) growing = growing || e.type == "inlet";
        if (prepared.initial.particles.size() > kAllPairsAttractionLimit || growing)
            diags.error(
                scene.attraction.loc, "attraction.cutoff",
                fmt::format(
                    "an all-pairs attraction costs N^2/2 pair forces per step; with {} particles{} set a "
                    "cutoff [m] (pairs farther apart are skipped; summed on a cell grid)",
                    prepared.initial.particles.size(), growing ? " and particles entering" : ""));
    }
    if (!scene.fluid.present) return;
    if (fields.first) checkCoverage(scene, *fields.first, prepared, diags);
    checkDragTimeStep(scene, prepared, diags);
    if (fields.source.load)
        prepared.fieldsNote = fmt::format(
            "{} field file{} ({} times{}), {} interpolation on {} nodes", fields.files.size(),
            fields.files.size() == 1 ? "" : "s", fields.timing,
            fields.source.interpolateInTime ? ", linear in time" : "", fields.method, fields.nodes);
    else
        prepared.fieldsNote =
            fmt::format("uniform flow ({:.6g}, {:.6g}) m/s", scene.fluid.velocity.x, scene.fluid.velocity.y);
    prepared.fields = std::move(fields.source);
}

std::vector<std::string> fluidSeriesColumns(const model::SceneDef& scene) {
    if (!scene.fluid.present) return {};
    std::vector<std::string> c = {"fluid_outside", "fluid_drag_x", "fluid_drag_y", "fluid_max_reynolds",
                                  "fluid_field"};
    if (fluid::needsVoidage(fluid::makeDragLaw(scene.fluid.drag, scene.fluid.cw)))
        c.push_back("fluid_min_voidage");
    return c;
}

void appendFluidSeriesRow(const model::SceneDef& scene, const dem::World& world, std::vector<double>& row) {
    if (!scene.fluid.present) return;
    const dem::FluidStats& st = world.fluidStats();
    const fluid::FieldSeries* f = world.field();
    row.push_back(static_cast<double>(st.outside));
    row.push_back(st.drag.x);
    row.push_back(st.drag.y);
    row.push_back(st.maxReynolds);
    row.push_back(f && f->ready() ? static_cast<double>(f->currentIndex()) : 0.0);
    if (fluid::needsVoidage(world.config().fluid->forces.drag)) row.push_back(st.minVoidage);
}

namespace {
/// The flow field sampled at every particle's centre, in slot order; none without a loaded field
/// (an empty vector: a loaded field and no particle).
std::optional<std::vector<fluid::FluidSample>> flowAtCentres(const dem::World& world) {
    const fluid::FieldSeries* f = world.field();
    if (!f || !f->ready()) return std::nullopt;
    const auto& s = world.store();
    std::vector<fluid::FluidSample> out(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) out[i] = f->sample({s.x[i], s.y[i]});
    return out;
}
}  // namespace

std::vector<io::FinalExtraColumn> fluidFinalColumns(const dem::World& world) {
    const auto flow = flowAtCentres(world);
    if (!flow) return {};
    std::vector<io::FinalExtraColumn> cols = {{"fluid_ux", std::vector<Real>(flow->size())},
                                              {"fluid_uy", std::vector<Real>(flow->size())}};
    for (std::size_t i = 0; i < flow->size(); ++i) {
        cols[0].values[i] = (*flow)[i].u.x;
        cols[1].values[i] = (*flow)[i].u.y;
    }
    return cols;
}

io::FluidAtParticles fluidSnapshotArrays(const dem::World& world) {
    io::FluidAtParticles out;
    if (!world.field()) return out;
    const std::size_t n = world.store().size();
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    out.velocity.assign(2 * n, kNaN);
    out.pressure.assign(n, kNaN);
    const auto flow = flowAtCentres(world);
    if (!flow) return out;
    for (std::size_t i = 0; i < flow->size(); ++i) {
        const fluid::FluidSample& f = (*flow)[i];
        if (!f.inside) continue;
        out.velocity[2 * i] = f.u.x;
        out.velocity[2 * i + 1] = f.u.y;
        out.pressure[i] = f.p;
    }
    return out;
}

nlohmann::json fluidSummary(const model::SceneDef& scene, const dem::World& world, const std::string& note) {
    nlohmann::json js;
    if (!scene.fluid.present) return js;
    const fluid::FieldSeries* f = world.field();
    js["fields"] = f ? f->count() : 0;
    js["field_loads"] = f ? f->loads() : 0;
    js["description"] = note;
    js["interpolation"] = f && f->ready() ? f->first().methodName() : "none";
    js["drag"] = scene.fluid.drag;
    js["outside_at_end"] = world.fluidStats().outside;
    js["field_memory_bytes"] = f ? f->memoryBytes() : 0;
    return js;
}

}  // namespace granulab::app
