// SPDX-License-Identifier: MIT
// Readers of [[drum]], [[source]], [[inlet]], [[outlet]], [[boundary]], [gravity] and [[change]]
// (docs/scene-format.md; gc2d spec 6.2-6.7, cfddem spec 4.1-4.3).
#include "io/dem_machine_sections.hpp"

#include <fmt/format.h>

namespace granulab::io {

namespace {

bool window(TableReader& r, const std::string& key, Real& from, Real& to) {
    std::vector<Real> w;
    if (!r.numbers(key, w, 2)) return false;
    from = w[0];
    to = w[1];
    return true;
}

void required(TableReader& r, const std::string& key, const std::string& what) {
    if (!r.table().get(key)) r.diags().error(r.loc(), r.keyPath(key), "missing: " + what);
}

/// The keys of what a source or inlet inserts (same names everywhere).
void readInsert(TableReader& r, model::InsertDef& d) {
    r.string("shape", d.shape);
    readSize(r, "radius", d.radius);
    r.string("material", d.material);
    required(r, "material", "material of the inserted particles");
    r.vec2("velocity", d.velocity);
    r.number("angle", d.angle);
    r.number("omega", d.omega);
    r.integer("attempts", d.attempts);
}

bool edge(TableReader& r, Vec2& a, Vec2& b) {
    std::vector<Vec2> p;
    if (!r.points("edge", p)) return false;
    if (p.size() != 2) {
        r.diags().error(r.loc(), r.keyPath("edge"),
                        fmt::format("an edge has 2 points [[x1, y1], [x2, y2]], got {}", p.size()));
        return false;
    }
    a = p[0];
    b = p[1];
    return true;
}

void readDrum(TableReader& r, model::DrumDef& d) {
    d.loc = r.loc();
    r.string("name", d.name);
    r.vec2("centre", d.centre);
    r.number("inner_radius", d.innerRadius);
    required(r, "inner_radius", "inner radius r of the drum [m]");
    r.number("thickness", d.thickness);
    required(r, "thickness", "wall thickness d of the drum [m]");
    r.integer("count", d.count);
    r.number("surface_speed", d.surfaceSpeed);
    r.boolean("rotating", d.rotating);
    r.string("material", d.material);
    required(r, "material", "wall material");
}

void readSource(TableReader& r, model::SourceDef& s) {
    s.loc = r.loc();
    r.string("name", s.name);
    r.vec2("position", s.position);
    r.choice("placement", s.placement, {"abs", "rel"});
    r.number("width", s.width);
    Real end = 0;
    if (r.number("width_end", end)) s.widthEnd = end;
    r.number("interval", s.interval);
    r.number("from", s.from);
    r.number("to", s.to);
    readInsert(r, s.insert);
}

void readInlet(TableReader& r, model::InletDef& in) {
    in.loc = r.loc();
    r.string("name", in.name);
    if (!edge(r, in.a, in.b)) required(r, "edge", "[[x1, y1], [x2, y2]] in m (the domain lies to the right)");
    r.number("rate", in.rate);
    required(r, "rate", "particles per second (pps)");
    r.number("from", in.from);
    r.number("to", in.to);
    r.boolean("inset", in.inset);
    readInsert(r, in.insert);
}

void readOutlet(TableReader& r, model::OutletDef& o) {
    o.loc = r.loc();
    r.string("name", o.name);
    const bool hasEdge = edge(r, o.a, o.b);
    std::vector<Real> region;
    if (r.numbers("region", region, 4)) {
        o.isRegion = true;
        o.xmin = region[0];
        o.ymin = region[1];
        o.xmax = region[2];
        o.ymax = region[3];
    }
    if (hasEdge && o.isRegion)
        r.diags().error(o.loc, r.keyPath("region"), "an outlet has either `edge` or `region`, not both");
    if (!r.table().get("edge") && !r.table().get("region"))
        r.diags().error(o.loc, r.keyPath("edge"),
                        "missing: `edge = [[x1, y1], [x2, y2]]` or `region = [xmin, ymin, xmax, ymax]`");
    std::string remove = "inside";
    r.choice("remove", remove, {"inside", "outside"});
    o.removeInside = remove == "inside";
    r.number("open_at", o.openAt);
    r.string("material", o.material);
}

void readBoundary(TableReader& r, model::BoundaryDef& b) {
    b.loc = r.loc();
    r.string("name", b.name);
    if (!r.points("points", b.points)) required(r, "points", "[[x0, y0], [x1, y1], ...] in m");
    if (const toml::node* n = r.node("edges")) {
        const toml::array* a = n->as_array();
        bool ok = a != nullptr;
        for (std::size_t k = 0; ok && k < a->size(); ++k) {
            const toml::array* e = (*a)[k].as_array();
            ok = e && e->size() == 3 && (*e)[0].is_integer() && (*e)[1].is_integer() && (*e)[2].is_string();
            if (!ok) break;
            model::BoundaryDef::Edge edge;
            edge.from = (*e)[0].value<std::int64_t>().value_or(-1);
            edge.to = (*e)[1].value<std::int64_t>().value_or(-1);
            edge.type = (*e)[2].value<std::string>().value_or("");
            b.edges.push_back(edge);
        }
        if (!ok)
            r.typeError("edges", *n,
                        "an array of [from, to, \"wall\" | \"outlet\" | \"inlet\"] (point indices from 0)");
    } else {
        required(r, "edges", "[[from, to, \"wall\"], ...]: point indices from 0 and the edge type");
    }
    r.boolean("obstacle", b.obstacle);
    r.string("material", b.material);
    r.number("rate", b.rate);
    r.number("open_at", b.openAt);
    if (const toml::node* n = r.node("inlet")) {
        if (const toml::table* t = n->as_table()) {
            TableReader in(*t, r.keyPath("inlet"), r.file(), r.diags());
            readInsert(in, b.insert);
            in.finish();
        } else {
            r.typeError("inlet", *n, "a table { material = ..., radius = ..., velocity = [...] }");
        }
    }
}

/// `key = x` (both values x) or `key = [x1, x2]`.
void numberOrPair(TableReader& r, const std::string& key, Real& first, Real& second) {
    const toml::node* n = r.table().get(key);
    if (n && n->is_array()) {
        std::vector<Real> v;
        if (r.numbers(key, v, 2)) {
            first = v[0];
            second = v[1];
        }
    } else if (r.number(key, first)) {
        second = first;
    }
}

void readGravity(TableReader& r, model::GravityDef& g) {
    g.present = true;
    g.loc = r.loc();
    r.choice("type", g.type, {"constant", "linear", "step", "smooth_step"});
    numberOrPair(r, "magnitude", g.g1, g.g2);
    window(r, "window", g.t1, g.t2);
    r.number("steps", g.steps);
    r.number("ramp", g.ramp);
    numberOrPair(r, "direction", g.direction1, g.direction2);
    g.tilt1 = g.t1;
    g.tilt2 = g.t2;
    window(r, "tilt_window", g.tilt1, g.tilt2);
}

void readSizeScaling(TableReader& r, model::SizeScalingDef& z) {
    z.present = true;
    z.loc = r.loc();
    r.number("amplitude", z.amplitude);
    r.number("frequency", z.frequency);
    r.number("slope", z.slope);
    window(r, "window", z.t1, z.t2);
}

void readChange(TableReader& r, model::ChangeDef& c) {
    c.loc = r.loc();
    r.number("at", c.at);
    required(r, "at", "time of the change [s]");
    r.integer("contact", c.contact);
    required(r, "contact", "index of the [[contact]] entry to change (from 0)");
    const toml::node* n = r.node("set");
    const toml::table* t = n ? n->as_table() : nullptr;
    if (!t) {
        if (n)
            r.typeError("set", *n, "a table of law parameters, e.g. { mu = 0.0 }");
        else
            required(r, "set", "the law parameters to change, e.g. set = { mu = 0.0 }");
        return;
    }
    TableReader s(*t, r.keyPath("set"), r.file(), r.diags());
    for (auto&& [k, v] : *t) {
        const std::string key(k.str());
        model::LawParamDef p;
        p.loc = locOf(v, r.file());
        if (v.is_boolean()) {
            s.node(key);
            p.value = v.value<bool>().value_or(false) ? 1.0 : 0.0;
            p.isBool = true;
        } else if (!s.number(key, p.value)) {
            continue;
        }
        c.set[key] = p;
    }
    s.finish();
}

/// Reads every [[key]] table into `out` with `read`.
template <class Def, class Read>
void readEach(TableReader& root, const char* key, std::vector<Def>& out, Read read) {
    forEachTable(root, key, [&](TableReader& t, std::size_t) {
        Def d;
        read(t, d);
        out.push_back(std::move(d));
    });
}

}  // namespace

void readMachineSections(TableReader& root, model::SceneDef& scene) {
    auto& m = scene.machines;
    readEach(root, "drum", m.drums, readDrum);
    readEach(root, "source", m.sources, readSource);
    readEach(root, "inlet", m.inlets, readInlet);
    readEach(root, "outlet", m.outlets, readOutlet);
    readEach(root, "boundary", m.boundaries, readBoundary);
    withTable(root, "gravity", [&](TableReader& t) { readGravity(t, m.gravity); });
    withTable(root, "size_scaling", [&](TableReader& t) { readSizeScaling(t, m.sizeScaling); });
    readEach(root, "change", m.changes, readChange);
}

}  // namespace granulab::io
