// SPDX-License-Identifier: MIT
// TOML scene reader. Every table is read through a TableReader that remembers which keys it
// consumed, so that anything left over is reported as an unknown key with a hint.
#include "io/scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "core/suggest.hpp"

namespace granulab::io {

namespace {

using model::SceneDef;

/// Location of a node; nodes inserted by --set have no source and are named by their key.
SourceLoc locOf(const toml::node& node, const std::string& file) {
    const auto& src = node.source();
    if (src.begin.line == 0) return {"--set", 0, 0};
    return {file, static_cast<int>(src.begin.line), static_cast<int>(src.begin.column)};
}

std::string typeName(const toml::node& n) {
    switch (n.type()) {
        case toml::node_type::table: return "a table";
        case toml::node_type::array: return "an array";
        case toml::node_type::string: return "a string";
        case toml::node_type::integer: return "an integer";
        case toml::node_type::floating_point: return "a number";
        case toml::node_type::boolean: return "a boolean";
        default: return "a date/time";
    }
}

class TableReader {
public:
    TableReader(const toml::table& table, std::string path, const std::string& file, Diagnostics& diags)
        : m_table(table), m_path(std::move(path)), m_file(file), m_diags(diags) {}

    SourceLoc loc() const { return locOf(m_table, m_file); }
    std::string keyPath(const std::string& key) const { return m_path.empty() ? key : m_path + "." + key; }
    const std::string& file() const { return m_file; }
    Diagnostics& diags() { return m_diags; }

    /// Marks a key as known and returns its node (nullptr if absent).
    const toml::node* node(const std::string& key) {
        m_known.push_back(key);
        return m_table.get(key);
    }

    void typeError(const std::string& key, const toml::node& n, const std::string& expected) {
        m_diags.error(locOf(n, m_file), keyPath(key), fmt::format("expected {}, got {}", expected, typeName(n)));
    }

    bool number(const std::string& key, Real& out) {
        const toml::node* n = node(key);
        if (!n) return false;
        if (!n->is_number()) {
            typeError(key, *n, "a number");
            return false;
        }
        const Real v = n->value<double>().value_or(0.0);
        if (!std::isfinite(v)) {
            m_diags.error(locOf(*n, m_file), keyPath(key), fmt::format("must be a finite number, got {}", v));
            return false;
        }
        out = v;
        return true;
    }

    bool integer(const std::string& key, std::int64_t& out) {
        const toml::node* n = node(key);
        if (!n) return false;
        if (!n->is_integer()) {
            typeError(key, *n, "an integer");
            return false;
        }
        out = n->value<std::int64_t>().value_or(0);
        return true;
    }

    bool boolean(const std::string& key, bool& out) {
        const toml::node* n = node(key);
        if (!n) return false;
        if (!n->is_boolean()) {
            typeError(key, *n, "true or false");
            return false;
        }
        out = n->value<bool>().value_or(false);
        return true;
    }

    bool string(const std::string& key, std::string& out) {
        const toml::node* n = node(key);
        if (!n) return false;
        if (!n->is_string()) {
            typeError(key, *n, "a string");
            return false;
        }
        out = n->value<std::string>().value_or("");
        return true;
    }

    /// A string that must be one of `allowed`.
    bool choice(const std::string& key, std::string& out, const std::vector<std::string>& allowed) {
        std::string v;
        if (!string(key, v)) return false;
        for (const auto& a : allowed)
            if (a == v) {
                out = v;
                return true;
            }
        m_diags.error(locOf(*m_table.get(key), m_file), keyPath(key),
                      fmt::format("'{}' is not allowed{}; allowed: {}", v, didYouMean(v, allowed), joinList(allowed)));
        return false;
    }

