// SPDX-License-Identifier: MIT
// SceneDef -> native TOML text (io/scene_toml_writer.hpp).
#include "io/scene_toml_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
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
    unsupported(!sc.shapes.empty(), "[[shape]]");
    unsupported(!sc.blocks.empty(), "[[block]]");
    unsupported(!sc.heaps.empty(), "[[heap]]");
    unsupported(!sc.walls.empty(), "[[wall]]");
    unsupported(!sc.springs.empty(), "[[spring]]");
    unsupported(!sc.dem.damping.empty(), "[[dem.damping]]");
    const auto& m = sc.machines;
    unsupported(!m.drums.empty() || !m.sources.empty() || !m.outlets.empty(),
                "[[drum]], [[source]], [[outlet]]");
    unsupported(m.gravity.present || m.sizeScaling.present || !m.changes.empty(),
                "[gravity], [size_scaling], [[change]]");

    Writer w;
    for (const auto& h : header) w.comment(h);

    w.section("[run]");
    if (!sc.run.title.empty()) w.key("title", tomlString(sc.run.title));
    if (sc.run.seed != model::RunDef{}.seed) w.key("seed", std::to_string(sc.run.seed));
    w.key("end_time", tomlNumber(sc.run.endTime), "[s] simulated end time");
    if (sc.run.benchmarkFrom != model::RunDef{}.benchmarkFrom)
        w.key("benchmark_from", tomlNumber(sc.run.benchmarkFrom), "[s]");

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
    return w.text();
}

}  // namespace granulab::io
