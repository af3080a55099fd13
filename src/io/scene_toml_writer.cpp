// SPDX-License-Identifier: MIT
// SceneDef -> native TOML text (io/scene_toml_writer.hpp).
#include "io/scene_toml_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "core/utf8.hpp"

namespace granulab::io {

namespace fs = std::filesystem;

std::string tomlNumber(double v) {
    if (v == 0 && std::signbit(v)) return "-0.0";
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return fmt::format("{}", v);  // shortest text that reads back as the same double
}

std::string tomlString(const std::string& s) {
    if (!isUtf8(s))  // TOML text is UTF-8
        throw std::invalid_argument(fmt::format("'{}' is not UTF-8 text, which TOML needs", s));
    std::string out = "\"";
    for (const char c : s) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\t':
                out += "\\t";
                break;
            case '\r':
                out += "\\r";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
                    out += fmt::format("\\u{:04X}", static_cast<unsigned>(static_cast<unsigned char>(c)));
                else
                    out += c;
        }
    }
    return out + "\"";
}

namespace {

std::string vec(Vec2 v) {
    return fmt::format("[{}, {}]", tomlNumber(v.x), tomlNumber(v.y));
}
std::string boolean(bool b) {
    return b ? "true" : "false";
}

/// Lines `key = value  # comment`, the comments aligned.
class Writer {
public:
    void section(const std::string& header) {
        if (!m_text.empty()) m_text += "\n";
        m_text += header + "\n";
    }
    void key(const std::string& k, const std::string& value, const std::string& comment = "") {
        std::string line = k + " = " + value;
        if (!comment.empty()) {
            if (line.size() < 32) line.resize(32, ' ');
            line += "  # " + comment;
        }
        m_text += line + "\n";
    }
    void comment(const std::string& c) { m_text += "# " + c + "\n"; }
    const std::string& text() const { return m_text; }

private:
    std::string m_text;
};

std::string sizeDist(const model::SizeDistDef& s) {
    using K = model::SizeDistDef::Kind;
    switch (s.kind) {
        case K::Constant:
            return tomlNumber(s.value);
        case K::Uniform:
            return fmt::format("{{ distribution = \"uniform\", min = {}, max = {} }}", tomlNumber(s.min),
                               tomlNumber(s.max));
        case K::Gaussian:
            return fmt::format("{{ distribution = \"gaussian\", mean = {}, sigma = {}, min = {}, max = {} }}",
                               tomlNumber(s.mean), tomlNumber(s.sigma), tomlNumber(s.min), tomlNumber(s.max));
    }
    return tomlNumber(s.value);
}

/// The keys of an InsertDef (as in [[inlet]] and a boundary's inlet table).
std::vector<std::pair<std::string, std::string>> insertKeys(const model::InsertDef& d) {
    std::vector<std::pair<std::string, std::string>> kv;
    if (d.shape != "disk") kv.emplace_back("shape", tomlString(d.shape));
    if (d.shape == "disk") kv.emplace_back("radius", sizeDist(d.radius));
    kv.emplace_back("material", tomlString(d.material));
    kv.emplace_back("velocity", vec(d.velocity));
    kv.emplace_back("angle", tomlNumber(d.angle));
    kv.emplace_back("omega", tomlNumber(d.omega));
    if (d.attempts != model::InsertDef{}.attempts) kv.emplace_back("attempts", std::to_string(d.attempts));
    return kv;
}

std::string points(const std::vector<Vec2>& pts) {
    std::string out = "[";
    for (std::size_t k = 0; k < pts.size(); ++k) out += (k ? ", " : "") + vec(pts[k]);
    return out + "]";
}
std::string pair(Real a, Real b) {
    return fmt::format("[{}, {}]", tomlNumber(a), tomlNumber(b));
}
std::string inlineTable(const std::vector<std::pair<std::string, std::string>>& kv) {
    std::string t = "{ ";
    for (std::size_t k = 0; k < kv.size(); ++k) t += (k ? ", " : "") + kv[k].first + " = " + kv[k].second;
    return t + " }";
}
std::string lawParams(const std::map<std::string, model::LawParamDef>& params) {
    std::vector<std::pair<std::string, std::string>> kv;
    for (const auto& [key, p] : params)
        kv.emplace_back(key, p.isBool ? (p.value != 0 ? "true" : "false") : tomlNumber(p.value));
    return inlineTable(kv);
}
const char* latticeName(model::BlockDef::Lattice l) {
    using L = model::BlockDef::Lattice;
    switch (l) {
        case L::Hexagonal:
            return "hexagonal";
        case L::Square:
            return "square";
        case L::Random:
            return "random";
        case L::Rect:
            return "rect";
        case L::Fcc:
            return "fcc";
    }
    return "hexagonal";
}
const char* jitterName(model::BlockDef::Jitter j) {
    using J = model::BlockDef::Jitter;
    return j == J::Gauss ? "gauss" : j == J::Equal ? "equal" : "none";
}

void writeShape(Writer& w, const model::ShapeDef& s) {
    const model::ShapeDef d;
    w.section("[[shape]]");
    w.key("name", tomlString(s.name));
    w.key("kind", tomlString(s.kind));
    if (s.kind == "polygon") w.key("corners", points(s.corners), "[m] counter-clockwise");
    if (s.kind == "regular" || s.kind == "ellipse" ||
        (s.kind == "grain" && !(s.cornerAngles == "special_rectangle" && s.cornerCount == 0)))
        w.key("corner_count", std::to_string(s.cornerCount));
    if (s.kind == "regular") w.key("radius", tomlNumber(s.radius), "[m] circumscribed");
    if (s.kind == "rectangle" || s.kind == "ellipse" || s.kind == "grain")
        w.key("size", vec(s.size), s.kind == "rectangle" ? "[m] edge lengths" : "[m] semi-axes");
    if (s.kind == "rectangle" && s.chamfer != d.chamfer) w.key("chamfer", tomlNumber(s.chamfer));
    if (s.kind == "grain") {
        w.key("corner_angles", tomlString(s.cornerAngles));
        w.key("size_mode", tomlString(s.sizeMode));
        w.key("size_variation", tomlNumber(s.sizeVariation), "[-] I");
        if (s.fullAxes) w.key("full_axes", "true");
        w.key("corner_count_mode", tomlString(s.cornerCountMode));
        w.key("corner_variation", std::to_string(s.cornerVariation), "N_I");
    }
    if (s.rotationMode != d.rotationMode) w.key("rotation_mode", tomlString(s.rotationMode));
    if (s.rotation != d.rotation) w.key("rotation", tomlNumber(s.rotation), "[rad] counter-clockwise");
}

void writeBlock(Writer& w, const model::BlockDef& b, const std::vector<model::ShapeDef>& shapes) {
    using L = model::BlockDef::Lattice;
    const model::BlockDef d;
    w.section("[[block]]");
    w.key("lattice", tomlString(latticeName(b.lattice)));
    if (b.shape != "disk") w.key("shape", tomlString(b.shape));
    w.key("region",
          fmt::format("[{}, {}, {}, {}]", tomlNumber(b.xmin), tomlNumber(b.ymin), tomlNumber(b.xmax),
                      tomlNumber(b.ymax)),
          "[m] xmin, ymin, xmax, ymax");
    if (b.spacing != d.spacing) w.key("spacing", tomlNumber(b.spacing), "[m]");
    if (b.origin) w.key("origin", vec(*b.origin), "[m]");
    if (b.count != d.count) w.key("count", std::to_string(b.count));
    const bool polygon =
        std::any_of(shapes.begin(), shapes.end(), [&](const auto& s) { return s.name == b.shape; });
    if (!polygon) w.key("radius", sizeDist(b.radius), "[m]");
    w.key("material", tomlString(b.material));
    if (!(b.velocity == d.velocity)) w.key("velocity", vec(b.velocity), "[m/s]");
    if (b.temperature != d.temperature) w.key("temperature", tomlNumber(b.temperature), "[J]");
    if (b.lattice == L::Rect || b.lattice == L::Fcc || !(b.grid == d.grid)) w.key("grid", vec(b.grid), "[m]");
    if (b.jitter != d.jitter) w.key("jitter", tomlString(jitterName(b.jitter)));
    if (b.jitterFraction != d.jitterFraction) w.key("jitter_fraction", tomlNumber(b.jitterFraction));
    if (!(b.directionRange == d.directionRange)) w.key("direction_range", vec(b.directionRange), "[rad]");
    if (!(b.speedRange == d.speedRange)) w.key("speed_range", vec(b.speedRange), "[m/s]");
}

void writeHeap(Writer& w, const model::HeapDef& h) {
    const model::HeapDef d;
    w.section("[[heap]]");
    w.key("stacking",
          tomlString(h.stacking == model::HeapDef::Stacking::Hexagonal ? "hexagonal" : "rectangular"));
    w.key("x_range", pair(h.xLeft, h.xRight), "[m]");
    w.key("base", tomlNumber(h.base), "[m]");
    w.key("slope", tomlNumber(h.slope), "[rad]");
    if (!(h.gap == d.gap)) w.key("spacing", vec(h.gap), "[m] gaps");
    if (h.shape != "disk") w.key("shape", tomlString(h.shape));
    if (h.radius != d.radius) w.key("radius", tomlNumber(h.radius), "[m]");
    if (!(h.size == d.size)) w.key("size", vec(h.size), "[m]");
    w.key("material", tomlString(h.material));
}

void writeWall(Writer& w, const model::WallDef& x) {
    const model::WallDef d;
    w.section("[[wall]]");
    if (!x.name.empty()) w.key("name", tomlString(x.name));
    w.key("kind", tomlString(x.kind));
    w.key("points", points(x.points), "[m]");
    if (x.closed) w.key("closed", "true");
    if (!(x.offset == d.offset)) w.key("offset", vec(x.offset), "[m]");
    if (x.angle != d.angle) w.key("angle", tomlNumber(x.angle), "[rad] counter-clockwise");
    if (!x.material.empty()) w.key("material", tomlString(x.material));
    if (!(x.velocity == d.velocity)) w.key("velocity", vec(x.velocity), "[m/s]");
    if (!(x.surfaceVelocity == d.surfaceVelocity))
        w.key("surface_velocity", vec(x.surfaceVelocity), "[m/s] belt");
    if (!x.vibType.empty()) w.key("vib_type", tomlString(x.vibType));
    if (x.vibDirection != d.vibDirection) w.key("vib_direction", tomlNumber(x.vibDirection), "[rad]");
    if (x.vibWidth != d.vibWidth) w.key("vib_width", tomlNumber(x.vibWidth), "[m]");
    if (x.vibFrequency != d.vibFrequency) w.key("vib_frequency", tomlNumber(x.vibFrequency), "[1/s]");
    if (x.vibFrom != d.vibFrom || x.vibTo != d.vibTo) w.key("vib_window", pair(x.vibFrom, x.vibTo), "[s]");
    if (x.pistonForce) w.key("piston_force", tomlNumber(*x.pistonForce), "[N]");
    if (x.pistonDirection != d.pistonDirection)
        w.key("piston_direction", tomlNumber(x.pistonDirection), "[rad]");
    if (x.pistonMaxSpeed != d.pistonMaxSpeed) w.key("piston_v_max", tomlNumber(x.pistonMaxSpeed), "[m/s]");
    if (x.pistonGain != d.pistonGain) w.key("piston_gain", tomlNumber(x.pistonGain), "[m/(N s)]");
    if (x.pistonFrom != d.pistonFrom) w.key("piston_from", tomlNumber(x.pistonFrom), "[s]");
    if (x.omega != d.omega) w.key("omega", tomlNumber(x.omega), "[rad/s]");
    if (x.pivot) w.key("pivot", vec(*x.pivot), "[m]");
}

void writeSpring(Writer& w, const model::SpringDef& sp) {
    const model::SpringDef d;
    w.section("[[spring]]");
    w.key("particle", std::to_string(sp.particle), "id (generation order)");
    w.key("k", tomlNumber(sp.stiffness), "[N/m]");
    w.key("attach", vec(sp.attach), "[m] body frame");
    w.key("pull_start", vec(sp.pullStart), "[m]");
    w.key("speed", tomlNumber(sp.speed), "[m/s]");
    w.key("direction", tomlNumber(sp.direction), "[rad]");
    if (sp.from != d.from) w.key("from", tomlNumber(sp.from), "[s]");
    if (sp.to != d.to) w.key("to", tomlNumber(sp.to), "[s]");
}

void writeMachines(Writer& w, const model::MachineDefs& m) {
    for (const auto& dr : m.drums) {
        w.section("[[drum]]");
        if (!dr.name.empty()) w.key("name", tomlString(dr.name));
        w.key("centre", vec(dr.centre), "[m]");
        w.key("inner_radius", tomlNumber(dr.innerRadius), "[m]");
        w.key("thickness", tomlNumber(dr.thickness), "[m]");
        w.key("count", std::to_string(dr.count));
        w.key("surface_speed", tomlNumber(dr.surfaceSpeed), "[m/s]");
        if (dr.rotating) w.key("rotating", "true");
        w.key("material", tomlString(dr.material));
    }
    for (const auto& s : m.sources) {
        const model::SourceDef d;
        w.section("[[source]]");
        if (!s.name.empty()) w.key("name", tomlString(s.name));
        w.key("position", vec(s.position), "[m]");
        w.key("placement", tomlString(s.placement));
        w.key("width", tomlNumber(s.width), "[m]");
        if (s.widthEnd) w.key("width_end", tomlNumber(*s.widthEnd), "[m]");
        w.key("interval", tomlNumber(s.interval), "[s]");
        w.key("from", tomlNumber(s.from), "[s]");
        w.key("to", tomlNumber(s.to), "[s]");
        for (const auto& [k, v] : insertKeys(s.insert)) w.key(k, v);
    }
    for (const auto& o : m.outlets) {
        w.section("[[outlet]]");
        if (!o.name.empty()) w.key("name", tomlString(o.name));
        if (o.isRegion) {
            w.key("region",
                  fmt::format("[{}, {}, {}, {}]", tomlNumber(o.xmin), tomlNumber(o.ymin), tomlNumber(o.xmax),
                              tomlNumber(o.ymax)),
                  "[m]");
            w.key("remove", tomlString(o.removeInside ? "inside" : "outside"));
        } else {
            w.key("edge", fmt::format("[{}, {}]", vec(o.a), vec(o.b)), "[m]");
        }
        if (o.openAt != 0) w.key("open_at", tomlNumber(o.openAt), "[s]");
        if (!o.material.empty()) w.key("material", tomlString(o.material));
    }
    if (m.gravity.present) {
        const auto& g = m.gravity;
        w.section("[gravity]");
        w.key("type", tomlString(g.type));
        w.key("magnitude", pair(g.g1, g.g2), "[m/s^2] g1, g2");
        w.key("window", pair(g.t1, g.t2), "[s]");
        w.key("steps", tomlNumber(g.steps));
        w.key("ramp", tomlNumber(g.ramp));
        w.key("direction", pair(g.direction1, g.direction2), "[rad]");
        w.key("tilt_window", pair(g.tilt1, g.tilt2), "[s]");
    }
    if (m.sizeScaling.present) {
        const auto& z = m.sizeScaling;
        w.section("[size_scaling]");
        w.key("amplitude", tomlNumber(z.amplitude));
        w.key("frequency", tomlNumber(z.frequency), "[1/s]");
        w.key("slope", tomlNumber(z.slope));
        w.key("window", pair(z.t1, z.t2), "[s]");
    }
    for (const auto& c : m.changes) {
        w.section("[[change]]");
        w.key("at", tomlNumber(c.at), "[s]");
        w.key("contact", std::to_string(c.contact));
        w.key("set", lawParams(c.set));
    }
}

void unsupported(bool present, const char* what) {
    if (present)
        throw std::invalid_argument(fmt::format(
            "scene TOML writer: {} cannot be written (only the Defs of the cfddem input files)", what));
}

/// `p` (relative to `from`'s folder unless absolute) as seen from the folder `to`.
std::string rebase(const std::string& p, const fs::path& fromDir, const fs::path& toDir) {
    const fs::path path(p);
    if (path.is_absolute()) return p;
    const fs::path abs = fs::absolute(fromDir / path).lexically_normal();
    const fs::path rel = abs.lexically_relative(fs::absolute(toDir).lexically_normal());
    return rel.empty() ? abs.string() : rel.string();
}

}  // namespace