    /// Array of `count` finite numbers.
    bool numbers(const std::string& key, std::vector<Real>& out, std::size_t count) {
        const toml::node* n = node(key);
        if (!n) return false;
        const toml::array* a = n->as_array();
        if (!a || a->size() != count) {
            m_diags.error(locOf(*n, m_file), keyPath(key), fmt::format("expected an array of {} numbers", count));
            return false;
        }
        out.clear();
        for (const auto& e : *a) {
            const auto v = e.value<double>();
            if (!e.is_number() || !v || !std::isfinite(*v)) {
                m_diags.error(locOf(e, m_file), keyPath(key), "expected finite numbers in the array");
                return false;
            }
            out.push_back(*v);
        }
        return true;
    }

    bool vec2(const std::string& key, Vec2& out) {
        std::vector<Real> v;
        if (!numbers(key, v, 2)) return false;
        out = {v[0], v[1]};
        return true;
    }

    /// Array of [x, y] points [m]; counts are checked by validate().
    bool points(const std::string& key, std::vector<Vec2>& out) {
        const toml::node* n = node(key);
        if (!n) return false;
        const toml::array* a = n->as_array();
        if (!a) {
            typeError(key, *n, "an array of [x, y] points");
            return false;
        }
        bool ok = true;
        for (const auto& e : *a) {
            const toml::array* pt = e.as_array();
            if (!pt || pt->size() != 2 || !(*pt)[0].is_number() || !(*pt)[1].is_number()) {
                m_diags.error(locOf(e, m_file), keyPath(key), "each point must be [x, y] in m");
                ok = false;
                continue;
            }
            const Real x = (*pt)[0].value<double>().value_or(0), y = (*pt)[1].value<double>().value_or(0);
            if (!std::isfinite(x) || !std::isfinite(y)) {
                m_diags.error(locOf(e, m_file), keyPath(key), "points must be finite");
                ok = false;
                continue;
            }
            out.push_back({x, y});
        }
        return ok;
    }

    /// Marks a key as dealt with (already reported) without listing it as allowed here.
    void ignore(const std::string& key) { m_ignored.push_back(key); }

    /// Reports keys that were never asked for.
    void finish() {
        for (auto&& [k, v] : m_table) {
            const std::string key(k.str());
            bool known = false;
            for (const auto& kk : m_known) known = known || kk == key;
            for (const auto& kk : m_ignored) known = known || kk == key;
            if (!known)
                m_diags.error(locOf(v, m_file), keyPath(key),
                              fmt::format("unknown key{}; allowed here: {}", didYouMean(key, m_known),
                                          joinList(m_known)));
        }
    }

