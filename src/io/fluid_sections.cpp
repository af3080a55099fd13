// SPDX-License-Identifier: MIT
// [fluid] and [attraction] (io/fluid_sections.hpp; cfddem spec 5.2-5.6).
#include "io/fluid_sections.hpp"

#include <algorithm>

#include "fluid/drag_laws.hpp"

namespace granulab::io {

namespace {

/// `fields`: one path or an array of paths, each remembered with its location.
void readFieldList(TableReader& r, model::FluidDef& f) {
    const toml::node* n = r.node("fields");
    if (!n) return;
    const SourceLoc loc = locOf(*n, r.file());
    if (n->is_string()) {
        f.fields.push_back(**n->as_string());
        f.fieldLocs.push_back(loc);
        return;
    }
    const toml::array* arr = n->as_array();
    if (!arr) {
        r.typeError("fields", *n, "a path or an array of paths");
        return;
    }
    for (std::size_t k = 0; k < arr->size(); ++k) {
        const toml::node& e = (*arr)[k];
        if (!e.is_string()) {
            r.typeError("fields", e, "a path (string)");
            continue;
        }
        f.fields.push_back(**e.as_string());
        const SourceLoc el = locOf(e, r.file());
        f.fieldLocs.push_back(el.line > 0 ? el : loc);
    }
}

void readFluid(TableReader& r, model::FluidDef& f) {
    f.present = true;
    f.loc = r.loc();
    readFieldList(r, f);
    r.choice("timing", f.timing, {"auto", "even", "file"});
    r.boolean("time_interpolation", f.timeInterpolation);
    r.choice("check", f.check, {"all", "first"});
    r.string("velocity_array", f.velocityArray);
    r.string("pressure_array", f.pressureArray);
    r.choice("data", f.data, {"auto", "point", "cell"});
    r.choice("interpolation", f.interpolation, {"auto", "bilinear", "shepard", "cell"});
    r.choice("outside", f.outside, {"zero", "nearest"});
    std::int64_t nodes = f.shepardNodes;
    if (r.integer("shepard_nodes", nodes))
        f.shepardNodes = static_cast<int>(std::clamp<std::int64_t>(nodes, -1, 1 << 20));
    r.number("shepard_power", f.shepardPower);
    r.vec2("velocity", f.velocity);
    r.number("density", f.density);
    r.number("viscosity", f.viscosity);
    r.choice("drag", f.drag, fluid::dragKeywords());
    r.number("cw", f.cw);
    r.boolean("buoyancy", f.buoyancy);
    r.boolean("pressure_gradient", f.pressureGradient);
    r.choice("pressure", f.pressure, {"kinematic", "static"});
    r.number("depth", f.depth);
    r.number("voidage_cell", f.voidageCell);
    r.number("check_margin", f.checkMargin);
}

void readAttraction(TableReader& r, model::AttractionDef& a) {
    a.present = true;
    a.loc = r.loc();
    r.number("constant", a.constant);
    r.number("cutoff", a.cutoff);
}

}  // namespace

void readFluidSections(TableReader& root, model::SceneDef& scene) {
    withTable(root, "fluid", [&](TableReader& t) { readFluid(t, scene.fluid); });
    withTable(root, "attraction", [&](TableReader& t) { readAttraction(t, scene.attraction); });
}

}  // namespace granulab::io