std::string sceneToToml(const model::SceneDef& sc, const std::string& tomlPath,
                        const std::vector<std::string>& header) {
    unsupported(sc.run.engine != "dem" || sc.run.dimension != 2, "an engine other than 2D dem");
    const auto& m = sc.machines;
    const bool restartState =
        !sc.rememberedContacts.empty() ||
        std::any_of(sc.particles.begin(), sc.particles.end(), [](const auto& p) { return !p.gear.empty(); });
    if (restartState)
        throw std::invalid_argument(
            "the scene holds a gc2d restart state (a gso's ACCELERATION and PC_ derivatives, a gci's "
            "contacts), "
            "which TOML has no keys for; run the gso itself (granulab run scene.gso.gsi)");

    Writer w;
    for (const auto& h : header) w.comment(h);

    w.section("[run]");
    if (!sc.run.title.empty()) w.key("title", tomlString(sc.run.title));
    if (sc.run.seed != model::RunDef{}.seed)  // TOML integers are signed: the reader casts back
        w.key("seed", std::to_string(static_cast<std::int64_t>(sc.run.seed)));
    if (sc.run.startTime != 0)
        w.key("start_time", tomlNumber(sc.run.startTime), "[s] the clock at the start");
    w.key("end_time", tomlNumber(sc.run.endTime), "[s] simulated end time");
    if (sc.run.benchmarkFrom != model::RunDef{}.benchmarkFrom)
        w.key("benchmark_from", tomlNumber(sc.run.benchmarkFrom), "[s]");
    if (sc.run.threads != model::RunDef{}.threads) w.key("threads", std::to_string(sc.run.threads));
    if (sc.run.loadBalance != model::RunDef{}.loadBalance) w.key("load_balance", boolean(sc.run.loadBalance));

    const model::DemDef dd;
    const auto& dem = sc.dem;
    w.section("[dem]");
    w.key("dt", tomlNumber(dem.dt), "[s] time step");
    w.key("integrator", tomlString(dem.integrator));
    if (dem.integrator == "pc") {
        w.key("pc_tolerance", tomlNumber(dem.pcTolerance), "[m/s^2] corrector convergence threshold");
        w.key("pc_iterations", std::to_string(dem.pcIterations), "[-] 0: modified explicit Euler");
        w.key("pc_corrector", tomlNumber(dem.pcCorrector), "[-] relaxation factor c");
    }
    if (dem.gearC0 != dd.gearC0) w.key("gear_c0", tomlNumber(dem.gearC0));
    if (dem.broadPhase != dd.broadPhase) w.key("broad_phase", tomlString(dem.broadPhase));
    if (dem.skin != dd.skin) w.key("skin", tomlNumber(dem.skin), "[m]");
    if (dem.sortEvery != dd.sortEvery) w.key("sort_every", std::to_string(dem.sortEvery));
    w.key("mass_model", tomlString(dem.massModel), dem.massModel == "sphere" ? "m = 4/3 pi r^3 rho" : "");
    w.key("overlap_guard", boolean(dem.overlapGuard), "skip pair contacts deeper than 1 % of the radius");
    w.key("gravity", vec(dem.gravity), "[m/s^2]");
    w.key("weight", boolean(dem.weight), "m g on every particle");
    w.key("particle_contacts", boolean(dem.particleContacts));
    w.key("wall_contacts", boolean(dem.wallContacts));
    for (const auto& dw : dem.damping) {
        w.section("[[dem.damping]]");
        w.key("gamma", tomlNumber(dw.gamma), "[kg/s]");
        w.key("gamma_rotation", tomlNumber(dw.gammaRotation), "[kg m^2/s]");
        w.key("from", tomlNumber(dw.from), "[s]");
        w.key("to", tomlNumber(dw.to), "[s]");
    }

    for (const auto& mat : sc.materials) {
        w.section("[[material]]");
        w.key("name", tomlString(mat.name));
        if (mat.density != 0)
            w.key("density", tomlNumber(mat.density), dem.massModel == "sphere" ? "[kg/m^3]" : "[kg/m^2]");
        if (mat.youngsModulus != 0) w.key("youngs_modulus", tomlNumber(mat.youngsModulus), "[Pa]");
        w.key("poisson", tomlNumber(mat.poisson), "[-]");
    }

    for (const auto& c : sc.contacts) {
        w.section("[[contact]]");
        w.key("materials", fmt::format("[{}, {}]", tomlString(c.materialA), tomlString(c.materialB)));
        w.key("normal", tomlString(c.normal));
        w.key("damping", tomlString(c.damping));
        w.key("tangential", tomlString(c.tangential));
        w.key("rolling", tomlString(c.rolling));
        for (const auto& [key, p] : c.params) {
            const std::string unit = key == "k_r" ? "[N]" : key == "kn" || key == "kt" ? "[N/m]" : "";
            w.key(key, p.isBool ? boolean(p.value != 0) : tomlNumber(p.value), unit);
        }
    }

    for (const auto& sh : sc.shapes) writeShape(w, sh);

    for (const auto& p : sc.particles) {
        w.section("[[particle]]");
        if (p.shape != "disk") w.key("shape", tomlString(p.shape));
        w.key("position", vec(p.position), "[m]");
        w.key("velocity", vec(p.velocity), "[m/s]");
        w.key("angle", tomlNumber(p.angle), "[rad]");
        w.key("omega", tomlNumber(p.omega), "[rad/s]");
        if (p.shape == "disk") w.key("radius", tomlNumber(p.radius), "[m]");
        w.key("material", tomlString(p.material));
    }

    for (const auto& b : sc.blocks) writeBlock(w, b, sc.shapes);
    for (const auto& h : sc.heaps) writeHeap(w, h);
    for (const auto& wall : sc.walls) writeWall(w, wall);
    for (const auto& sp : sc.springs) writeSpring(w, sp);
    writeMachines(w, m);

    for (const auto& b : m.boundaries) {
        w.section("[[boundary]]");
        if (!b.name.empty()) w.key("name", tomlString(b.name));
        std::string points = "[";
        for (std::size_t k = 0; k < b.points.size(); ++k) points += (k ? ", " : "") + vec(b.points[k]);
        w.key("points", points + "]", "[m]");
        std::string edges = "[";
        for (std::size_t k = 0; k < b.edges.size(); ++k)
            edges += fmt::format("{}[{}, {}, {}]", k ? ", " : "", b.edges[k].from, b.edges[k].to,
                                 tomlString(b.edges[k].type));
        w.key("edges", edges + "]", "point indices from 0");
        if (b.obstacle) w.key("obstacle", "true");
        if (!b.material.empty()) w.key("material", tomlString(b.material), "wall material");
        const bool inlets =
            std::any_of(b.edges.begin(), b.edges.end(), [](const auto& e) { return e.type == "inlet"; });
        if (inlets || b.rate != 0)
            w.key("rate", tomlNumber(b.rate), "[1/s] particles per second per inlet edge");
        if (inlets) {
            std::string t = "{ ";
            bool first = true;
            for (const auto& [k, v] : insertKeys(b.insert)) {
                t += (first ? "" : ", ") + k + " = " + v;
                first = false;
            }
            w.key("inlet", t + " }", "[m], [m/s], [rad], [rad/s]");
        }
        if (b.openAt != 0) w.key("open_at", tomlNumber(b.openAt), "[s]");
    }

    for (const auto& in : m.inlets) {
        w.section("[[inlet]]");
        if (!in.name.empty()) w.key("name", tomlString(in.name));
        w.key("edge", fmt::format("[{}, {}]", vec(in.a), vec(in.b)), "[m] the domain lies to the right");
        w.key("rate", tomlNumber(in.rate), "[1/s]");
        if (in.from != 0) w.key("from", tomlNumber(in.from), "[s]");
        if (in.to != model::InletDef{}.to) w.key("to", tomlNumber(in.to), "[s]");
        if (!in.inset) w.key("inset", "false");
        for (const auto& [k, v] : insertKeys(in.insert)) {
            const std::string unit = k == "radius"     ? "[m]"
                                     : k == "velocity" ? "[m/s]"
                                     : k == "angle"    ? "[rad]"
                                     : k == "omega"    ? "[rad/s]"
                                                       : "";
            w.key(k, v, unit);
        }
    }

    if (sc.fluid.present) {
        const model::FluidDef fd;
        const auto& f = sc.fluid;
        w.section("[fluid]");
        w.key("density", tomlNumber(f.density), "[kg/m^3] rho_f");
        w.key("drag", tomlString(f.drag));
        w.key("cw", tomlNumber(f.cw), "[-] drag coefficient");
        w.key("buoyancy", boolean(f.buoyancy), "static buoyancy -rho_f V g");
        if (f.viscosity != fd.viscosity) w.key("viscosity", tomlNumber(f.viscosity), "[Pa s]");
        if (!(f.velocity == fd.velocity)) w.key("velocity", vec(f.velocity), "[m/s] uniform velocity");
        if (!f.fields.empty()) {
            const fs::path fromDir = fs::path(sc.path).parent_path();
            const fs::path toDir = fs::path(tomlPath).parent_path();
            std::string list = "[";
            for (std::size_t k = 0; k < f.fields.size(); ++k)
                list += (k ? ", " : "") + tomlString(rebase(f.fields[k], fromDir, toDir));
            w.key("fields", list + "]", "CFD files, relative to this file");
        }
        w.key("timing", tomlString(f.timing));
        if (f.timeInterpolation != fd.timeInterpolation)
            w.key("time_interpolation", boolean(f.timeInterpolation));
        if (f.velocityArray != fd.velocityArray) w.key("velocity_array", tomlString(f.velocityArray));
        if (f.pressureArray != fd.pressureArray) w.key("pressure_array", tomlString(f.pressureArray));
        if (f.data != fd.data) w.key("data", tomlString(f.data));
        if (f.interpolation != fd.interpolation) w.key("interpolation", tomlString(f.interpolation));
        if (f.outside != fd.outside) w.key("outside", tomlString(f.outside));
        if (f.shepardNodes != fd.shepardNodes) w.key("shepard_nodes", std::to_string(f.shepardNodes));
        if (f.shepardPower != fd.shepardPower) w.key("shepard_power", tomlNumber(f.shepardPower));
        if (f.pressureGradient != fd.pressureGradient)
            w.key("pressure_gradient", boolean(f.pressureGradient));
        if (f.pressure != fd.pressure) w.key("pressure", tomlString(f.pressure));
        if (f.depth != fd.depth) w.key("depth", tomlNumber(f.depth), "[m]");
        if (f.voidageCell != fd.voidageCell) w.key("voidage_cell", tomlNumber(f.voidageCell), "[m]");
        if (f.checkMargin != fd.checkMargin) w.key("check_margin", tomlNumber(f.checkMargin), "[m]");
    }

    if (sc.attraction.present) {
        w.section("[attraction]");
        w.key("constant", tomlNumber(sc.attraction.constant), "[m^3/(kg s^2)] G");
        if (sc.attraction.cutoff != 0) w.key("cutoff", tomlNumber(sc.attraction.cutoff), "[m]");
    }

    const model::OutputDef od;
    const auto& o = sc.output;
    w.section("[output]");
    w.key("series_interval", tomlNumber(o.seriesInterval), "[s] series.csv rows (0: about 100)");
    w.key("snapshot_interval", tomlNumber(o.snapshotInterval), "[s] VTK snapshots (0: first and last)");
    if (o.checkpointInterval != od.checkpointInterval)
        w.key("checkpoint_interval", tomlNumber(o.checkpointInterval), "[s]");
    w.key("vtk", boolean(o.vtk));
    if (o.contacts != od.contacts) w.key("contacts", boolean(o.contacts));
    w.key("particle_series", boolean(o.particleSeries), "the nine CSV/ per-particle series");
    if (!o.analyses.empty()) {
        std::string list = "[";
        for (std::size_t k = 0; k < o.analyses.size(); ++k)
            list += (k ? ", " : "") + tomlString(o.analyses[k]);
        w.key("analyses", list + "]");
    }
    const model::Gc2dOutputDef gd;
    if (o.gc2d.enabled) w.key("gc2d", "true", "gc2d's legacy files");
    if (o.gc2d.basename != gd.basename) w.key("gc2d_basename", tomlString(o.gc2d.basename));
    if (o.gc2d.nextDataNumber != gd.nextDataNumber)
        w.key("gc2d_next_data_number", std::to_string(o.gc2d.nextDataNumber));
    if (o.gc2d.nextSetupNumber != gd.nextSetupNumber)
        w.key("gc2d_next_setup_number", std::to_string(o.gc2d.nextSetupNumber));
    if (o.gc2d.setupInterval != gd.setupInterval)
        w.key("gc2d_setup_interval", tomlNumber(o.gc2d.setupInterval), "[s] numbered gso/gco");
    if (o.gc2d.lineInterval != gd.lineInterval)
        w.key("gc2d_line_interval", tomlNumber(o.gc2d.lineInterval), "[s] gpl lines");
    return w.text();
}

}  // namespace granulab::io
