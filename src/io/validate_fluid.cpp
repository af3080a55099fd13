// SPDX-License-Identifier: MIT
// Checks of [fluid] and [attraction] (io/validate_fluid.hpp).
#include "io/validate_fluid.hpp"

#include <fmt/format.h>

#include "fluid/drag_laws.hpp"
#include "io/range_checks.hpp"

namespace granulab::io {

namespace {

/// The first grain shape of the scene that is not a disk ("" if all are disks).
std::string firstNonDisk(const model::SceneDef& scene) {
    for (const auto& p : scene.particles)
        if (p.shape != "disk") return p.shape;
    for (const auto& b : scene.blocks)
        if (b.shape != "disk") return b.shape;
    for (const auto& h : scene.heaps)
        if (h.shape != "disk") return h.shape;
    for (const auto* ins : scene.machines.inserts())
        if (ins->shape != "disk") return ins->shape;
    return "";
}

void checkFluid(const model::SceneDef& scene, Diagnostics& d) {
    const model::FluidDef& f = scene.fluid;
    const SourceLoc& loc = f.loc;
    checkPositive(d, loc, "fluid.density", f.density, "kg/m^3");
    if (fluid::needsViscosity(fluid::makeDragLaw(f.drag, f.cw)))
        checkPositive(d, loc, "fluid.viscosity", f.viscosity, "Pa s");
    else
        checkNonNegative(d, loc, "fluid.viscosity", f.viscosity, "Pa s");
    checkPositive(d, loc, "fluid.cw", f.cw, "-");
    if (f.shepardNodes < 1 || f.shepardNodes > 64)
        d.error(loc, "fluid.shepard_nodes", fmt::format("must be in [1, 64], got {}", f.shepardNodes));
    checkPositive(d, loc, "fluid.shepard_power", f.shepardPower, "-");
    checkNonNegative(d, loc, "fluid.depth", f.depth, "m");
    checkNonNegative(d, loc, "fluid.voidage_cell", f.voidageCell, "m");
    checkNonNegative(d, loc, "fluid.check_margin", f.checkMargin, "m");
    if (!std::isfinite(f.velocity.x) || !std::isfinite(f.velocity.y))
        d.error(loc, "fluid.velocity", "must be finite [m/s]");
    if (!f.fields.empty() && (f.velocity.x != 0 || f.velocity.y != 0))
        d.error(
            loc, "fluid.velocity",
            "a uniform velocity and field files exclude each other: remove fluid.velocity or fluid.fields");
    if (f.pressureGradient && f.fields.empty())
        d.error(loc, "fluid.pressure_gradient", "needs field files with a pressure array (fluid.fields)");
    if (scene.dem.massModel != "sphere")
        d.error(loc, "fluid",
                "fluid forces act on spheres (volume 4/3 pi R^3, drag on pi R^2): set dem.mass_model = "
                "\"sphere\" "
                "(densities in kg/m^3)");
    if (const std::string shape = firstNonDisk(scene); !shape.empty())
        d.error(
            loc, "fluid",
            fmt::format("fluid forces are defined for spherical grains; shape \"{}\" is not a disk", shape));
}

void checkAttraction(const model::AttractionDef& a, Diagnostics& d) {
    checkNonNegative(d, a.loc, "attraction.constant", a.constant, "m^3/(kg s^2)");
    checkNonNegative(d, a.loc, "attraction.cutoff", a.cutoff, "m");
}

}  // namespace

void checkFluidDef(const model::SceneDef& scene, Diagnostics& diags) {
    if (scene.fluid.present) checkFluid(scene, diags);
    if (scene.attraction.present) checkAttraction(scene.attraction, diags);
}

}  // namespace granulab::io
