// SPDX-License-Identifier: MIT
// The dem engine's sections (io/dem_sections.hpp; docs/scene-format.md "[dem]" to "[[spring]]",
// gc2d spec sections 2.3, 3.8 and 6.5). Syntax, type and unknown-key errors only; io/validate.hpp checks
// ranges.
#include "io/dem_sections.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/suggest.hpp"
#include "io/dem_machine_sections.hpp"
#include "io/fluid_sections.hpp"
#include "io/toml_table_reader.hpp"

namespace granulab::io {

namespace {

void readDem(TableReader& r, model::DemDef& dem) {
    dem.loc = r.loc();
    if (!r.number("dt", dem.dt) && !r.table().get("dt"))
        r.diags().error(dem.loc, "dem.dt",
                        "missing: time step [s], allowed (0, inf); `granulab info` advises one");
    r.string("integrator", dem.integrator);
    r.number("pc_tolerance", dem.pcTolerance);
    r.integer("pc_iterations", dem.pcIterations);
    r.number("pc_corrector", dem.pcCorrector);
    r.number("gear_c0", dem.gearC0);
    r.string("broad_phase", dem.broadPhase);
    r.number("skin", dem.skin);
    r.choice("mass_model", dem.massModel, {"disk", "sphere"});
    r.integer("sort_every", dem.sortEvery);
    r.boolean("overlap_guard", dem.overlapGuard);
    r.vec2("gravity", dem.gravity);
    r.boolean("weight", dem.weight);
    r.boolean("particle_contacts", dem.particleContacts);
    r.boolean("wall_contacts", dem.wallContacts);
    forEachTable(r, "damping", [&](TableReader& d, std::size_t) {
        model::DampingWindowDef w;
        w.loc = d.loc();
        d.number("gamma", w.gamma);
        d.number("gamma_rotation", w.gammaRotation);
        d.number("from", w.from);
        d.number("to", w.to);
        dem.damping.push_back(w);
    });
}

}  // namespace

void readSize(TableReader& parent, const std::string& key, model::SizeDistDef& size) {
    const toml::node* n = parent.node(key);
    if (!n) return;
    size.loc = locOf(*n, parent.file());
    if (n->is_number()) {
        size.kind = model::SizeDistDef::Kind::Constant;
        parent.number(key, size.value);
        return;
    }
    const toml::table* t = n->as_table();
    if (!t) {
        parent.typeError(key, *n, "a number or a table { distribution = ..., ... }");
        return;
    }
    TableReader r(*t, parent.keyPath(key), parent.file(), parent.diags());
    std::string dist = "constant";
    r.choice("distribution", dist, {"constant", "uniform", "gaussian"});
    if (dist == "constant") {
        size.kind = model::SizeDistDef::Kind::Constant;
        r.number("value", size.value);
    } else if (dist == "uniform") {
        size.kind = model::SizeDistDef::Kind::Uniform;
        r.number("min", size.min);
        r.number("max", size.max);
    } else {
        size.kind = model::SizeDistDef::Kind::Gaussian;
        r.number("mean", size.mean);
        r.number("sigma", size.sigma);
        r.number("min", size.min);
        r.number("max", size.max);
    }
    r.finish();
}

namespace {

void readContact(TableReader& r, model::ContactDef& c) {
    c.loc = r.loc();
    const toml::node* n = r.node("materials");
    if (!n) {
        r.diags().error(c.loc, r.keyPath("materials"),
                        "missing: the two material names, e.g. [\"grain\", \"wall\"] (\"*\" matches any)");
    } else {
        const toml::array* a = n->as_array();
        if (!a || a->size() != 2 || !(*a)[0].is_string() || !(*a)[1].is_string()) {
            r.typeError("materials", *n, "an array of two material names");
        } else {
            c.materialA = (*a)[0].value<std::string>().value_or("");
            c.materialB = (*a)[1].value<std::string>().value_or("");
        }
    }
    r.string("normal", c.normal);
    r.string("damping", c.damping);
    r.string("tangential", c.tangential);
    r.string("rolling", c.rolling);
    // Every other key is a law parameter, checked against the law registry by validate().
    for (auto&& [k, v] : r.table()) {
        const std::string key(k.str());
        if (key == "materials" || key == "normal" || key == "damping" || key == "tangential" ||
            key == "rolling")
            continue;
        r.node(key);
        model::LawParamDef p;
        p.loc = locOf(v, r.file());
        if (v.is_boolean()) {
            p.value = v.value<bool>().value_or(false) ? 1.0 : 0.0;
            p.isBool = true;
        } else if (v.is_number()) {
            if (!r.number(key, p.value)) continue;  // finite, exact (reported there)
        } else {
            r.typeError(key, v, "a number or a boolean");
            continue;
        }
        c.params[key] = p;
    }
}

/// Keys of a [[shape]] besides name, kind, rotation_mode and rotation, by kind (gc2d spec
/// section 2.3; docs/scene-format.md "Shapes").
const std::vector<std::string>& shapeKeysOf(const std::string& kind) {
    static const std::map<std::string, std::vector<std::string>> keys = {
        {"polygon", {"corners"}},
        {"regular", {"corner_count", "radius"}},
        {"rectangle", {"size", "chamfer"}},
        {"ellipse", {"size", "corner_count"}},
        {"grain",
         {"size", "full_axes", "size_mode", "size_variation", "corner_count", "corner_count_mode",
          "corner_variation", "corner_angles"}},
        {"",
         {"corners", "corner_count", "radius", "size", "chamfer", "full_axes", "size_mode", "size_variation",
          "corner_count_mode", "corner_variation", "corner_angles"}},
    };
    const auto it = keys.find(kind);
    return it != keys.end() ? it->second : keys.at("");
}

void readShape(TableReader& r, model::ShapeDef& s) {
    s.loc = r.loc();
    if (!r.string("name", s.name) && !r.table().get("name"))
        r.diags().error(s.loc, r.keyPath("name"),
                        "missing: shape name, used by `shape = \"name\"` in [[particle]] and [[block]]");
    static const std::vector<std::string> kinds = {"polygon", "regular", "rectangle", "ellipse", "grain"};
    const bool kindOk = r.choice("kind", s.kind, kinds);
    if (!r.table().get("kind"))
        r.diags().error(s.loc, r.keyPath("kind"),
                        fmt::format("missing: shape kind, allowed: {}", joinList(kinds)));
    const auto& allowed = shapeKeysOf(kindOk ? s.kind : "");
    const auto has = [&](const std::string& key) {
        return std::find(allowed.begin(), allowed.end(), key) != allowed.end();
    };
    for (const auto& key : shapeKeysOf("")) {
        const toml::node* n = r.table().get(key);
        if (has(key) || !n) continue;
        std::vector<std::string> own = {"name", "kind"};
        own.insert(own.end(), allowed.begin(), allowed.end());
        own.insert(own.end(), {"rotation_mode", "rotation"});
        r.diags().error(locOf(*n, r.file()), r.keyPath(key),
                        fmt::format("does not apply to a shape of kind '{}'; keys of {} shapes: {}", s.kind,
                                    s.kind, joinList(own)));
        r.ignore(key);
    }
    const auto require = [&](const std::string& key, const std::string& what) {
        if (kindOk && !r.table().get(key))
            r.diags().error(s.loc, r.keyPath(key),
                            fmt::format("missing: {} (required for kind '{}')", what, s.kind));
    };
    if (has("corners")) {
        r.points("corners", s.corners);
        require("corners", "[[x0, y0], [x1, y1], ...] in m, counter-clockwise, convex");
    }
    if (has("corner_angles")) r.string("corner_angles", s.cornerAngles);
    if (has("corner_count")) {
        r.integer("corner_count", s.cornerCount);
        if (s.kind != "grain" || s.cornerAngles != "special_rectangle")
            require("corner_count", "number of corners, >= 3");
    }
    if (has("radius")) {
        r.number("radius", s.radius);
        require("radius", "circumscribed radius in m, allowed (0, inf)");
    }
    if (has("size")) {
        r.vec2("size", s.size);
        require("size",
                s.kind == "rectangle" ? "[a, b], the edge lengths in m" : "[a, b], the semi-axes in m");
    }
    if (has("chamfer")) r.number("chamfer", s.chamfer);
    if (has("full_axes")) r.boolean("full_axes", s.fullAxes);
    if (has("size_mode")) r.string("size_mode", s.sizeMode);
    if (has("size_variation")) r.number("size_variation", s.sizeVariation);
    if (has("corner_count_mode")) r.string("corner_count_mode", s.cornerCountMode);
    if (has("corner_variation")) r.integer("corner_variation", s.cornerVariation);
    r.string("rotation_mode", s.rotationMode);
    r.number("rotation", s.rotation);
}

/// Whether `name` is a [[shape]] (a polygon shape) rather than "disk" or an unknown name.
bool isShapeName(const std::vector<model::ShapeDef>& shapes, const std::string& name) {
    return std::any_of(shapes.begin(), shapes.end(),
                       [&](const model::ShapeDef& s) { return s.name == name; });
}

/// Reads `radius` for disks (required) and unknown shape names (optional; the name is reported
/// by validate()); for a [[shape]] a radius is an error. Returns false if the radius is not read.
bool radiusForShape(TableReader& r, const std::string& shape, const std::vector<model::ShapeDef>& shapes) {
    const toml::node* n = r.table().get("radius");
    if (shape == "disk" || !isShapeName(shapes, shape)) return true;
    if (n) {
        r.diags().error(
            locOf(*n, r.file()), r.keyPath("radius"),
            fmt::format("radius belongs to disks; the size of shape '{}' comes from its [[shape]]", shape));
        r.ignore("radius");
    }
    return false;
}

void readParticle(TableReader& r, model::ParticleDef& p, const std::vector<model::ShapeDef>& shapes) {
    p.loc = r.loc();
    r.string("shape", p.shape);
    if (!r.vec2("position", p.position) && !r.table().get("position"))
        r.diags().error(p.loc, r.keyPath("position"), "missing: [x, y] in m");
    r.vec2("velocity", p.velocity);
    r.number("angle", p.angle);
    r.number("omega", p.omega);
    const bool readRadius = radiusForShape(r, p.shape, shapes);
    if (readRadius && !r.number("radius", p.radius) && !r.table().get("radius") && p.shape == "disk")
        r.diags().error(p.loc, r.keyPath("radius"), "missing: radius in m, allowed (0, inf)");
    r.string("material", p.material);
}

/// The gc2d GENERATE_BLOCK keys of a [[block]] (spec section 6.5): rect/fcc grid, jitter,
/// velocity ranges.
void readBlockGc2d(TableReader& r, model::BlockDef& b) {
    r.vec2("grid", b.grid);
    std::string jitter = "none";
    r.choice("jitter", jitter, {"none", "gauss", "equal"});
    b.jitter = jitter == "gauss"   ? model::BlockDef::Jitter::Gauss
               : jitter == "equal" ? model::BlockDef::Jitter::Equal
                                   : model::BlockDef::Jitter::None;
    r.number("jitter_fraction", b.jitterFraction);
    r.vec2("direction_range", b.directionRange);
    r.vec2("speed_range", b.speedRange);
}

void readBlock(TableReader& r, model::BlockDef& b, const std::vector<model::ShapeDef>& shapes) {
    b.loc = r.loc();
    std::string lattice = "hexagonal";
    r.choice("lattice", lattice, {"hexagonal", "square", "random", "rect", "fcc"});
    b.lattice = lattice == "hexagonal" ? model::BlockDef::Lattice::Hexagonal
                : lattice == "square"  ? model::BlockDef::Lattice::Square
                : lattice == "rect"    ? model::BlockDef::Lattice::Rect
                : lattice == "fcc"     ? model::BlockDef::Lattice::Fcc
                                       : model::BlockDef::Lattice::Random;
    r.string("shape", b.shape);
    std::vector<Real> region;
    if (r.numbers("region", region, 4)) {
        b.xmin = region[0];
        b.ymin = region[1];
        b.xmax = region[2];
        b.ymax = region[3];
    } else if (!r.table().get("region")) {
        r.diags().error(b.loc, r.keyPath("region"), "missing: [xmin, ymin, xmax, ymax] in m");
    }
    r.number("spacing", b.spacing);
    Vec2 origin;
    if (r.vec2("origin", origin)) b.origin = origin;
    r.integer("count", b.count);
    if (radiusForShape(r, b.shape, shapes)) {
        readSize(r, "radius", b.radius);
        if (!r.table().get("radius") && b.shape == "disk")
            r.diags().error(b.loc, r.keyPath("radius"), "missing: radius in m or a distribution table");
    }
    r.string("material", b.material);
    r.vec2("velocity", b.velocity);
    r.number("temperature", b.temperature);
    readBlockGc2d(r, b);
}

/// [[heap]]: a regular pile of gc2d's heap.pm (spec section 6.5).
void readHeap(TableReader& r, model::HeapDef& h) {
    h.loc = r.loc();
    std::string stacking = "hexagonal";
    r.choice("stacking", stacking, {"hexagonal", "rectangular"});
    h.stacking =
        stacking == "hexagonal" ? model::HeapDef::Stacking::Hexagonal : model::HeapDef::Stacking::Rectangular;
    Vec2 range;
    if (r.vec2("x_range", range)) {
        h.xLeft = range.x;
        h.xRight = range.y;
    } else if (!r.table().get("x_range")) {
        r.diags().error(h.loc, r.keyPath("x_range"), "missing: [x_left, x_right] in m, the ends of the pile");
    }
    r.number("base", h.base);
    if (!r.number("slope", h.slope) && !r.table().get("slope"))
        r.diags().error(h.loc, r.keyPath("slope"),
                        "missing: slope angle psi of the flanks in rad, e.g. 0.5 (hexagonal stacks: "
                        "below arctan(2 height / width))");
    r.vec2("spacing", h.gap);
    r.string("shape", h.shape);
    r.number("radius", h.radius);
    r.vec2("size", h.size);
    r.string("material", h.material);
}

void readWall(TableReader& r, model::WallDef& w) {
    w.loc = r.loc();
    r.string("name", w.name);
    if (!r.points("points", w.points) && !r.table().get("points"))
        r.diags().error(w.loc, r.keyPath("points"), "missing: [[x0, y0], [x1, y1], ...] in m");
    r.boolean("closed", w.closed);
    r.choice("kind", w.kind, {"polyline", "polygon"});
    r.vec2("offset", w.offset);
    r.number("angle", w.angle);
    r.string("material", w.material);
    r.vec2("velocity", w.velocity);
    r.vec2("surface_velocity", w.surfaceVelocity);
    r.choice("vib_type", w.vibType, {"cosine", "sawtooth", "tapping", "triangle"});
    r.number("vib_direction", w.vibDirection);
    r.number("vib_width", w.vibWidth);
    r.number("vib_frequency", w.vibFrequency);
    std::vector<Real> window;
    if (r.numbers("vib_window", window, 2)) {
        w.vibFrom = window[0];
        w.vibTo = window[1];
    }
    Real force = 0;
    if (r.number("piston_force", force)) w.pistonForce = force;
    r.number("piston_direction", w.pistonDirection);
    r.number("piston_v_max", w.pistonMaxSpeed);
    r.number("piston_gain", w.pistonGain);
    r.number("piston_from", w.pistonFrom);
    r.number("omega", w.omega);
    Vec2 pivot;
    if (r.vec2("pivot", pivot)) w.pivot = pivot;
}

/// [[spring]]: gc2d DRAG spring (spec section 3.8).
void readSpring(TableReader& r, model::SpringDef& sp) {
    sp.loc = r.loc();
    if (!r.integer("particle", sp.particle) && !r.table().get("particle"))
        r.diags().error(sp.loc, r.keyPath("particle"),
                        "missing: id of the pulled particle (generation order, from 0)");
    sp.stiffness = 100;  // gc2d DRAG_K default [N/m]
    r.number("k", sp.stiffness);
    r.vec2("attach", sp.attach);
    if (!r.vec2("pull_start", sp.pullStart) && !r.table().get("pull_start"))
        r.diags().error(sp.loc, r.keyPath("pull_start"), "missing: [x, y] in m, the free end at t <= from");
    r.number("speed", sp.speed);
    r.number("direction", sp.direction);
    r.number("from", sp.from);
    r.number("to", sp.to);
}

/// Reads every dem section into `scene`; shapes before the particles and blocks that use them.
void readDemSections(TableReader& root, model::SceneDef& scene) {
    withTable(root, "dem", [&](TableReader& t) { readDem(t, scene.dem); });
    forEachTable(root, "material", [&](TableReader& t, std::size_t) {
        model::MaterialDef m;
        m.loc = t.loc();
        if (!t.string("name", m.name) && !t.table().get("name"))
            t.diags().error(m.loc, t.keyPath("name"), "missing: material name");
        t.number("density", m.density);
        t.number("youngs_modulus", m.youngsModulus);
        t.number("poisson", m.poisson);
        scene.materials.push_back(m);
    });
    forEachTable(root, "contact", [&](TableReader& t, std::size_t) {
        model::ContactDef c;
        readContact(t, c);
        scene.contacts.push_back(c);
    });
    forEachTable(root, "shape", [&](TableReader& t, std::size_t) {  // before particles and blocks use them
        model::ShapeDef sh;
        readShape(t, sh);
        scene.shapes.push_back(sh);
    });
    forEachTable(root, "particle", [&](TableReader& t, std::size_t) {
        model::ParticleDef p;
        readParticle(t, p, scene.shapes);
        scene.particles.push_back(p);
    });
    forEachTable(root, "block", [&](TableReader& t, std::size_t) {
        model::BlockDef b;
        readBlock(t, b, scene.shapes);
        scene.blocks.push_back(b);
    });
    forEachTable(root, "heap", [&](TableReader& t, std::size_t) {  // after the blocks: ids follow theirs
        model::HeapDef h;
        readHeap(t, h);
        scene.heaps.push_back(h);
    });
    forEachTable(root, "wall", [&](TableReader& t, std::size_t) {
        model::WallDef w;
        readWall(t, w);
        scene.walls.push_back(w);
    });
    forEachTable(root, "spring", [&](TableReader& t, std::size_t) {
        model::SpringDef sp;
        readSpring(t, sp);
        scene.springs.push_back(sp);
    });
    readMachineSections(root, scene);
    readFluidSections(root, scene);
}

}  // namespace

SceneSections demSceneSections() {
    SceneSections s;
    s.engine = "dem";
    s.sections = {"dem",     "material",     "contact", "shape",  "particle",  "block",  "heap",
                  "wall",    "spring",       "drum",    "source", "inlet",     "outlet", "boundary",
                  "gravity", "size_scaling", "change",  "fluid",  "attraction"};
    s.required = "dem";
    s.requiredHint = "needs at least dt";
    s.needsEndTime = true;
    s.read = &readDemSections;
    return s;
}

}  // namespace granulab::io
