// SPDX-License-Identifier: MIT
// SceneDef -> gsi text (io/gsi_writer.hpp), the inverse of io/gsi_scene.cpp (gc2d spec 9.3).
#include "io/gsi_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/ascii_case.hpp"
#include "core/float_preimage.hpp"

namespace granulab::io {

namespace {

constexpr Real kGc2dInfinity = 4294967295.0;  ///< gc2d's BIG_NUMBER (gstd.h): "never"
constexpr Real kArealDensity = 5000;          ///< [kg/m^2] the grains of a gsi scene (io/gsi_scene.cpp)

/// A time that gc2d writes as BIG_NUMBER when it means "never".
std::string gsiTime(Real t) {
    return t >= 1e300 ? gsiNumber(kGc2dInfinity) : gsiNumber(t);
}

class GsiText {
public:
    void line(const std::string& s) { m_text += s + "\n"; }
    void key(const std::string& keyword, std::initializer_list<Real> numbers) {
        std::string s = keyword;
        for (const Real v : numbers) {
            s += ' ';
            s += gsiNumber(v);
        }
        line(s);
    }
    void pair(const std::string& keyword, Vec2 v) { key(keyword, {v.x, v.y}); }
    void word(const std::string& keyword, const std::string& w) { line(keyword + " " + w); }
    void corners(const std::vector<Vec2>& c) {
        line("CORNERS");
        for (const Vec2& p : c) line(gsiNumber(p.x) + " " + gsiNumber(p.y));
        line("END");
    }
    const std::string& text() const { return m_text; }

private:
    std::string m_text;
};

/// Collects every element that gsi cannot express.
class Problems {
public:
    void check(bool ok, const std::string& what) {
        if (!ok) m_list.push_back(what);
    }
    void throwIfAny() const {
        if (m_list.empty()) return;
        std::string msg = "the scene uses what gsi cannot express (gsi holds gc2d's elements only):";
        for (const auto& p : m_list) msg += "\n  - " + p;
        throw std::invalid_argument(msg);
    }

private:
    std::vector<std::string> m_list;
};

/// The whole number of steps n of an interval [s]; BIG_NUMBER for 0 (never).
Real stepsOf(Real interval, Real dt, const char* key, Problems& problems) {
    if (interval == 0) return kGc2dInfinity;
    const Real n = std::round(interval / dt);
    // The engine rounds an interval to whole steps (dem/step_clock.hpp): n dt may differ from it
    // in the last bit and still give the same steps.
    problems.check(n >= 1 && std::abs(interval / dt - n) < 1e-9 * n,
                   fmt::format("{} = {} s is not a whole number of steps of dt = {} s", key, interval, dt));
    return n;
}

const model::ShapeDef* shapeNamed(const model::SceneDef& sc, const std::string& name) {
    const auto it =
        std::find_if(sc.shapes.begin(), sc.shapes.end(), [&](const auto& s) { return s.name == name; });
    return it == sc.shapes.end() ? nullptr : &*it;
}

void general(const model::SceneDef& sc, GsiText& g, Problems& problems) {
    const auto& dem = sc.dem;
    const model::DemDef dd;
    problems.check(sc.run.engine == "dem" && sc.run.dimension == 2, "run.engine must be the 2D dem");
    problems.check(dem.integrator == "gear",
                   fmt::format("dem.integrator = \"{}\" (gsi: gear)", dem.integrator));
    problems.check(dem.broadPhase == "sort_and_sweep",
                   fmt::format("dem.broad_phase = \"{}\" (gsi: sort_and_sweep)", dem.broadPhase));
    problems.check(dem.massModel == "disk", "dem.mass_model = \"sphere\" (gsi: areal masses)");
    problems.check(dem.gearC0 == dd.gearC0 && dem.skin == dd.skin && dem.sortEvery == dd.sortEvery &&
                       !dem.overlapGuard && dem.weight && dem.particleContacts && dem.wallContacts &&
                       dem.damping.empty(),
                   "[dem] settings besides dt, gravity and the gc2d defaults (gear_c0, skin, sort_every, "
                   "overlap_guard, weight, particle_contacts, wall_contacts, [[dem.damping]])");
    const bool materials = sc.materials.size() == 2 && sc.materials[0].name == "grain" &&
                           sc.materials[0].density == kArealDensity && sc.materials[1].name == "wall" &&
                           sc.materials[1].density == 0 && sc.materials[0].youngsModulus == 0 &&
                           sc.materials[0].poisson == 0 && sc.materials[1].youngsModulus == 0 &&
                           sc.materials[1].poisson == 0;
    problems.check(materials,
                   "[[material]]: gsi knows two, \"grain\" (areal density 5000 kg/m^2) and \"wall\" (no "
                   "density), in that order");
    const model::ContactDef* law = sc.contacts.size() == 1 ? &sc.contacts[0] : nullptr;
    const bool lawOk = law && law->materialA == "*" && law->materialB == "*" && law->normal == "area" &&
                       law->damping == "gamma" && law->tangential == "gc2d" && law->rolling == "none" &&
                       law->params.size() == 4 && law->params.count("E") && law->params.count("cohesion") &&
                       law->params.count("gamma") && law->params.count("mu");
    problems.check(
        lawOk,
        "[[contact]]: gsi has one law for every pair, [\"*\", \"*\"] normal \"area\" (E, cohesion), "
        "damping \"gamma\" (gamma), tangential \"gc2d\" (mu), no rolling");

    g.key("DELTA_T", {dem.dt});
    g.key("TIME", {sc.run.startTime, sc.run.endTime});
    if (lawOk) {
        g.key("E_MODUL", {law->params.at("E").value});
        g.key("COHESION", {law->params.at("cohesion").value});
        g.key("GAMMA", {law->params.at("gamma").value});
        g.key("MUE_STATISCH", {law->params.at("mu").value});
    }
    const auto& v = sc.machines.gravity;
    if (v.present) {
        problems.check(dem.gravity == Vec2{0, 0}, "dem.gravity beside a [gravity] schedule");
        problems.check(
            v.direction1 == -kPi / 2 && v.direction2 == -kPi / 2 && v.tilt1 == v.t1 && v.tilt2 == v.t2,
            "[gravity] direction or tilt_window (gsi's variable g points down)");
        g.key("G", {v.g1, v.g2});
        g.key("G_TIME", {v.t1, v.t2});
        g.key("G_PARAMETER", {v.steps, v.ramp});
        g.word("G_TYPE", asciiUpper(v.type));
    } else {
        problems.check(dem.gravity.x == 0, "dem.gravity with an x component (gsi's g points down)");
        g.key("G", {-dem.gravity.y});
    }
    if (const auto& h = sc.machines.sizeScaling; h.present) {
        g.line("HEAT_TIME " + gsiTime(h.t1) + " " + gsiTime(h.t2));
        g.key("HEAT_AMPLITUDE", {h.amplitude});
        g.key("HEAT_FREQUENCE", {h.frequency});
        g.key("HEAT_SLOPE", {h.slope});
    }
    const auto& out = sc.output;
    problems.check(
        out.snapshotInterval == out.seriesInterval,
        "output.snapshot_interval differs from output.series_interval (gsi: STEPS_DATA sets both)");
    g.key("STEPS_DATA", {stepsOf(out.seriesInterval, dem.dt, "output.series_interval", problems)});
    g.key("STEPS_CHECKPOINT",
          {stepsOf(out.checkpointInterval, dem.dt, "output.checkpoint_interval", problems)});
    g.key("STEPS_SETUP", {stepsOf(out.gc2d.setupInterval, dem.dt, "output.gc2d_setup_interval", problems)});
    g.key("STEPS_DUMPLINE", {stepsOf(out.gc2d.lineInterval, dem.dt, "output.gc2d_line_interval", problems)});
    g.key("NEXT_DATA_FILENUMBER", {static_cast<Real>(out.gc2d.nextDataNumber)});
    g.key("NEXT_SETUP_FILENUMBER", {static_cast<Real>(out.gc2d.nextSetupNumber)});
    g.key("SEED", {static_cast<Real>(sc.run.seed >> 32), static_cast<Real>(sc.run.seed & 0xffffffffULL)});
    const std::string& title = sc.run.title;
    const bool oneWord = !title.empty() && title.find_first_of(" \t") == std::string::npos;
    g.word("BASENAME", oneWord ? title : out.gc2d.basename);
}

void wall(const model::WallDef& w, std::size_t k, GsiText& g, Problems& problems) {
    const model::WallDef d;
    const std::string name = fmt::format("wall {} ('{}')", k, w.name);
    problems.check(w.kind == "polygon" && w.closed,
                   name + ": gsi walls are convex polygons (kind \"polygon\")");
    problems.check(w.material == "wall", name + ": material must be \"wall\"");
    problems.check(
        w.velocity == d.velocity && w.omega == 0 && !w.pivot && w.pistonGain == 0 && w.pistonFrom == 0,
        name + ": velocity, omega, pivot, piston_gain and piston_from have no gsi keyword");
    g.line("");
    g.line("WALL");
    if (w.gc2dId >= 0) g.key("ID", {static_cast<Real>(w.gc2dId)});
    g.corners(w.points);
    if (!(w.offset == d.offset)) g.pair("OFFSET", w.offset);
    if (w.angle != 0) g.key("ANGLE", {-w.angle});  // gc2d turns clockwise
    if (!(w.surfaceVelocity == d.surfaceVelocity)) g.pair("VELOCITY", w.surfaceVelocity);
    if (w.pistonForce) {
        problems.check(*w.pistonForce != 0, name + ": piston_force = 0 (gsi: no piston)");
        g.key("PISTON_FORCE", {*w.pistonForce});
        g.key("PISTON_ANGLE", {w.pistonDirection});
        g.key("PISTON_V_MAX", {w.pistonMaxSpeed});
    }
    if (!w.vibType.empty()) {
        g.word("VIB_TYPE", w.vibType == "cosine" ? "COSINUS" : asciiUpper(w.vibType));
        g.key("VIB_ANGLE", {w.vibDirection});
        g.key("VIB_WIDTH", {w.vibWidth});
        g.key("VIB_FREQUENCE", {w.vibFrequency});
        g.line("VIB_TIME " + gsiNumber(w.vibFrom) + " " + gsiTime(w.vibTo));
    }
}

void spring(const model::SpringDef& s, GsiText& g) {
    g.key("DRAG_K", {s.stiffness});
    g.pair("DRAG_FIXING_POINT", s.attach);
    g.pair("DRAG_PULLING_POINT", s.pullStart);
    g.key("DRAG_VELOCITY", {s.speed});
    g.key("DRAG_ANGLE", {s.direction});
    g.key("DRAG_TIME", {s.from, s.to});
}

void particle(const model::SceneDef& sc, std::size_t k, GsiText& g, Problems& problems) {
    const model::ParticleDef& p = sc.particles[k];
    const model::ShapeDef* shape = shapeNamed(sc, p.shape);
    const std::string name = fmt::format("particle {}", k);
    problems.check(
        shape && shape->kind == "polygon" && shape->rotation == 0 && shape->rotationMode == "const",
        name +
            ": gsi particles are polygons given by their corners (a [[shape]] of kind "
            "\"polygon\" without rotation)");
    problems.check(p.material == "grain", name + ": material must be \"grain\"");
    g.line("");
    g.line("PARTICLE");
    if (p.gc2dId >= 0) g.key("ID", {static_cast<Real>(p.gc2dId)});
    if (shape) g.corners(shape->corners);
    g.pair("COM", p.position);
    if (p.angle != 0) g.key("ANGLE", {-p.angle});  // gc2d turns clockwise
    if (!(p.velocity == Vec2{0, 0})) g.pair("VELOCITY", p.velocity);
    if (p.omega != 0) g.key("OMEGA", {-p.omega});
    if (p.gear.size() == model::ParticleDef::kGearValues) {  // a gso: the Gear predictor's state
        // r2..r5 of x, then y, then phi: scaled derivatives r_n = dt^n/n! d^n/dt^n [m], [rad]
        // (dem/integrator.hpp); r2 as the acceleration gc2d writes, r3..r5 as they are.
        const auto& r = p.gear;
        // The reader's r2 = a * (dt dt / 2) (io/gsi_scene.cpp): `a` is chosen to give r2 exactly.
        const Real half = sc.dem.dt * sc.dem.dt / 2;
        g.key("ACCELERATION", {preimageOfProduct(r[0], half), preimageOfProduct(r[4], half)});
        g.key("OMEGA_DOT", {-preimageOfProduct(r[8], half)});
        g.key("PC_TRANS3", {r[1], r[5]});
        g.key("PC_TRANS4", {r[2], r[6]});
        g.key("PC_TRANS5", {r[3], r[7]});
        g.key("PC_ROT3", {-r[9]});
        g.key("PC_ROT4", {-r[10]});
        g.key("PC_ROT5", {-r[11]});
    }
    std::size_t springs = 0;
    for (const auto& s : sc.springs)
        if (s.particle == static_cast<std::int64_t>(k)) {
            if (++springs == 1) spring(s, g);
        }
    problems.check(springs <= 1, name + ": gsi holds one DRAG spring per particle");
}

/// The shape keywords of GENERATE_BLOCK and DROPSOURCE (a grain shape).
void grainKeys(const model::ShapeDef* s, const std::string& name, GsiText& g, Problems& problems) {
    problems.check(s && s->kind == "grain" && !s->fullAxes,
                   name + ": gsi generates random grains (a [[shape]] of kind \"grain\", semi-axes)");
    if (!s) return;
    g.pair("PART_SIZE", s->size);
    g.key("PART_VAR_SIZE", {s->sizeVariation});
    g.word("RANDOM_SIZE", asciiUpper(s->sizeMode));
    g.key("PART_NUM_CORNERS", {static_cast<Real>(s->cornerCount)});
    g.key("PART_VAR_CORNERS", {static_cast<Real>(s->cornerVariation)});
    g.word("RANDOM_NUM_CORNERS", asciiUpper(s->cornerCountMode));
    g.word("PART_RANDOM_POS_CORNERS", asciiUpper(s->cornerAngles));
    g.key("PART_ROT", {-s->rotation});  // gc2d turns clockwise
    g.word("RANDOM_ROT", asciiUpper(s->rotationMode));
}

void block(const model::SceneDef& sc, std::size_t k, GsiText& g, Problems& problems) {
    using L = model::BlockDef::Lattice;
    using J = model::BlockDef::Jitter;
    const model::BlockDef& b = sc.blocks[k];
    const model::BlockDef d;
    const std::string name = fmt::format("block {}", k);
    problems.check(b.lattice == L::Rect || b.lattice == L::Fcc, name + ": gsi lattices are rect and fcc");
    problems.check(b.material == "grain", name + ": material must be \"grain\"");
    problems.check(b.spacing == d.spacing && !b.origin && b.count == d.count && b.temperature == 0 &&
                       b.velocity == d.velocity && b.jitterFraction == d.jitterFraction,
                   name +
                       ": spacing, origin, count, temperature, velocity and jitter_fraction have no gsi "
                       "keyword");
    g.line("");
    g.line("GENERATE_BLOCK");
    g.key("X_RANGE", {b.xmin, b.xmax});
    g.key("Y_RANGE", {b.ymin, b.ymax});
    g.pair("GRID_DISTANCE", b.grid);
    const std::string jitter = b.jitter == J::Gauss ? "_GAUSS" : b.jitter == J::Equal ? "_EQUAL" : "";
    g.word("GRID_TYPE", fmt::format("{}{}", b.lattice == L::Rect ? "RECT" : "FCC", jitter));
    g.pair("ANGLE_RANGE", b.directionRange);
    g.pair("VELOCITY_RANGE", b.speedRange);
    grainKeys(shapeNamed(sc, b.shape), name, g, problems);
}

void source(const model::SceneDef& sc, std::size_t k, GsiText& g, Problems& problems) {
    const model::SourceDef& s = sc.machines.sources[k];
    const model::InsertDef di;
    const std::string name = fmt::format("source {}", k);
    problems.check(!s.widthEnd, name + ": width_end has no gsi keyword");
    problems.check(s.insert.material == "grain", name + ": material must be \"grain\"");
    problems.check(s.insert.velocity == di.velocity && s.insert.angle == 0 && s.insert.omega == 0 &&
                       s.insert.attempts == di.attempts,
                   name + ": velocity, angle, omega and attempts have no gsi keyword");
    g.line("");
    g.line("DROPSOURCE");
    g.pair("POS", s.position);
    g.word("TYPE", asciiUpper(s.placement));
    g.key("WIDTH", {s.width});
    g.key("DELTA_T", {s.interval});
    g.key("TIME", {s.from, s.to});
    grainKeys(shapeNamed(sc, s.insert.shape), name, g, problems);
}

}  // namespace

std::string gsiNumber(double v) {
    if (v == 0) return "0";  // -0 too: gsi has no signed zero
    return fmt::format("{}", v);
}

std::string sceneToGsi(const model::SceneDef& sc, const std::string& identification) {
    Problems problems;
    GsiText g;
    g.line("PARAMETER v1.4");
    g.line(identification);
    g.line("# granulab scene in gc2d's gsi language (docs/coming-from-gc2d.md); SI units, angles clockwise");
    general(sc, g, problems);
    for (std::size_t k = 0; k < sc.walls.size(); ++k) wall(sc.walls[k], k, g, problems);
    for (std::size_t k = 0; k < sc.particles.size(); ++k) particle(sc, k, g, problems);
    for (std::size_t k = 0; k < sc.blocks.size(); ++k) block(sc, k, g, problems);
    for (std::size_t k = 0; k < sc.machines.sources.size(); ++k) source(sc, k, g, problems);
    for (const auto& s : sc.springs)
        problems.check(
            s.particle >= 0 && s.particle < static_cast<std::int64_t>(sc.particles.size()),
            fmt::format("spring on particle {}: gsi pulls only PARTICLEs, not generated grains", s.particle));
    const auto& m = sc.machines;
    problems.check(sc.heaps.empty(), "[[heap]] (gsi: generate it with a script, docs/coming-from-gc2d.md)");
    problems.check(m.drums.empty(), "[[drum]] (gsi: generate it with a script, docs/coming-from-gc2d.md)");
    problems.check(m.inlets.empty() && m.outlets.empty() && m.boundaries.empty(),
                   "[[inlet]], [[outlet]], [[boundary]] (cfddem elements)");
    problems.check(m.changes.empty(), "[[change]] (gsi: restart with changed GENERAL parameters)");
    problems.check(!sc.fluid.present && !sc.attraction.present, "[fluid], [attraction] (cfddem elements)");
    problems.throwIfAny();
    g.line("");
    g.line("END_OF_FILE");
    return g.text();
}

}  // namespace granulab::io