    const toml::table& table() const { return m_table; }

private:
    const toml::table& m_table;
    std::string m_path;
    const std::string& m_file;
    Diagnostics& m_diags;
    std::vector<std::string> m_known;
    std::vector<std::string> m_ignored;
};

/// Calls fn(reader, index) for every table of an array of tables `key` of `root`.
template <class Fn>
void forEachTable(TableReader& root, const std::string& key, Fn&& fn) {
    const toml::node* n = root.node(key);
    if (!n) return;
    const toml::array* arr = n->as_array();
    if (!arr) {
        root.typeError(key, *n, "an array of tables ([[" + key + "]])");
        return;
    }
    for (std::size_t k = 0; k < arr->size(); ++k) {
        const toml::table* t = (*arr)[k].as_table();
        if (!t) {
            root.typeError(key, (*arr)[k], "a table");
            continue;
        }
        TableReader r(*t, fmt::format("{}[{}]", key, k), root.file(), root.diags());
        fn(r, k);
        r.finish();
    }
}

/// Optional sub-table; calls fn(reader) when present.
template <class Fn>
void withTable(TableReader& root, const std::string& key, Fn&& fn) {
    const toml::node* n = root.node(key);
    if (!n) return;
    const toml::table* t = n->as_table();
    if (!t) {
        root.typeError(key, *n, "a table");
        return;
    }
    TableReader r(*t, root.keyPath(key), root.file(), root.diags());
    fn(r);
    r.finish();
}

void readRun(TableReader& r, model::RunDef& run) {
    run.loc = r.loc();
    r.choice("engine", run.engine, {"dem", "edmd"});
    std::int64_t dim = run.dimension;
    if (r.integer("dimension", dim)) run.dimension = static_cast<int>(dim);
    std::int64_t seed = static_cast<std::int64_t>(run.seed);
    if (r.integer("seed", seed)) run.seed = static_cast<std::uint64_t>(seed);
    if (!r.number("end_time", run.endTime) && !r.table().get("end_time") && run.engine != "edmd")
        r.diags().error(run.loc, "run.end_time", "missing: simulated end time [s], allowed (0, inf)");
    r.number("benchmark_from", run.benchmarkFrom);
    r.string("title", run.title);
}

void readDem(TableReader& r, model::DemDef& dem) {
    dem.loc = r.loc();
    if (!r.number("dt", dem.dt) && !r.table().get("dt"))
        r.diags().error(dem.loc, "dem.dt", "missing: time step [s], allowed (0, inf); `granulab info` advises one");
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

void readContact(TableReader& r, model::ContactDef& c) {
    c.loc = r.loc();
    const toml::node* n = r.node("materials");
    if (!n) {
        r.diags().error(c.loc, r.keyPath("materials"), "missing: the two material names, e.g. [\"grain\", \"wall\"] (\"*\" matches any)");
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
        if (key == "materials" || key == "normal" || key == "damping" || key == "tangential" || key == "rolling")
            continue;
        r.node(key);
        model::LawParamDef p;
        p.loc = locOf(v, r.file());
        if (v.is_boolean()) {
            p.value = v.value<bool>().value_or(false) ? 1.0 : 0.0;
            p.isBool = true;
        } else if (v.is_number()) {
            p.value = v.value<double>().value_or(0.0);
            if (!std::isfinite(p.value)) {
                r.diags().error(p.loc, r.keyPath(key), fmt::format("must be a finite number, got {}", p.value));
                continue;
            }
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
        {"grain", {"size", "full_axes", "size_mode", "size_variation", "corner_count", "corner_count_mode",
                   "corner_variation", "corner_angles"}},
        {"", {"corners", "corner_count", "radius", "size", "chamfer", "full_axes", "size_mode", "size_variation",
              "corner_count_mode", "corner_variation", "corner_angles"}},
    };
    const auto it = keys.find(kind);
    return it != keys.end() ? it->second : keys.at("");
}

void readShape(TableReader& r, model::ShapeDef& s) {
    s.loc = r.loc();
    if (!r.string("name", s.name) && !r.table().get("name"))
        r.diags().error(s.loc, r.keyPath("name"), "missing: shape name, used by `shape = \"name\"` in [[particle]] and [[block]]");
    static const std::vector<std::string> kinds = {"polygon", "regular", "rectangle", "ellipse", "grain"};
    const bool kindOk = r.choice("kind", s.kind, kinds);
    if (!r.table().get("kind"))
        r.diags().error(s.loc, r.keyPath("kind"), fmt::format("missing: shape kind, allowed: {}", joinList(kinds)));
    const auto& allowed = shapeKeysOf(kindOk ? s.kind : "");
    const auto has = [&](const std::string& key) { return std::find(allowed.begin(), allowed.end(), key) != allowed.end(); };
    for (const auto& key : shapeKeysOf("")) {
        const toml::node* n = r.table().get(key);
        if (has(key) || !n) continue;
        std::vector<std::string> own = {"name", "kind"};
        own.insert(own.end(), allowed.begin(), allowed.end());
        own.insert(own.end(), {"rotation_mode", "rotation"});
        r.diags().error(locOf(*n, r.file()), r.keyPath(key),
                        fmt::format("does not apply to a shape of kind '{}'; keys of {} shapes: {}", s.kind, s.kind, joinList(own)));
        r.ignore(key);
    }
    const auto require = [&](const std::string& key, const std::string& what) {
        if (kindOk && !r.table().get(key))
            r.diags().error(s.loc, r.keyPath(key), fmt::format("missing: {} (required for kind '{}')", what, s.kind));
    };
    if (has("corners")) {
        r.points("corners", s.corners);
        require("corners", "[[x0, y0], [x1, y1], ...] in m, counter-clockwise, convex");
    }
    if (has("corner_angles")) r.string("corner_angles", s.cornerAngles);
    if (has("corner_count")) {
        r.integer("corner_count", s.cornerCount);
        if (s.kind != "grain" || s.cornerAngles != "special_rectangle") require("corner_count", "number of corners, >= 3");
    }
    if (has("radius")) {
        r.number("radius", s.radius);
        require("radius", "circumscribed radius in m, allowed (0, inf)");
    }
    if (has("size")) {
        r.vec2("size", s.size);
        require("size", s.kind == "rectangle" ? "[a, b], the edge lengths in m" : "[a, b], the semi-axes in m");
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
    return std::any_of(shapes.begin(), shapes.end(), [&](const model::ShapeDef& s) { return s.name == name; });
}

/// Reads `radius` for disks (required) and unknown shape names (optional; the name is reported
/// by validate()); for a [[shape]] a radius is an error. Returns false if the radius is not read.
bool radiusForShape(TableReader& r, const std::string& shape, const std::vector<model::ShapeDef>& shapes) {
    const toml::node* n = r.table().get("radius");
    if (shape == "disk" || !isShapeName(shapes, shape)) return true;
    if (n) {
        r.diags().error(locOf(*n, r.file()), r.keyPath("radius"),
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

void readBlock(TableReader& r, model::BlockDef& b, const std::vector<model::ShapeDef>& shapes) {
    b.loc = r.loc();
    std::string lattice = "hexagonal";
    r.choice("lattice", lattice, {"hexagonal", "square", "random"});
    b.lattice = lattice == "hexagonal" ? model::BlockDef::Lattice::Hexagonal
                : lattice == "square"  ? model::BlockDef::Lattice::Square
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
}

void readWall(TableReader& r, model::WallDef& w) {
    w.loc = r.loc();
    r.string("name", w.name);
    if (!r.points("points", w.points) && !r.table().get("points"))
        r.diags().error(w.loc, r.keyPath("points"), "missing: [[x0, y0], [x1, y1], ...] in m");
    r.boolean("closed", w.closed);
    r.string("material", w.material);
    r.vec2("velocity", w.velocity);
}

/// [[spring]]: gc2d DRAG spring (spec section 3.8).
void readSpring(TableReader& r, model::SpringDef& sp) {
    sp.loc = r.loc();
    if (!r.integer("particle", sp.particle) && !r.table().get("particle"))
        r.diags().error(sp.loc, r.keyPath("particle"), "missing: id of the pulled particle (generation order, from 0)");
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

void readOutput(TableReader& r, model::OutputDef& o) {
    o.loc = r.loc();
    r.number("snapshot_interval", o.snapshotInterval);
    r.number("series_interval", o.seriesInterval);
    r.number("checkpoint_interval", o.checkpointInterval);
    r.boolean("vtk", o.vtk);
}

/// A per-axis array of 2 or 3 numbers (2D or 3D; the dimension is checked in validation).
void readAxisNumbers(TableReader& r, const std::string& key, std::vector<Real>& out, const std::string& what) {
    const toml::node* n = r.node(key);
    if (!n) return;
    const auto* a = n->as_array();
    const std::size_t count = a ? a->size() : 0;
    if (count != 2 && count != 3) r.diags().error(locOf(*n, r.file()), r.keyPath(key), "expected an array of 2 or 3 " + what);
    else r.numbers(key, out, count);
}

void readEdmd(TableReader& r, model::EdmdDef& e) {
    e.loc = r.loc();
    readAxisNumbers(r, "box", e.box, "edge lengths [m]");
    if (const toml::node* n = r.node("periodic")) {
        const auto* a = n->as_array();
        bool ok = a && (a->size() == 2 || a->size() == 3);
        if (ok)
            for (const auto& v : *a) {
                if (!v.is_boolean()) ok = false;
                else e.periodic.push_back(v.value<bool>().value_or(true));
            }
        if (!ok) r.diags().error(locOf(*n, r.file()), r.keyPath("periodic"), "expected an array of 2 or 3 booleans, one per axis");
    }
    r.integer("count", e.count);
    r.number("volume_fraction", e.volumeFraction);
    r.number("radius", e.radius);
    r.number("radius_max", e.radiusMax);
    r.number("mass", e.mass);
    r.choice("placement", e.placement, {"lattice", "random"});
    r.number("temperature", e.temperature);
    r.number("equilibrate", e.equilibrate);
    r.number("restitution", e.restitution);
    r.choice("restitution_model", e.restitutionModel, {"constant", "mcnamara_falcon", "viscoelastic"});
    r.number("restitution_speed", e.restitutionSpeed);
    r.number("wall_restitution", e.wallRestitution);
    r.number("tangential_restitution", e.tangentialRestitution);
    r.number("inertia_factor", e.inertiaFactor);
    r.number("tc", e.tc);
    readAxisNumbers(r, "gravity", e.gravity, "components [m/s^2]");
    r.number("growth_rate", e.growthRate);
    r.number("cell_size", e.cellSize);
    r.choice("queue", e.queue, {"calendar", "heap", "tree"});
    r.number("end_tau", e.endTau);
    r.number("end_collisions", e.endCollisions);
    r.choice("series", e.series, {"linear", "log"});
    r.integer("series_points", e.seriesPoints);
    r.number("series_first", e.seriesFirst);
    r.boolean("clusters", e.clusters);
    r.number("cluster_delta", e.clusterDelta);
    r.boolean("analysis_files", e.analysisFiles);
}

/// Splits "a.b[2].c" into segments {"a", "b", "[2]", "c"}.
std::vector<std::string> splitPath(const std::string& key) {
    std::vector<std::string> parts;
    std::string cur;
    for (std::size_t k = 0; k < key.size(); ++k) {
        const char ch = key[k];
        if (ch == '.') {
            if (!cur.empty()) parts.push_back(cur);
            cur.clear();
        } else if (ch == '[') {
            if (!cur.empty()) parts.push_back(cur);
            cur = "[";
        } else if (ch == ']') {
            parts.push_back(cur + "]");
            cur.clear();
        } else {
            cur += ch;
        }
    }
    if (!cur.empty()) parts.push_back(cur);
    return parts;
}

void applyOverride(toml::table& root, const Override& ov, Diagnostics& diags) {
    const SourceLoc loc{"--set " + ov.key, 0, 0};
    const auto parts = splitPath(ov.key);
    if (parts.empty() || parts.back().front() == '[') {
        diags.error(loc, ov.key, "malformed key; expected section.key or section[index].key");
        return;
    }
    toml::node* cur = &root;
    for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
        const std::string& part = parts[k];
        if (part.front() == '[') {
            toml::array* arr = cur->as_array();
            std::size_t idx = 0;
            try {
                idx = std::stoul(part.substr(1, part.size() - 2));
            } catch (...) {
                diags.error(loc, ov.key, "array index must be a number");
                return;
            }
            if (!arr || idx >= arr->size()) {
                diags.error(loc, ov.key, fmt::format("no element {} to override", part));
                return;
            }
            cur = arr->get(idx);
        } else {
            toml::table* t = cur->as_table();
            if (!t) {
                diags.error(loc, ov.key, fmt::format("'{}' is not inside a table", part));
                return;
            }
            if (!t->get(part)) t->insert(part, toml::table{});
            cur = t->get(part);
        }
    }
    toml::table* target = cur->as_table();
    if (!target) {
        diags.error(loc, ov.key, "the parent of the key is not a table");
        return;
    }
    toml::table parsed;
    try {
        parsed = toml::parse("v = " + ov.value);
    } catch (const toml::parse_error&) {
        parsed = toml::table{};
        parsed.insert("v", ov.value);  // bare word: a string
    }
    target->insert_or_assign(parts.back(), *parsed.get("v"));
}

SceneDef buildScene(toml::table& root, const std::string& path, const std::vector<Override>& overrides) {
    Diagnostics diags;
    for (const auto& ov : overrides) applyOverride(root, ov, diags);
    SceneDef scene;
    scene.path = path;
    TableReader r(root, "", path, diags);
    withTable(r, "run", [&](TableReader& t) { readRun(t, scene.run); });
    if (!root.get("run")) diags.error({path, 1, 1}, "run", "missing section [run] (needs at least end_time)");
    withTable(r, "dem", [&](TableReader& t) { readDem(t, scene.dem); });
    withTable(r, "edmd", [&](TableReader& t) { readEdmd(t, scene.edmd); });
    scene.hasDem = root.get("dem") != nullptr;
    scene.hasEdmd = root.get("edmd") != nullptr;
    if (scene.run.engine == "edmd") {
        if (!scene.hasEdmd)
            diags.error({path, 1, 1}, "edmd", "missing section [edmd] (the event-driven gas: count or volume_fraction, radius)");
        for (const char* section : {"dem", "material", "contact", "shape", "particle", "block", "wall", "spring"})
            if (const toml::node* n = root.get(section))
                diags.error(locOf(*n, path), section,
                            fmt::format("[{}] belongs to the dem engine; run.engine = \"edmd\" takes its particles, box "
                                        "and walls from [edmd]", section));
    } else if (!scene.hasDem) {
        diags.error({path, 1, 1}, "dem", "missing section [dem] (needs at least dt)");
    }
    if (scene.run.engine != "edmd" && scene.hasEdmd)
        diags.error(locOf(*root.get("edmd"), path), "edmd", "[edmd] needs run.engine = \"edmd\"");
    forEachTable(r, "material", [&](TableReader& t, std::size_t) {
        model::MaterialDef m;
        m.loc = t.loc();
        if (!t.string("name", m.name) && !t.table().get("name")) diags.error(m.loc, t.keyPath("name"), "missing: material name");
        t.number("density", m.density);
        t.number("youngs_modulus", m.youngsModulus);
        t.number("poisson", m.poisson);
        scene.materials.push_back(m);
    });
    forEachTable(r, "contact", [&](TableReader& t, std::size_t) {
        model::ContactDef c;
        readContact(t, c);
        scene.contacts.push_back(c);
    });
    forEachTable(r, "shape", [&](TableReader& t, std::size_t) {  // before particles and blocks use them
        model::ShapeDef sh;
        readShape(t, sh);
        scene.shapes.push_back(sh);
    });
    forEachTable(r, "particle", [&](TableReader& t, std::size_t) {
        model::ParticleDef p;
        readParticle(t, p, scene.shapes);
        scene.particles.push_back(p);
    });
    forEachTable(r, "block", [&](TableReader& t, std::size_t) {
        model::BlockDef b;
        readBlock(t, b, scene.shapes);
        scene.blocks.push_back(b);
    });
    forEachTable(r, "wall", [&](TableReader& t, std::size_t) {
        model::WallDef w;
        readWall(t, w);
        scene.walls.push_back(w);
    });
    forEachTable(r, "spring", [&](TableReader& t, std::size_t) {
        model::SpringDef sp;
        readSpring(t, sp);
        scene.springs.push_back(sp);
    });
    withTable(r, "output", [&](TableReader& t) { readOutput(t, scene.output); });
    r.finish();
    diags.throwIfAny();
    return scene;
}

}  // namespace

Override parseOverride(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw SceneError(makeDiagnostic("--set", 0, text, "expected key=value, e.g. --set dem.dt=1e-5"));
    return {text.substr(0, eq), text.substr(eq + 1)};
}

SceneDef readSceneText(const std::string& text, const std::string& path, const std::vector<Override>& overrides) {
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        const auto& b = e.source().begin;
        throw SceneError(makeDiagnostic(path, static_cast<int>(b.line), "",
                                        fmt::format("syntax error: {}", e.description())));
    }
    return buildScene(root, path, overrides);
}

SceneDef readScene(const std::string& path, const std::vector<Override>& overrides) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(makeDiagnostic(path, 0, "", "cannot open scene file (missing or unreadable)"));
    std::ostringstream ss;
    ss << in.rdbuf();
    return readSceneText(ss.str(), path, overrides);
}

}  // namespace granulab::io
