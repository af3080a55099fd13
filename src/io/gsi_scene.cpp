// SPDX-License-Identifier: MIT
// gsi document -> SceneDef (io/gsi_scene.hpp; gc2d spec 9.3).
#include "io/gsi_scene.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/ascii_case.hpp"
#include "io/gci_file.hpp"

namespace granulab::io {

namespace {

constexpr Real kGc2dInfinity = 4294967295.0;  ///< gc2d's BIG_NUMBER, 2^32 - 1 (gstd.h)
constexpr Real kArealDensity = 5000;          ///< [kg/m^2] the thesis's grains (spec 3.9)

/// Reads the entries of one object with their gc2d defaults.
class ObjectReader {
public:
    explicit ObjectReader(const GsiObject& o) : m_object(o) {}

    const GsiEntry* entry(std::string_view key) const noexcept { return m_object.find(key); }
    bool has(std::string_view key) const noexcept { return entry(key) != nullptr; }
    /// The first entry (file order) of a keyword family such as "VIB_", or nullptr.
    const GsiEntry* firstOf(std::string_view prefix) const noexcept {
        for (const GsiEntry& e : m_object.entries)
            if (e.keyword.starts_with(prefix)) return &e;
        return nullptr;
    }
    Real number(std::string_view key, Real fallback, std::size_t k = 0) const {
        const GsiEntry* e = entry(key);
        return e && k < e->numbers.size() ? e->numbers[k] : fallback;
    }
    Vec2 pair(std::string_view key, Vec2 fallback) const {
        const GsiEntry* e = entry(key);
        return e ? Vec2{e->numbers[0], e->numbers[1]} : fallback;
    }
    std::string choice(std::string_view key, std::string fallback) const {
        const GsiEntry* e = entry(key);
        return e ? asciiLower(e->text) : fallback;
    }
    /// The line of `key`, else the object's line.
    SourceLoc loc(std::string_view key) const {
        const GsiEntry* e = entry(key);
        return e ? e->loc : m_object.loc;
    }
    const GsiObject& object() const noexcept { return m_object; }

private:
    const GsiObject& m_object;
};

/// [s] the interval of `steps` steps of dt; 0 (only at the end) for gc2d's infinity.
Real stepsInterval(Real steps, Real dt) {
    return steps >= kGc2dInfinity || steps <= 0 ? 0.0 : steps * dt;
}

/// run.seed of SEED s1 s2: s1 2^32 + s2 when both are whole numbers in [0, 2^32) (so every seed
/// has a SEED line: io/gsi_writer.hpp writes it back), otherwise a hash of both numbers' bits.
std::uint64_t seedOf(Real a, Real b) {
    const auto word = [](Real v) { return v >= 0 && v < 4294967296.0 && v == std::floor(v); };
    if (word(a) && word(b)) return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
    std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a over the bits of both numbers
    for (const Real v : {a, b}) {
        unsigned char bytes[sizeof(Real)];
        std::memcpy(bytes, &v, sizeof v);
        for (const unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
    }
    return h;
}

/// Area centroid of a polygon (corners in order); the mean of the corners if degenerate.
Vec2 centroidOf(const std::vector<Vec2>& c) {
    Real a2 = 0;
    Vec2 s{0, 0};
    for (std::size_t i = 0; i < c.size(); ++i) {
        const Vec2 p = c[i], q = c[(i + 1) % c.size()];
        const Real w = cross(p, q);
        a2 += w;
        s += (p + q) * w;
    }
    if (a2 != 0) return s / (3 * a2);
    Vec2 m{0, 0};
    for (const Vec2& p : c) m += p;
    return c.empty() ? m : m / static_cast<Real>(c.size());
}

class SceneBuilder {
public:
    explicit SceneBuilder(const GsiDocument& doc) : m_doc(doc) {}

    model::SceneDef build() {
        m_scene.path = m_doc.path;
        m_scene.run.engine = "dem";
        general(ObjectReader(m_doc.general()));
        int walls = 0, particles = 0, blocks = 0, sources = 0;
        for (const GsiObject& o : m_doc.objects) {
            const ObjectReader r(o);
            switch (o.kind) {
                case GsiObjectKind::General:
                case GsiObjectKind::Display:  // gc2d's window: not used
                    break;
                case GsiObjectKind::Wall:
                    wall(r, ++walls);
                    break;
                case GsiObjectKind::Particle:
                    particle(r, particles++);
                    break;
                case GsiObjectKind::GenerateBlock:
                    block(r, ++blocks);
                    break;
                case GsiObjectKind::DropSource:
                    source(r, ++sources);
                    break;
            }
        }
        m_diags.throwIfAny();
        return std::move(m_scene);
    }

private:
    void general(const ObjectReader& g) {
        auto& run = m_scene.run;
        run.loc = g.object().loc;
        run.title = g.has("BASENAME") ? g.entry("BASENAME")->text : "default";
        run.seed = seedOf(g.number("SEED", 0, 0), g.number("SEED", 0, 1));
        run.startTime = g.number("TIME", 0, 0);  // t0 > 0: a restart from a gso
        run.endTime = g.number("TIME", 1, 1);
        auto& dem = m_scene.dem;
        dem.loc = g.loc("DELTA_T");
        dem.dt = g.number("DELTA_T", 1e-4);
        dem.integrator = "gear";
        dem.broadPhase = "sort_and_sweep";
        dem.massModel = "disk";
        const GsiEntry* gravity = g.entry("G");
        const Real g1 = gravity ? gravity->numbers[0] : 9.81;
        dem.gravity = {0, -g1};
        if (gravity && gravity->given == 2) {  // variable g (spec 6.6): the schedule alone sets it
            dem.gravity = {0, 0};
            auto& v = m_scene.machines.gravity;
            v.present = true;
            v.loc = gravity->loc;
            v.g1 = g1;
            v.g2 = gravity->numbers[1];
            v.type = g.choice("G_TYPE", "constant");
            v.t1 = g.number("G_TIME", 0, 0);
            v.t2 = g.number("G_TIME", 1, 1);
            v.steps = g.number("G_PARAMETER", 5, 0);
            v.ramp = g.number("G_PARAMETER", 0.5, 1);
            v.tilt1 = v.t1;
            v.tilt2 = v.t2;
        }
        if (const GsiEntry* heat = g.firstOf("HEAT_")) {
            auto& h = m_scene.machines.sizeScaling;
            h.present = true;
            h.loc = g.has("HEAT_TIME") ? g.loc("HEAT_TIME") : heat->loc;
            h.amplitude = g.number("HEAT_AMPLITUDE", 0.01);
            h.frequency = g.number("HEAT_FREQUENCE", 1.0);
            h.slope = g.number("HEAT_SLOPE", 10.0);
            h.t1 = g.number("HEAT_TIME", kGc2dInfinity, 0);
            h.t2 = g.number("HEAT_TIME", kGc2dInfinity, 1);
            if (h.t1 >= kGc2dInfinity) h.t1 = 1e300;
            if (h.t2 >= kGc2dInfinity) h.t2 = 1e300;
            // HEAT_TIME inf inf (its default) is "off": literally t_c = 2^32 - 1 and s != 1, which
            // the spec's audit note (2.4) corrects to s = 1.
            if (h.t1 >= 1e300 && h.t2 >= 1e300) h.present = false;
        }
        for (const char* key : {"STEPS_DATA", "STEPS_CHECKPOINT", "STEPS_SETUP", "STEPS_DUMPLINE"})
            if (const GsiEntry* e = g.entry(key); e && !(e->numbers[0] >= 1))
                m_diags.error(
                    e->loc, key,
                    fmt::format("{} is a number of steps, at least 1 (2^32 - 1 or more: never); got {}", key,
                                e->numbers[0]));
        auto& out = m_scene.output;
        out.loc = g.loc("STEPS_DATA");
        out.seriesInterval = stepsInterval(g.number("STEPS_DATA", 10000), dem.dt);
        out.snapshotInterval = out.seriesInterval;
        out.checkpointInterval = stepsInterval(g.number("STEPS_CHECKPOINT", 10000), dem.dt);
        out.gc2d.enabled = true;  // a gsi scene writes gc2d's files (spec 9.5)
        out.gc2d.basename = std::filesystem::path(run.title).filename().string();
        if (out.gc2d.basename.empty() || out.gc2d.basename == "." || out.gc2d.basename == "..")
            out.gc2d.basename = "default";
        out.gc2d.setupInterval = stepsInterval(g.number("STEPS_SETUP", kGc2dInfinity), dem.dt);
        out.gc2d.lineInterval = stepsInterval(g.number("STEPS_DUMPLINE", kGc2dInfinity), dem.dt);
        for (auto [key, number] : {std::pair{"NEXT_DATA_FILENUMBER", &out.gc2d.nextDataNumber},
                                   std::pair{"NEXT_SETUP_FILENUMBER", &out.gc2d.nextSetupNumber}}) {
            const Real n = g.number(key, 1);
            if (n >= 1 && n <= 9999 && n == std::floor(n))
                *number = static_cast<std::int64_t>(n);
            else
                m_diags.error(
                    g.loc(key), key,
                    fmt::format("{} is the NNNN of the next file name, a whole number in [1, 9999]; "
                                "got {}",
                                key, n));
        }

        model::MaterialDef grain;
        grain.name = "grain";
        grain.density = kArealDensity;
        grain.loc = g.object().loc;
        model::MaterialDef wallMaterial;
        wallMaterial.name = "wall";
        wallMaterial.loc = g.object().loc;
        m_scene.materials = {grain, wallMaterial};
        model::ContactDef law;
        law.materialA = law.materialB = "*";
        law.normal = "area";
        law.damping = "gamma";
        law.tangential = "gc2d";
        law.loc = g.loc("E_MODUL");
        const auto param = [&](const char* name, std::string_view key, Real fallback) {
            law.params[name] = {g.number(key, fallback), false, g.loc(key)};
        };
        param("E", "E_MODUL", 1e7);
        param("cohesion", "COHESION", 0);
        param("gamma", "GAMMA", 0.5);
        param("mu", "MUE_STATISCH", 0.6);
        m_scene.contacts = {law};
    }

    const std::vector<Vec2>* corners(const ObjectReader& r) {
        const GsiEntry* c = r.entry("CORNERS");
        if (!c) {
            m_diags.error(
                r.object().loc, gsiObjectName(r.object().kind),
                fmt::format("a {} needs CORNERS (x y lines up to END)", gsiObjectName(r.object().kind)));
            return nullptr;
        }
        return &c->corners;
    }

    void wall(const ObjectReader& r, int k) {
        const std::vector<Vec2>* c = corners(r);
        if (!c) return;
        model::WallDef w;
        w.name = fmt::format("wall{}", k);
        w.kind = "polygon";
        w.closed = true;
        w.points = *c;
        w.loc = r.entry("CORNERS")->loc;
        w.offset = r.pair("OFFSET", {0, 0});
        w.angle = -r.number("ANGLE", 0);  // gc2d turns clockwise
        w.material = "wall";
        if (const GsiEntry* id = r.entry("ID"))
            w.gc2dId = static_cast<std::int64_t>(std::clamp<Real>(id->numbers[0], -1, 1e15));
        w.surfaceVelocity = r.pair("VELOCITY", {0, 0});
        if (const Real force = r.number("PISTON_FORCE", 0); force != 0) {
            w.pistonForce = force;
            w.pistonDirection = r.number("PISTON_ANGLE", 0);
            w.pistonMaxSpeed = r.number("PISTON_V_MAX", 1);
        }
        if (r.firstOf("VIB_")) {
            const std::string type = r.choice("VIB_TYPE", "cosinus");
            w.vibType = type == "cosinus" ? "cosine" : type;  // sawtooth, tapping, triangle alike
            w.vibDirection = r.number("VIB_ANGLE", kPi / 2);
            w.vibWidth = r.number("VIB_WIDTH", 1);
            w.vibFrequency = r.number("VIB_FREQUENCE", 1);
            w.vibFrom = r.number("VIB_TIME", 0, 0);
            w.vibTo = r.number("VIB_TIME", kGc2dInfinity, 1);
            if (w.vibTo >= kGc2dInfinity) w.vibTo = 1e300;
        }
        m_scene.walls.push_back(std::move(w));
    }

    void particle(const ObjectReader& r, int index) {
        std::vector<Real> gear = restartState(r);
        const std::vector<Vec2>* c = corners(r);
        if (!c) return;
        model::ShapeDef shape;
        shape.name = fmt::format("particle{}", index + 1);
        shape.kind = "polygon";
        shape.corners = *c;
        shape.loc = r.entry("CORNERS")->loc;
        model::ParticleDef p;
        p.shape = shape.name;
        p.position = r.has("POSITION_ABSOLUT") ? centroidOf(*c) : r.pair("COM", {0, 0});
        p.angle = -r.number("ANGLE", 0);  // clockwise in gc2d
        p.omega = -r.number("OMEGA", 0);
        p.velocity = r.pair("VELOCITY", {0, 0});
        p.material = "grain";
        p.loc = r.object().loc;
        p.gear = std::move(gear);
        if (const GsiEntry* id = r.entry("ID"))
            p.gc2dId = static_cast<std::int64_t>(std::clamp<Real>(id->numbers[0], -1, 1e15));
        m_scene.shapes.push_back(std::move(shape));
        m_scene.particles.push_back(std::move(p));
        if (r.firstOf("DRAG_")) {
            model::SpringDef s;
            s.particle = index;  // [[particle]]s come first in generation order
            s.stiffness = r.number("DRAG_K", 100);
            s.attach = r.pair("DRAG_FIXING_POINT", {0, 0});
            s.pullStart = r.pair("DRAG_PULLING_POINT", {0, 0});
            s.speed = r.number("DRAG_VELOCITY", 0.1);
            s.direction = r.number("DRAG_ANGLE", 0);
            s.from = r.number("DRAG_TIME", 0, 0);
            s.to = r.number("DRAG_TIME", 1, 1);
            s.loc = r.loc("DRAG_K");
            m_scene.springs.push_back(s);
        }
    }

    /// The Gear predictor's state of a gso PARTICLE (model::ParticleDef::gear): ACCELERATION and
    /// OMEGA_DOT give r2 = dt^2/2 a, PC_TRANS3-5 and PC_ROT3-5 are r3..r5 as gc2d writes them (scaled,
    /// [m] and [rad], rotations clockwise). Empty when none of them is given.
    std::vector<Real> restartState(const ObjectReader& r) const {
        static const char* const keys[] = {"ACCELERATION", "OMEGA_DOT", "PC_TRANS3", "PC_TRANS4",
                                           "PC_TRANS5",    "PC_ROT3",   "PC_ROT4",   "PC_ROT5"};
        if (std::none_of(std::begin(keys), std::end(keys), [&](const char* k) { return r.has(k); }))
            return {};
        const Real dt = m_scene.dem.dt, half = dt * dt / 2;
        std::vector<Real> g(model::ParticleDef::kGearValues, 0.0);
        g[0] = r.number("ACCELERATION", 0, 0) * half;
        g[4] = r.number("ACCELERATION", 0, 1) * half;
        g[8] = -r.number("OMEGA_DOT", 0) * half;
        for (int n = 3; n <= 5; ++n) {
            const std::string trans = fmt::format("PC_TRANS{}", n), rot = fmt::format("PC_ROT{}", n);
            g[static_cast<std::size_t>(n - 2)] = r.number(trans, 0, 0);
            g[static_cast<std::size_t>(4 + n - 2)] = r.number(trans, 0, 1);
            g[static_cast<std::size_t>(8 + n - 2)] = -r.number(rot, 0);
        }
        return g;
    }

    /// The random grain of GENERATE_BLOCK and DROPSOURCE, with the object's defaults.
    model::ShapeDef grain(const ObjectReader& r, std::string name, Vec2 size, Real sizeVariation,
                          Real corners) {
        model::ShapeDef s;
        s.name = std::move(name);
        s.kind = "grain";
        s.size = r.pair("PART_SIZE", size);
        s.sizeVariation = r.number("PART_VAR_SIZE", sizeVariation);
        s.sizeMode = r.choice("RANDOM_SIZE", "const");
        // Clamped before the cast (a huge count is then refused by the shape checks, not undefined).
        const auto whole = [](Real v) { return static_cast<std::int64_t>(std::clamp<Real>(v, -1e15, 1e15)); };
        s.cornerCount = whole(r.number("PART_NUM_CORNERS", corners));
        s.cornerVariation = whole(r.number("PART_VAR_CORNERS", 2));
        s.cornerCountMode = r.choice("RANDOM_NUM_CORNERS", "const");
        s.cornerAngles = r.choice("PART_RANDOM_POS_CORNERS", "regular");
        s.rotation = -r.number("PART_ROT", 0);  // clockwise in gc2d
        s.rotationMode = r.choice("RANDOM_ROT", "const");
        s.loc = r.object().loc;
        return s;
    }

    void block(const ObjectReader& r, int k) {
        model::ShapeDef shape = grain(r, fmt::format("block{}", k), {1, 1}, 0.5, 6);
        model::BlockDef b;
        b.shape = shape.name;
        const std::string type = r.choice("GRID_TYPE", "fcc");
        b.lattice =
            type.rfind("rect", 0) == 0 ? model::BlockDef::Lattice::Rect : model::BlockDef::Lattice::Fcc;
        b.jitter = type.ends_with("_gauss")   ? model::BlockDef::Jitter::Gauss
                   : type.ends_with("_equal") ? model::BlockDef::Jitter::Equal
                                              : model::BlockDef::Jitter::None;
        b.xmin = r.number("X_RANGE", 0, 0);
        b.xmax = r.number("X_RANGE", 10, 1);
        b.ymin = r.number("Y_RANGE", 0, 0);
        b.ymax = r.number("Y_RANGE", 10, 1);
        b.grid = r.pair("GRID_DISTANCE", {2, 2});
        b.directionRange = r.pair("ANGLE_RANGE", {0, 2 * kPi});
        b.speedRange = r.pair("VELOCITY_RANGE", {0, 0});
        b.material = "grain";
        b.loc = r.object().loc;
        m_scene.shapes.push_back(std::move(shape));
        m_scene.blocks.push_back(std::move(b));
    }

    void source(const ObjectReader& r, int k) {
        model::ShapeDef shape = grain(r, fmt::format("source{}", k), {0.01, 0.01}, 0.1, 8);
        model::SourceDef s;
        s.name = fmt::format("source{}", k);
        s.position = r.pair("POS", {0, 0.01});
        s.placement = r.choice("TYPE", "abs");
        s.width = r.number("WIDTH", 0);
        s.interval = r.number("DELTA_T", 0.1);
        s.from = r.number("TIME", 0, 0);
        s.to = r.number("TIME", 1, 1);
        s.insert.shape = shape.name;
        s.insert.material = "grain";
        s.loc = r.object().loc;
        m_scene.shapes.push_back(std::move(shape));
        m_scene.machines.sources.push_back(std::move(s));
    }

    const GsiDocument& m_doc;
    model::SceneDef m_scene;
    Diagnostics m_diags;
};

}  // namespace

bool isGsiPath(const std::string& path) {
    const std::string l = asciiLower(path);
    return l.ends_with(".gsi") || l.ends_with(".gsi.gz");
}

model::SceneDef gsiToScene(const GsiDocument& doc) {
    return SceneBuilder(doc).build();
}

model::SceneDef readGsiFile(const std::string& path) {
    std::string text;
    if (asciiLower(path).ends_with(".gz")) {  // gzip (gc2d: gunzip first); zlib reads it directly
        gzFile in = gzopen(path.c_str(), "rb");
        if (!in)
            throw SceneError(
                makeDiagnostic(path, 0, "", "cannot open the gsi scene file (missing or unreadable)"));
        char buffer[1 << 16];
        int n = 0;
        while ((n = gzread(in, buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<std::size_t>(n));
        int code = Z_OK;
        const std::string reason = n < 0 ? gzerror(in, &code) : "";
        gzclose(in);
        if (n < 0)
            throw SceneError(
                makeDiagnostic(path, 0, "", fmt::format("not a readable gzip file: {}", reason)));
    } else {
        std::ifstream in(path, std::ios::binary);
        if (!in)
            throw SceneError(
                makeDiagnostic(path, 0, "", "cannot open the gsi scene file (missing or unreadable)"));
        std::stringstream s;
        s << in.rdbuf();
        text = s.str();
    }
    const GsiDocument doc = parseGsi(text, path);
    model::SceneDef scene = gsiToScene(doc);
    const std::string gci = gciPathFor(path);
    std::error_code ec;
    if (std::filesystem::exists(gci, ec)) {  // a restart: the contacts of the gco it was renamed from
        std::ifstream in(gci, std::ios::binary);
        if (!in)
            throw SceneError(makeDiagnostic(gci, 0, "", "cannot open the gci contact file (unreadable)"));
        std::stringstream s;
        s << in.rdbuf();
        GciDocument contacts = parseGci(s.str(), gci);
        if (contacts.identification != doc.identification)
            throw SceneError(makeDiagnostic(
                gci, 2, "identification",
                fmt::format("'{}' does not match line 2 of {} ('{}'): the gci belongs to another gsi (gc2d "
                            "writes a gso and its gco with the same identification; rename both together)",
                            contacts.identification, path, doc.identification)));
        scene.rememberedContacts = std::move(contacts.contacts);
    }
    return scene;
}

}  // namespace granulab::io
