// SPDX-License-Identifier: MIT
// The gsi corpus (gc2d spec 9.2-9.3; docs/coming-from-gc2d.md). tests/data/gsi holds at least 15
// scenes, the thesis's sample of App. B.1.8 (piston.gsi) among them, which together use every
// keyword of every object and every choice value the spec lists. Each file maps onto the SceneDef
// values derived by hand from the spec and the mapping tables of docs/coming-from-gc2d.md, and the
// dem engine accepts it. tests/data/gsi/bad holds malformed files; each names, in lines
// "# expect LINE: TEXT", the error it must give: a SceneError at file:LINE whose message holds
// TEXT (the command line's exit status 2 is checked in tests/app/test_gsi_cli.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "app/dem/dem_engine.hpp"
#include "dem/generate.hpp"
#include "dem/machine_setup.hpp"
#include "dem/schedules.hpp"
#include "io/gsi_scene.hpp"
#include "io/gsi_syntax.hpp"

using granulab::kPi;
using granulab::Real;
using granulab::SceneError;
using granulab::Vec2;
using granulab::io::GsiDocument;
using granulab::io::GsiObjectKind;
using granulab::io::parseGsi;
using granulab::model::BlockDef;
using granulab::model::SceneDef;
namespace fs = std::filesystem;

namespace {

const std::string kCorpus = std::string(GRANULAB_SOURCE_DIR) + "/tests/data/gsi/";
constexpr Real kInfinity = 4294967295.0;  ///< gc2d's BIG_NUMBER, 2^32 - 1 (spec 9.2)

/// The corpus: tests/data/gsi/*.gsi and *.gsi.gz (not the malformed files in bad/), by name.
std::vector<std::string> corpusNames() {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(kCorpus)) {
        const std::string n = e.path().filename().string();
        if (e.is_regular_file() && (n.ends_with(".gsi") || n.ends_with(".gsi.gz"))) names.push_back(n);
    }
    std::sort(names.begin(), names.end());
    return names;
}

/// The text of a corpus file; a .gz one through gzip -dc, as gc2d reads it after gunzip.
std::string textOf(const std::string& path) {
    std::string text;
    if (path.ends_with(".gz")) {
        FILE* pipe = ::popen(("gzip -dc '" + path + "'").c_str(), "r");
        if (!pipe) return text;
        char buffer[4096];
        for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
        ::pclose(pipe);
        return text;
    }
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

SceneDef load(const std::string& name) {
    return granulab::io::readGsiFile(kCorpus + name);
}

GsiDocument parsed(const std::string& name) {
    return parseGsi(textOf(kCorpus + name), kCorpus + name);
}

/// The engine's set-up of a scene (validation, generation, start overlaps, time step): what
/// `granulab run` does before the first step.
granulab::dem::PreparedScene accepted(const SceneDef& s) {
    return granulab::app::checkAndPrepareDem(s);
}

/// The corners of corpus square "-0.005 -0.005 / 0.005 -0.005 / 0.005 0.005 / -0.005 0.005".
const std::vector<Vec2> kSquare = {{-0.005, -0.005}, {0.005, -0.005}, {0.005, 0.005}, {-0.005, 0.005}};

#define EXPECT_VEC(v, ex, ey)          \
    do {                               \
        EXPECT_DOUBLE_EQ((v).x, (ex)); \
        EXPECT_DOUBLE_EQ((v).y, (ey)); \
    } while (0)

/// gc2d's general defaults (spec 9.3) on what a file leaves out of GENERAL.
Real law(const SceneDef& s, const char* key) {
    return s.contacts.at(0).params.at(key).value;
}

/// The gravity magnitude of the scene's schedule at t (spec 6.6).
Real gravityAt(const SceneDef& s, Real t) {
    const auto g = granulab::dem::buildGravitySchedule(s);
    return g ? granulab::dem::gravityMagnitude(*g, t) : -s.dem.gravity.y;
}

/// The size scale factor s(t) of spec 2.4 (1 without HEAT_*).
Real scaleAt(const SceneDef& s, Real t) {
    const auto c = granulab::dem::buildSizeCycle(s);
    return c ? granulab::dem::sizeScale(*c, t) : 1.0;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// (a) The corpus covers every object, keyword, alias and choice.

TEST(GsiCorpus, CoversEveryKeywordOfEveryObjectAndEveryChoice) {
    const auto names = corpusNames();
    EXPECT_GE(names.size(), 15u);
    EXPECT_TRUE(std::count(names.begin(), names.end(), "piston.gsi"))  // App. B.1.8, as printed
        << "the thesis's sample belongs to the corpus";
    EXPECT_TRUE(std::any_of(names.begin(), names.end(), [](const auto& n) { return n.ends_with(".gz"); }));
    std::map<GsiObjectKind, std::set<std::string>> used;
    std::map<std::pair<GsiObjectKind, std::string>, std::set<std::string>> choices;
    std::set<std::string> written;  // first words as written, upper case (the alias spellings)
    for (const auto& name : names) {
        const std::string text = textOf(kCorpus + name);
        const GsiDocument d = parseGsi(text, name);
        for (const auto& o : d.objects)
            for (const auto& e : o.entries) {
                used[o.kind].insert(e.keyword);
                if (!e.text.empty() && e.keyword != "BASENAME" && e.keyword != "EMAIL")
                    choices[{o.kind, e.keyword}].insert(e.text);
            }
        std::stringstream lines(text);
        for (std::string line; std::getline(lines, line);) {
            std::stringstream words(line);
            std::string w;
            if (!(words >> w)) continue;
            if (w == "END_OF_FILE") break;
            std::transform(w.begin(), w.end(), w.begin(), [](unsigned char c) { return std::toupper(c); });
            written.insert(w);
        }
    }
    for (int k = 0; k < 6; ++k) {
        const auto kind = static_cast<GsiObjectKind>(k);
        const auto all = granulab::io::gsiKeywords(kind);
        std::set<std::string> missing(all.begin(), all.end());
        for (const auto& w : used[kind]) missing.erase(w);
        std::string list;
        for (const auto& w : missing) list += " " + w;
        EXPECT_TRUE(missing.empty()) << granulab::io::gsiObjectName(kind)
                                     << " keywords no corpus file uses:" << list;
        EXPECT_EQ(used[kind].size(), all.size()) << granulab::io::gsiObjectName(kind);
    }
    // Both spellings of the aliased keywords (spec 9.3, erratum 24).
    for (const char* w :
         {"RANDOM_POS_CORNERS", "PART_RANDOM_POS_CORNERS", "RANDOM_NUM_CORNERS", "PART_RANDOM_NUM_CORNERS"})
        EXPECT_TRUE(written.count(w)) << "no corpus file writes " << w;
    // Every choice value spec 9.3 lists, per object.
    using K = GsiObjectKind;
    const std::vector<std::string> dist = {"CONST", "EQUAL", "GAUSS"};
    const std::vector<std::string> corners = {"SPECIAL_RECTANGLE", "REGULAR", "RAND1", "RAND2", "FULL"};
    const std::vector<std::tuple<K, std::string, std::vector<std::string>>> lists = {
        {K::General, "G_TYPE", {"CONSTANT", "LINEAR", "STEP", "SMOOTH_STEP"}},
        {K::Wall, "VIB_TYPE", {"COSINUS", "SAWTOOTH", "TAPPING", "TRIANGLE"}},
        {K::GenerateBlock,
         "GRID_TYPE",
         {"RECT", "RECT_GAUSS", "RECT_EQUAL", "FCC", "FCC_GAUSS", "FCC_EQUAL"}},
        {K::GenerateBlock, "RANDOM_SIZE", dist},
        {K::GenerateBlock, "RANDOM_NUM_CORNERS", dist},
        {K::GenerateBlock, "RANDOM_ROT", dist},
        {K::GenerateBlock, "PART_RANDOM_POS_CORNERS", corners},
        {K::DropSource, "TYPE", {"ABS", "REL"}},
        {K::DropSource, "RANDOM_SIZE", dist},
        {K::DropSource, "RANDOM_NUM_CORNERS", dist},
        {K::DropSource, "RANDOM_ROT", dist},
        {K::DropSource, "PART_RANDOM_POS_CORNERS", corners},
    };
    for (const auto& [kind, key, values] : lists)
        for (const auto& v : values)
            EXPECT_TRUE(choices[std::make_pair(kind, key)].count(v))
                << granulab::io::gsiObjectName(kind) << " " << key << " " << v << ": no corpus file uses it";
}

TEST(GsiCorpus, EverySceneIsAcceptedButTheSampleAsPrinted) {
    for (const auto& name : corpusNames()) {
        SCOPED_TRACE(name);
        const SceneDef s = load(name);
        if (name == "piston.gsi") {
            // docs/coming-from-gc2d.md: read with PART_SIZE as semi-axes (erratum 26), the sample's
            // grains overlap on its 5 mm grid; examples/gc2d/piston.gsi halves them.
            try {
                accepted(s);
                ADD_FAILURE() << "the printed sample's grains overlap on its grid";
            } catch (const SceneError& e) {
                EXPECT_NE(std::string(e.what()).find("overlap"), std::string::npos) << e.what();
            }
            EXPECT_NO_THROW(accepted(
                granulab::io::readGsiFile(std::string(GRANULAB_SOURCE_DIR) + "/examples/gc2d/piston.gsi")));
            continue;
        }
        try {
            accepted(s);
        } catch (const SceneError& e) {
            ADD_FAILURE() << e.what();
        }
    }
}

// ---------------------------------------------------------------------------------------------
// (b) Per file: the SceneDef values, derived from spec 9.3 and docs/coming-from-gc2d.md.

TEST(GsiCorpus, ThesisSamplePiston) {  // App. B.1.8 as printed (more in GsiScene.ThesisSamplePiston)
    const SceneDef s = load("piston.gsi");
    EXPECT_DOUBLE_EQ(s.output.snapshotInterval, 1000 * 1.5e-5);  // STEPS_DATA n -> n dt
    EXPECT_DOUBLE_EQ(law(s, "cohesion"), 0);
    EXPECT_DOUBLE_EQ(s.dem.gravity.y, 0);  // G 0
    EXPECT_FALSE(s.machines.gravity.present);
    ASSERT_EQ(s.walls.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(s.walls[k].name, "wall" + std::to_string(k + 1));
    EXPECT_VEC(s.walls[0].points[0], -0.05, 0.01);  // absolute, not re-centred
    EXPECT_VEC(s.walls[0].offset, -0.3, 0);
    EXPECT_DOUBLE_EQ(s.walls[0].pistonDirection, 0);  // Piston_Angle -0.0: along +x
    for (std::size_t k = 1; k < 4; ++k) EXPECT_FALSE(s.walls[k].pistonForce) << k;
    EXPECT_VEC(s.walls[3].offset, 0, 0);
    EXPECT_TRUE(s.particles.empty());
    ASSERT_EQ(s.blocks.size(), 1u);
    EXPECT_VEC(s.blocks[0].directionRange, 0, 2 * kPi);  // ANGLE_RANGE default
    EXPECT_VEC(s.blocks[0].speedRange, 0, 0);
    EXPECT_DOUBLE_EQ(s.shapes[0].sizeVariation, 0.5);  // PART_VAR_SIZE default of GENERATE_BLOCK
}

TEST(GsiCorpus, DropPile) {
    const GsiDocument d = parsed("drop_pile.gsi");
    EXPECT_EQ(d.echoes, (std::vector<std::string>{"drop pile: one 7-gon every 2 ms"}));
    const SceneDef s = load("drop_pile.gsi");
    EXPECT_DOUBLE_EQ(s.dem.dt, 2e-6);
    EXPECT_DOUBLE_EQ(s.run.endTime, 0.05);
    EXPECT_DOUBLE_EQ(s.output.seriesInterval, 5000 * 2e-6);
    EXPECT_DOUBLE_EQ(s.output.checkpointInterval, 25000 * 2e-6);
    EXPECT_EQ(s.run.title, "out/drop_pile");
    EXPECT_DOUBLE_EQ(law(s, "mu"), 0.6);
    EXPECT_DOUBLE_EQ(law(s, "gamma"), 0.75);
    EXPECT_DOUBLE_EQ(law(s, "E"), 1e7);  // default
    ASSERT_EQ(s.machines.sources.size(), 1u);
    const auto& src = s.machines.sources[0];
    EXPECT_EQ(src.placement, "rel");
    EXPECT_VEC(src.position, 0, 0.02);
    EXPECT_DOUBLE_EQ(src.width, 0.004);
    EXPECT_DOUBLE_EQ(src.interval, 0.002);
    EXPECT_DOUBLE_EQ(src.from, 0);
    EXPECT_DOUBLE_EQ(src.to, 0.05);
    EXPECT_EQ(src.insert.material, "grain");
    ASSERT_EQ(s.shapes.size(), 1u);
    const auto& g = s.shapes[0];
    EXPECT_EQ(src.insert.shape, g.name);
    EXPECT_EQ(g.kind, "grain");
    EXPECT_VEC(g.size, 0.0015, 0.0015);
    EXPECT_DOUBLE_EQ(g.sizeVariation, 0.2);
    EXPECT_EQ(g.sizeMode, "equal");
    EXPECT_EQ(g.cornerCount, 7);
    EXPECT_EQ(g.cornerVariation, 0);
    EXPECT_EQ(g.cornerCountMode, "const");  // default
    EXPECT_EQ(g.cornerAngles, "rand1");
    EXPECT_EQ(g.rotationMode, "equal");
    EXPECT_TRUE(accepted(s).initial.particles.empty());  // the source inserts them during the run
}

TEST(GsiCorpus, PulledBlock) {
    const SceneDef s = load("pulled_block.gsi");
    EXPECT_DOUBLE_EQ(s.output.seriesInterval, 10000 * 1e-5);  // STEPS_DATA default
    ASSERT_EQ(s.particles.size(), 2u);
    EXPECT_VEC(s.particles[0].position, 0, 0.005);
    EXPECT_NEAR(s.particles[1].position.x, 0.025, 1e-15);  // POSITION_ABSOLUT: corners' centroid
    EXPECT_NEAR(s.particles[1].position.y, (0.006 + 0.006 + 0.014) / 3, 1e-15);
    EXPECT_DOUBLE_EQ(s.particles[1].angle, -0.3);  // clockwise 0.3
    EXPECT_DOUBLE_EQ(s.particles[1].omega, -1);
    ASSERT_EQ(s.springs.size(), 1u);
    const auto& sp = s.springs[0];
    EXPECT_EQ(sp.particle, 0);
    EXPECT_DOUBLE_EQ(sp.stiffness, 200);
    EXPECT_VEC(sp.attach, 0.005, 0);
    EXPECT_VEC(sp.pullStart, 0.01, 0.005);
    EXPECT_DOUBLE_EQ(sp.speed, 0.05);
    EXPECT_DOUBLE_EQ(sp.direction, 0);
    EXPECT_DOUBLE_EQ(sp.from, 0);
    EXPECT_DOUBLE_EQ(sp.to, 1);
    ASSERT_EQ(s.walls.size(), 1u);
    EXPECT_VEC(s.walls[0].surfaceVelocity, 0.01, 0);
    EXPECT_VEC(s.walls[0].velocity, 0, 0);  // a belt: the wall itself rests
    EXPECT_EQ(accepted(s).initial.particles.size(), 2u);
}

TEST(GsiCorpus, TiltedGravity) {
    const SceneDef s = load("tilted_gravity.gsi");
    const auto& g = s.machines.gravity;
    ASSERT_TRUE(g.present);
    EXPECT_EQ(g.type, "smooth_step");
    EXPECT_DOUBLE_EQ(g.g1, 9.81);
    EXPECT_DOUBLE_EQ(g.g2, 4.0);
    EXPECT_DOUBLE_EQ(g.t1, 0);
    EXPECT_DOUBLE_EQ(g.t2, 0.01);
    EXPECT_DOUBLE_EQ(g.steps, 5);
    EXPECT_DOUBLE_EQ(g.ramp, 0.5);
    EXPECT_DOUBLE_EQ(s.dem.gravity.y, 0);  // the schedule alone
    // Spec 6.6 SMOOTH_STEP: tau = 0.5 at t = 5 ms, k = 2, u = 0.5, ramp fraction clamp(0, 0, 1) = 0.
    EXPECT_NEAR(gravityAt(s, 0.005), 9.81 + (4.0 - 9.81) * 2 / 5, 1e-12);
    const auto& h = s.machines.sizeScaling;
    ASSERT_TRUE(h.present);
    EXPECT_DOUBLE_EQ(h.t1, 0);
    EXPECT_DOUBLE_EQ(h.t2, 0.01);
    EXPECT_DOUBLE_EQ(h.amplitude, 0.01);
    EXPECT_DOUBLE_EQ(h.frequency, 100);
    EXPECT_DOUBLE_EQ(h.slope, 10);
    // Eq. B.2 at t = 5 ms: cos(2 pi 100 0.005) = -1, s = 1 + a (1/2 + tanh(10)/2).
    EXPECT_NEAR(scaleAt(s, 0.005), 1 + 0.01 * (0.5 + 0.5 * std::tanh(10.0)), 1e-12);
    EXPECT_DOUBLE_EQ(law(s, "cohesion"), 10);
    ASSERT_EQ(s.blocks.size(), 1u);
    EXPECT_EQ(s.blocks[0].lattice, BlockDef::Lattice::Fcc);
    EXPECT_EQ(s.blocks[0].jitter, BlockDef::Jitter::Gauss);
    const auto& sh = s.shapes[0];
    EXPECT_EQ(sh.cornerCount, 6);
    EXPECT_EQ(sh.cornerVariation, 1);
    EXPECT_EQ(sh.cornerCountMode, "gauss");
    EXPECT_EQ(sh.sizeMode, "gauss");
    EXPECT_DOUBLE_EQ(sh.sizeVariation, 0.1);
    EXPECT_EQ(sh.cornerAngles, "regular");  // PART_RANDOM_POS_CORNERS default
    EXPECT_EQ(sh.rotationMode, "const");
    EXPECT_EQ(accepted(s).initial.particles.size(), 20u);  // 10 sites in each of 2 rows
}

TEST(GsiCorpus, VibratedBed) {
    const GsiDocument d = parsed("vibrated_bed.gsi");
    EXPECT_EQ(d.identification, "vibrated bed, identification text");
    const SceneDef s = load("vibrated_bed.gsi");
    EXPECT_DOUBLE_EQ(s.dem.dt, 5e-6);
    EXPECT_DOUBLE_EQ(s.dem.gravity.y, -9.81);
    ASSERT_EQ(s.walls.size(), 3u);
    const auto& floor = s.walls[0];
    EXPECT_EQ(floor.vibType, "tapping");
    EXPECT_DOUBLE_EQ(floor.vibWidth, 0.001);
    EXPECT_DOUBLE_EQ(floor.vibFrequency, 50);
    EXPECT_DOUBLE_EQ(floor.vibFrom, 0);
    EXPECT_DOUBLE_EQ(floor.vibTo, 1);
    EXPECT_DOUBLE_EQ(floor.vibDirection, kPi / 2);  // VIB_ANGLE default: up
    EXPECT_TRUE(s.walls[1].vibType.empty());
    EXPECT_VEC(s.walls[2].offset, 0.11, 0);
    EXPECT_EQ(s.blocks[0].lattice, BlockDef::Lattice::Rect);
    EXPECT_EQ(s.blocks[0].jitter, BlockDef::Jitter::None);
    EXPECT_EQ(s.shapes[0].cornerAngles, "special_rectangle");
    // X -0.045 .. 0.045 on a 6 mm grid from -0.042: 15 sites; Y 0.003 .. 0.03 from 0.006: 4 rows.
    EXPECT_EQ(accepted(s).initial.particles.size(), 60u);
}

TEST(GsiCorpus, GeneralKeywords) {
    const GsiDocument d = parsed("general_keywords.gsi");
    const auto& g = d.general();
    EXPECT_EQ(g.find("EMAIL")->text, "Granulab@Example.ORG");  // case kept
    EXPECT_DOUBLE_EQ(g.find("MUE_DYNAMISCH")->numbers[0], 0.3);
    EXPECT_DOUBLE_EQ(g.find("STEPS_SETUP")->numbers[0], kInfinity);
    EXPECT_DOUBLE_EQ(g.find("STEPS_DUMPLINE")->numbers[0], 100);
    EXPECT_DOUBLE_EQ(g.find("NEXT_DATA_FILENUMBER")->numbers[0], 3);
    EXPECT_DOUBLE_EQ(g.find("NEXT_SETUP_FILENUMBER")->numbers[0], 2);
    EXPECT_EQ(g.find("G")->given, 1);
    ASSERT_EQ(d.objects.size(), 3u);  // the named GENERAL is the implicit one, not a new object

    const SceneDef s = load("general_keywords.gsi");
    EXPECT_DOUBLE_EQ(s.dem.dt, 1e-5);
    EXPECT_DOUBLE_EQ(s.run.endTime, 0.01);
    EXPECT_DOUBLE_EQ(law(s, "mu"), 0.4);  // MUE_STATISCH; MUE_DYNAMISCH is unused
    EXPECT_DOUBLE_EQ(law(s, "E"), 2e7);
    EXPECT_DOUBLE_EQ(law(s, "gamma"), 0.3);
    EXPECT_DOUBLE_EQ(law(s, "cohesion"), 5);
    EXPECT_DOUBLE_EQ(s.output.seriesInterval, 250 * 1e-5);
    EXPECT_DOUBLE_EQ(s.output.snapshotInterval, 250 * 1e-5);
    EXPECT_DOUBLE_EQ(s.output.checkpointInterval, 500 * 1e-5);
    EXPECT_EQ(s.run.title, "Corpus/General_Keywords");
    EXPECT_DOUBLE_EQ(s.dem.gravity.x, 0);
    EXPECT_DOUBLE_EQ(s.dem.gravity.y, -5.5);
    EXPECT_FALSE(s.machines.gravity.present);  // one G value: G_TIME, G_PARAMETER, G_TYPE ignored
    EXPECT_NE(s.run.seed, load("block_defaults.gsi").run.seed);  // SEED 12.5 7 vs the default 0 0
    EXPECT_EQ(s.dem.integrator, "gear");
    EXPECT_EQ(s.dem.broadPhase, "sort_and_sweep");
    // The 10 mm square: areal density 5000 kg/m^2 (spec 2.2), m = 0.5 kg, I = m (a^2 + b^2) / 12.
    const auto v = accepted(s);
    ASSERT_EQ(v.initial.particles.size(), 1u);
    const auto& p = v.initial.particles[0];
    EXPECT_DOUBLE_EQ(s.materials[p.material].density, 5000);
    EXPECT_NEAR(granulab::dem::initialMass(v.initial, p, granulab::model::MassModel::Disk, 5000), 0.5, 1e-12);
    EXPECT_NEAR(5000 * v.initial.shapes.secondMoment[p.shape], 0.5 * (1e-4 + 1e-4) / 12, 1e-15);
}

TEST(GsiCorpus, GravityLinearAndFccEqualBlock) {
    const SceneDef s = load("gravity_linear.gsi");
    const auto& g = s.machines.gravity;
    ASSERT_TRUE(g.present);
    EXPECT_EQ(g.type, "linear");
    EXPECT_DOUBLE_EQ(g.g1, 9.81);
    EXPECT_DOUBLE_EQ(g.g2, 2.0);
    EXPECT_DOUBLE_EQ(g.t1, 0);
    EXPECT_DOUBLE_EQ(g.t2, 0.02);
    EXPECT_DOUBLE_EQ(g.steps, 5);  // G_PARAMETER default 5 0.5
    EXPECT_DOUBLE_EQ(g.ramp, 0.5);
    EXPECT_DOUBLE_EQ(g.direction1, -kPi / 2);  // gc2d's g points down, (0, -g)
    EXPECT_DOUBLE_EQ(g.direction2, -kPi / 2);
    EXPECT_DOUBLE_EQ(s.dem.gravity.y, 0);
    EXPECT_NEAR(gravityAt(s, 0.01), (9.81 + 2.0) / 2, 1e-12);  // LINEAR: halfway at mid-window
    EXPECT_NEAR(gravityAt(s, 0.02), 2.0, 1e-12);
    ASSERT_EQ(s.blocks.size(), 1u);
    const auto& b = s.blocks[0];
    EXPECT_EQ(b.lattice, BlockDef::Lattice::Fcc);
    EXPECT_EQ(b.jitter, BlockDef::Jitter::Equal);
    EXPECT_DOUBLE_EQ(b.xmin, -0.025);
    EXPECT_DOUBLE_EQ(b.xmax, 0.027);
    EXPECT_DOUBLE_EQ(b.ymin, 0.004);
    EXPECT_DOUBLE_EQ(b.ymax, 0.02);
    EXPECT_VEC(b.grid, 0.01, 0.008);
    EXPECT_VEC(b.directionRange, 1.0, 2.0);
    EXPECT_VEC(b.speedRange, 0.05, 0.1);
    EXPECT_EQ(b.material, "grain");
    const auto& sh = s.shapes[0];
    EXPECT_EQ(sh.name, "block1");
    EXPECT_EQ(b.shape, "block1");
    EXPECT_VEC(sh.size, 0.0015, 0.0015);
    EXPECT_EQ(sh.sizeMode, "const");
    EXPECT_DOUBLE_EQ(sh.sizeVariation, 0.5);  // GENERATE_BLOCK defaults: PART_VAR_SIZE 0.5,
    EXPECT_EQ(sh.cornerVariation, 2);         // PART_VAR_CORNERS 2
    EXPECT_EQ(sh.cornerCount, 7);
    EXPECT_EQ(sh.cornerCountMode, "const");
    EXPECT_EQ(sh.cornerAngles, "full");
    EXPECT_DOUBLE_EQ(sh.rotation, -0.5);  // clockwise 0.5
    EXPECT_EQ(sh.rotationMode, "const");
    // FCC sites: y 0.008 and 0.016; even row x -0.02 .. 0.02 (5), odd row x -0.025 .. 0.025 (6).
    const auto v = accepted(s);
    ASSERT_EQ(v.initial.particles.size(), 11u);
    for (const auto& p : v.initial.particles) {
        EXPECT_EQ(v.initial.shapes.count[p.shape], 7u);  // RANDOM_NUM_CORNERS CONST
        const Real speed = std::hypot(p.velocity.x, p.velocity.y);
        EXPECT_GE(speed, 0.05);  // VELOCITY_RANGE
        EXPECT_LE(speed, 0.1);
        const Real dir = std::atan2(p.velocity.y, p.velocity.x);
        EXPECT_GE(dir, 1.0 - 1e-12);  // ANGLE_RANGE, counter-clockwise from +x
        EXPECT_LE(dir, 2.0 + 1e-12);
        EXPECT_NEAR(p.angle, -0.5, 1e-12);  // RANDOM_ROT CONST
    }
}

TEST(GsiCorpus, RectGaussAndRectEqualBlocks) {
    const SceneDef s = load("block_rect_jitter.gsi");
    ASSERT_EQ(s.blocks.size(), 2u);
    ASSERT_EQ(s.shapes.size(), 2u);
    const auto& b1 = s.blocks[0];
    EXPECT_EQ(b1.lattice, BlockDef::Lattice::Rect);
    EXPECT_EQ(b1.jitter, BlockDef::Jitter::Gauss);  // written Rect_Gauss
    EXPECT_VEC(b1.grid, 0.008, 0.008);
    EXPECT_EQ(b1.shape, "block1");
    const auto& g1 = s.shapes[0];
    EXPECT_VEC(g1.size, 0.002, 0.0015);
    EXPECT_DOUBLE_EQ(g1.sizeVariation, 0.1);
    EXPECT_EQ(g1.sizeMode, "equal");
    EXPECT_EQ(g1.cornerCount, 6);
    EXPECT_EQ(g1.cornerVariation, 1);
    EXPECT_EQ(g1.cornerCountMode, "equal");  // written Part_Random_Num_Corners
    EXPECT_EQ(g1.cornerAngles, "regular");
    EXPECT_DOUBLE_EQ(g1.rotation, -0.3);
    EXPECT_EQ(g1.rotationMode, "gauss");
    const auto& b2 = s.blocks[1];
    EXPECT_EQ(b2.lattice, BlockDef::Lattice::Rect);
    EXPECT_EQ(b2.jitter, BlockDef::Jitter::Equal);
    EXPECT_DOUBLE_EQ(b2.xmin, 0.005);
    EXPECT_DOUBLE_EQ(b2.xmax, 0.04);
    EXPECT_VEC(b2.grid, 0.012, 0.01);
    EXPECT_EQ(b2.shape, "block2");
    const auto& g2 = s.shapes[1];
    EXPECT_EQ(g2.sizeMode, "const");
    EXPECT_EQ(g2.cornerCount, 9);
    EXPECT_EQ(g2.cornerVariation, 2);
    EXPECT_EQ(g2.cornerCountMode, "gauss");
    EXPECT_EQ(g2.cornerAngles, "rand2");
    EXPECT_DOUBLE_EQ(g2.rotation, 0);
    EXPECT_EQ(g2.rotationMode, "equal");
    // Block 1: x -0.036 .. -0.012 (4 sites) in rows 0.007 and 0.015; block 2: x 0.011 .. 0.035
    // (3) in rows 0.008 and 0.018.
    const auto v = accepted(s);
    ASSERT_EQ(v.initial.particles.size(), 14u);
    for (std::size_t k = 0; k < 14; ++k) {
        const auto& p = v.initial.particles[k];
        const auto n = v.initial.shapes.count[p.shape];
        if (k < 8) {
            EXPECT_GE(n, 5u);  // 6 +- 1 corners
            EXPECT_LE(n, 7u);
            EXPECT_GT(p.angle, -0.3 - kPi / 2);  // GAUSS: ]phi0 - pi/2, phi0 + pi/2[ (spec 2.3)
            EXPECT_LT(p.angle, -0.3 + kPi / 2);
        } else {
            EXPECT_GE(n, 7u);  // 9 +- 2 corners
            EXPECT_LE(n, 11u);
        }
    }
}

TEST(GsiCorpus, GravityStepAndHeatTimeOnly) {
    const SceneDef s = load("gravity_step.gsi");
    const auto& g = s.machines.gravity;
    ASSERT_TRUE(g.present);
    EXPECT_EQ(g.type, "step");
    EXPECT_DOUBLE_EQ(g.g2, 4.905);
    EXPECT_DOUBLE_EQ(g.t1, 0.002);
    EXPECT_DOUBLE_EQ(g.t2, 0.012);
    EXPECT_DOUBLE_EQ(g.steps, 4);
    EXPECT_DOUBLE_EQ(g.ramp, 0);  // the missing second G_PARAMETER
    // Spec 6.6 STEP: g1 before the window, g1 + (g2 - g1) k / p1 inside it, g2 after.
    EXPECT_NEAR(gravityAt(s, 0.001), 9.81, 1e-12);
    EXPECT_NEAR(gravityAt(s, 0.0075), 9.81 + (4.905 - 9.81) * 2 / 4, 1e-12);  // tau 0.55, k 2
    EXPECT_NEAR(gravityAt(s, 0.013), 4.905, 1e-12);
    const auto& h = s.machines.sizeScaling;
    ASSERT_TRUE(h.present);  // HEAT_TIME alone switches it on
    EXPECT_DOUBLE_EQ(h.t1, 0);
    EXPECT_DOUBLE_EQ(h.t2, 0.5);
    EXPECT_DOUBLE_EQ(h.amplitude, 0.01);  // defaults: HEAT_AMPLITUDE 0.01, HEAT_FREQUENCE 1,
    EXPECT_DOUBLE_EQ(h.frequency, 1.0);
    EXPECT_DOUBLE_EQ(h.slope, 10);  // HEAT_SLOPE 10 (docs/coming-from-gc2d.md)
    // Eq. B.2 at t = 0.25 s: cos(2 pi 0.25) = 0, s = 1 + a / 2.
    EXPECT_NEAR(scaleAt(s, 0.25), 1.005, 1e-12);
    ASSERT_EQ(s.particles.size(), 3u);
    EXPECT_VEC(s.particles[2].position, 0, 0.0255);
    EXPECT_EQ(accepted(s).initial.particles.size(), 3u);
}

TEST(GsiCorpus, HeatWithoutHeatTimeKeepsTheSize) {
    const SceneDef s = load("heat_default_time.gsi");
    const auto& h = s.machines.sizeScaling;
    EXPECT_DOUBLE_EQ(h.amplitude, 0.02);
    EXPECT_DOUBLE_EQ(h.frequency, 50);
    EXPECT_DOUBLE_EQ(h.slope, 10);  // HEAT_SLOPE default (docs)
    // HEAT_TIME inf inf is "off" (spec 2.4 audit note, erratum 28): s = 1 at every time.
    for (const Real t : {0.0, 0.003, 0.01, 1.0}) EXPECT_DOUBLE_EQ(scaleAt(s, t), 1.0) << "t = " << t;
    EXPECT_EQ(accepted(s).initial.particles.size(), 3u);
}

TEST(GsiCorpus, VibratingWallsOfEveryType) {
    const SceneDef s = load("vib_walls.gsi");
    ASSERT_EQ(s.walls.size(), 4u);
    const auto& floor = s.walls[0];
    EXPECT_EQ(floor.vibType, "cosine");
    EXPECT_DOUBLE_EQ(floor.vibDirection, kPi / 2);
    EXPECT_DOUBLE_EQ(floor.vibWidth, 0.0005);
    EXPECT_DOUBLE_EQ(floor.vibFrequency, 30);
    EXPECT_DOUBLE_EQ(floor.vibFrom, 0);
    EXPECT_DOUBLE_EQ(floor.vibTo, 0.01);
    const auto& left = s.walls[1];
    EXPECT_EQ(left.vibType, "sawtooth");
    EXPECT_DOUBLE_EQ(left.vibDirection, 0);
    EXPECT_DOUBLE_EQ(left.vibFrequency, 50);
    EXPECT_DOUBLE_EQ(left.vibFrom, 0);
    EXPECT_GE(left.vibTo, kInfinity);  // VIB_TIME default 0 .. inf
    const auto& right = s.walls[2];
    EXPECT_EQ(right.vibType, "triangle");
    EXPECT_DOUBLE_EQ(right.vibDirection, kPi);
    EXPECT_DOUBLE_EQ(right.vibFrom, 0.002);
    EXPECT_DOUBLE_EQ(right.vibTo, 0.008);
    const auto& lid = s.walls[3];  // only VIB_WIDTH and VIB_FREQUENCE: the rest by default
    EXPECT_EQ(lid.vibType, "cosine");
    EXPECT_DOUBLE_EQ(lid.vibDirection, kPi / 2);
    EXPECT_DOUBLE_EQ(lid.vibWidth, 0.001);
    EXPECT_DOUBLE_EQ(lid.vibFrequency, 20);
    EXPECT_DOUBLE_EQ(lid.vibFrom, 0);
    EXPECT_GE(lid.vibTo, kInfinity);
    for (const auto& w : s.walls) EXPECT_FALSE(w.pistonForce) << w.name;
    EXPECT_EQ(s.blocks[0].lattice, BlockDef::Lattice::Rect);
    EXPECT_EQ(s.blocks[0].jitter, BlockDef::Jitter::None);
    // One row at y 0.0026, x -0.025 .. 0.025: six regular octagons.
    const auto v = accepted(s);
    ASSERT_EQ(v.initial.particles.size(), 6u);
    for (const auto& p : v.initial.particles) {
        EXPECT_EQ(v.initial.shapes.count[p.shape], 8u);
        EXPECT_NEAR(v.initial.shapes.circumradius[p.shape], 0.002, 1e-15);
    }
}

TEST(GsiCorpus, PistonPressingDown) {
    const SceneDef s = load("piston_down.gsi");
    ASSERT_EQ(s.walls.size(), 4u);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_FALSE(s.walls[k].pistonForce) << k;
    const auto& piston = s.walls[3];
    EXPECT_EQ(piston.name, "wall4");
    ASSERT_TRUE(piston.pistonForce);
    EXPECT_DOUBLE_EQ(*piston.pistonForce, 50);
    EXPECT_NEAR(piston.pistonDirection, 1.5 * kPi, 1e-12);  // down
    EXPECT_DOUBLE_EQ(piston.pistonMaxSpeed, 0.2);
    EXPECT_VEC(piston.offset, 0, 0.002);
    EXPECT_VEC(piston.points[0], -0.045, 0.012);  // CORNERS as written, OFFSET apart
    EXPECT_TRUE(piston.vibType.empty());
    const auto placed = granulab::dem::placedWallPoints(piston);
    EXPECT_NEAR(placed[0].y, 0.014, 1e-15);
    EXPECT_EQ(accepted(s).initial.particles.size(), 3u);
}

TEST(GsiCorpus, BeltAndTurnedWall) {
    const SceneDef s = load("belt_conveyor.gsi");
    ASSERT_EQ(s.walls.size(), 2u);
    EXPECT_VEC(s.walls[0].surfaceVelocity, 0.05, 0);  // VELOCITY 0.05: the second number 0
    EXPECT_VEC(s.walls[0].velocity, 0, 0);
    EXPECT_DOUBLE_EQ(s.walls[0].angle, 0);
    EXPECT_DOUBLE_EQ(s.walls[1].angle, -0.2);  // clockwise 0.2
    EXPECT_VEC(s.walls[1].surfaceVelocity, 0, 0);
    // Spec 2.1/6.1: turning clockwise by phi about the centroid (0.08, -0.005) takes the corner
    // (0.06, 0), relative (-0.02, 0.005), to (x cos phi + y sin phi, -x sin phi + y cos phi).
    const auto placed = granulab::dem::placedWallPoints(s.walls[1]);
    const Real c = std::cos(0.2), sn = std::sin(0.2);
    bool found = false;
    for (const Vec2& q : placed)
        found |= std::abs(q.x - (0.08 + -0.02 * c + 0.005 * sn)) < 1e-12 &&
                 std::abs(q.y - (-0.005 + 0.02 * sn + 0.005 * c)) < 1e-12;
    EXPECT_TRUE(found) << "the turned corner of the step";
    ASSERT_EQ(s.particles.size(), 2u);
    EXPECT_VEC(s.particles[0].position, -0.03, 0.0051);
    EXPECT_VEC(s.particles[1].position, -0.01, 0.0031);
    EXPECT_EQ(s.shapes[1].corners.size(), 3u);
    EXPECT_EQ(accepted(s).initial.particles.size(), 2u);  // IDs are ignored
}

TEST(GsiCorpus, ParticleStateAndPlacement) {
    const SceneDef s = load("particle_state.gsi");
    ASSERT_EQ(s.particles.size(), 3u);
    ASSERT_EQ(s.shapes.size(), 3u);
    const auto& a = s.particles[0];
    EXPECT_EQ(a.shape, "particle1");
    EXPECT_EQ(s.shapes[0].kind, "polygon");
    EXPECT_EQ(s.shapes[0].corners, kSquare);
    EXPECT_VEC(a.position, -0.03, 0.0051);
    EXPECT_DOUBLE_EQ(a.angle, 0);
    EXPECT_VEC(a.velocity, 0.01, 0);
    EXPECT_DOUBLE_EQ(a.omega, -2);  // clockwise 2 rad/s
    EXPECT_EQ(a.material, "grain");
    const auto& b = s.particles[1];  // POSITION_ABSOLUT: the corners' centroid, COM 0.5 0.5 ignored
    EXPECT_NEAR(b.position.x, 0.006, 1e-15);
    EXPECT_NEAR(b.position.y, (0.0001 + 0.0001 + 0.0101) / 3, 1e-15);
    EXPECT_DOUBLE_EQ(b.angle, 0);
    const auto& c = s.particles[2];
    EXPECT_VEC(c.position, 0.03, 0.005);
    EXPECT_DOUBLE_EQ(c.angle, -0.3);
    EXPECT_EQ(s.shapes[2].corners.size(), 5u);
    EXPECT_TRUE(s.springs.empty());
    EXPECT_EQ(accepted(s).initial.particles.size(), 3u);
}

TEST(GsiCorpus, RestartStateOfEveryParticle) {
    const GsiDocument d = parsed("restart_state.gsi");
    ASSERT_EQ(d.objects.size(), 4u);
    for (const std::size_t k : {2u, 3u}) {
        const auto& p = d.objects[k];
        for (const char* key : {"ACCELERATION", "OMEGA_DOT", "PC_TRANS3", "PC_TRANS4", "PC_TRANS5", "PC_ROT3",
                                "PC_ROT4", "PC_ROT5", "ID"})
            EXPECT_NE(p.find(key), nullptr) << k << " " << key;
        EXPECT_EQ(p.find("PC_TRANS5")->numbers, (std::vector<Real>{0, 0}));
        EXPECT_EQ(p.find("PC_ROT5")->numbers, (std::vector<Real>{0}));
        EXPECT_DOUBLE_EQ(p.find("ID")->numbers[0], static_cast<Real>(k - 1));
    }
    const SceneDef s = load("restart_state.gsi");
    ASSERT_EQ(s.particles.size(), 2u);
    EXPECT_VEC(s.particles[0].position, -0.01, 0.0051);
    EXPECT_VEC(s.particles[1].position, 0.01, 0.0051);
    for (const auto& p : s.particles) {
        EXPECT_VEC(p.velocity, 0, 0);
        EXPECT_DOUBLE_EQ(p.omega, 0);
    }
    EXPECT_EQ(accepted(s).initial.particles.size(), 2u);
}

TEST(GsiCorpus, DragSpringDefaults) {
    const SceneDef s = load("drag_spring_defaults.gsi");
    ASSERT_EQ(s.springs.size(), 2u);
    const auto& d = s.springs[0];  // only DRAG_K: every other default of spec 3.8 / 9.3
    EXPECT_EQ(d.particle, 0);
    EXPECT_DOUBLE_EQ(d.stiffness, 150);
    EXPECT_VEC(d.attach, 0, 0);
    EXPECT_VEC(d.pullStart, 0, 0);
    EXPECT_DOUBLE_EQ(d.speed, 0.1);
    EXPECT_DOUBLE_EQ(d.direction, 0);
    EXPECT_DOUBLE_EQ(d.from, 0);
    EXPECT_DOUBLE_EQ(d.to, 1);
    const auto& l = s.springs[1];
    EXPECT_EQ(l.particle, 1);
    EXPECT_DOUBLE_EQ(l.stiffness, 300);
    EXPECT_VEC(l.attach, -0.005, 0.005);  // body frame, relative to the centroid
    EXPECT_VEC(l.pullStart, 0.015, 0.0101);
    EXPECT_DOUBLE_EQ(l.speed, 0.2);
    EXPECT_DOUBLE_EQ(l.direction, kPi / 2);
    EXPECT_DOUBLE_EQ(l.from, 0.002);
    EXPECT_DOUBLE_EQ(l.to, 0.012);
    EXPECT_EQ(accepted(s).initial.particles.size(), 2u);
}

TEST(GsiCorpus, EveryDefaultOfGeneralAndGenerateBlock) {
    const SceneDef s = load("block_defaults.gsi");
    EXPECT_DOUBLE_EQ(s.dem.dt, 1e-4);
    EXPECT_DOUBLE_EQ(s.run.endTime, 1);
    EXPECT_DOUBLE_EQ(s.dem.gravity.y, -9.81);
    EXPECT_EQ(s.run.title, "default");
    EXPECT_DOUBLE_EQ(law(s, "E"), 1e7);
    EXPECT_DOUBLE_EQ(law(s, "gamma"), 0.5);
    EXPECT_DOUBLE_EQ(law(s, "mu"), 0.6);
    EXPECT_DOUBLE_EQ(law(s, "cohesion"), 0);
    EXPECT_DOUBLE_EQ(s.output.seriesInterval, 10000 * 1e-4);
    EXPECT_DOUBLE_EQ(s.output.checkpointInterval, 10000 * 1e-4);
    EXPECT_FALSE(s.machines.gravity.present);
    EXPECT_FALSE(s.machines.sizeScaling.present);
    ASSERT_EQ(s.blocks.size(), 1u);
    const auto& b = s.blocks[0];
    EXPECT_EQ(b.lattice, BlockDef::Lattice::Fcc);
    EXPECT_EQ(b.jitter, BlockDef::Jitter::None);
    EXPECT_DOUBLE_EQ(b.xmin, 0);
    EXPECT_DOUBLE_EQ(b.xmax, 10);
    EXPECT_DOUBLE_EQ(b.ymin, 0);
    EXPECT_DOUBLE_EQ(b.ymax, 10);
    EXPECT_VEC(b.grid, 2, 2);
    EXPECT_VEC(b.directionRange, 0, 2 * kPi);
    EXPECT_VEC(b.speedRange, 0, 0);
    const auto& g = s.shapes[0];
    EXPECT_VEC(g.size, 1, 1);
    EXPECT_DOUBLE_EQ(g.sizeVariation, 0.5);
    EXPECT_EQ(g.sizeMode, "const");
    EXPECT_EQ(g.cornerCount, 6);
    EXPECT_EQ(g.cornerVariation, 2);
    EXPECT_EQ(g.cornerCountMode, "const");
    EXPECT_EQ(g.cornerAngles, "regular");
    EXPECT_DOUBLE_EQ(g.rotation, 0);
    EXPECT_EQ(g.rotationMode, "const");
    // Rows y = 1, 3, 5, 7, 9; even rows x = 1 .. 9, odd rows x = 0 .. 8: 5 x 5 hexagons of
    // circumradius 1 with a corner at angle 0 (REGULAR, PART_ROT 0), mass 5000 * 3 sqrt(3) / 2.
    const auto v = accepted(s);
    ASSERT_EQ(v.initial.particles.size(), 25u);
    EXPECT_VEC(v.initial.particles[0].position, 1, 1);
    EXPECT_VEC(v.initial.particles[5].position, 0, 3);
    for (const auto& p : v.initial.particles) {
        EXPECT_EQ(v.initial.shapes.count[p.shape], 6u);
        EXPECT_NEAR(v.initial.shapes.circumradius[p.shape], 1, 1e-12);
        EXPECT_NEAR(v.initial.shapes.area[p.shape], 1.5 * std::sqrt(3.0), 1e-12);
        EXPECT_DOUBLE_EQ(p.angle, 0);
    }
}

TEST(GsiCorpus, EveryDefaultOfDropSource) {
    const SceneDef s = load("source_defaults.gsi");
    EXPECT_DOUBLE_EQ(s.dem.dt, 1e-4);
    EXPECT_DOUBLE_EQ(s.run.endTime, 0.25);
    ASSERT_EQ(s.machines.sources.size(), 1u);
    const auto& src = s.machines.sources[0];
    EXPECT_EQ(src.name, "source1");
    EXPECT_VEC(src.position, 0, 0.01);
    EXPECT_EQ(src.placement, "abs");
    EXPECT_DOUBLE_EQ(src.width, 0);
    EXPECT_DOUBLE_EQ(src.interval, 0.1);
    EXPECT_DOUBLE_EQ(src.from, 0);
    EXPECT_DOUBLE_EQ(src.to, 1);
    ASSERT_EQ(s.shapes.size(), 1u);
    const auto& g = s.shapes[0];
    EXPECT_EQ(src.insert.shape, g.name);
    EXPECT_EQ(g.kind, "grain");
    EXPECT_VEC(g.size, 0.01, 0.01);  // DROPSOURCE's own defaults
    EXPECT_DOUBLE_EQ(g.sizeVariation, 0.1);
    EXPECT_EQ(g.sizeMode, "const");
    EXPECT_EQ(g.cornerCount, 8);
    EXPECT_EQ(g.cornerVariation, 2);
    EXPECT_EQ(g.cornerCountMode, "const");
    EXPECT_EQ(g.cornerAngles, "regular");
    EXPECT_DOUBLE_EQ(g.rotation, 0);
    EXPECT_EQ(g.rotationMode, "const");
    EXPECT_TRUE(accepted(s).initial.particles.empty());
}

TEST(GsiCorpus, AbsAndRelSourcesUnderConstantVariableGravity) {
    const SceneDef s = load("sources_abs_rel.gsi");
    const auto& g = s.machines.gravity;
    ASSERT_TRUE(g.present);
    EXPECT_EQ(g.type, "constant");
    EXPECT_DOUBLE_EQ(g.g1, 9.81);
    EXPECT_DOUBLE_EQ(g.g2, 1.62);
    EXPECT_DOUBLE_EQ(g.t2, 0.03);
    EXPECT_DOUBLE_EQ(g.steps, 2);
    EXPECT_DOUBLE_EQ(g.ramp, 1);
    for (const Real t : {0.0, 0.015, 0.03}) EXPECT_DOUBLE_EQ(gravityAt(s, t), 9.81);  // CONSTANT: g1
    ASSERT_EQ(s.machines.sources.size(), 2u);
    ASSERT_EQ(s.shapes.size(), 2u);
    const auto& abs = s.machines.sources[0];
    EXPECT_EQ(abs.placement, "abs");
    EXPECT_VEC(abs.position, -0.02, 0.004);
    EXPECT_DOUBLE_EQ(abs.width, 0.02);
    EXPECT_DOUBLE_EQ(abs.interval, 0.01);
    EXPECT_DOUBLE_EQ(abs.from, 0);
    EXPECT_DOUBLE_EQ(abs.to, 0.025);
    EXPECT_EQ(abs.insert.shape, "source1");
    const auto& g1 = s.shapes[0];
    EXPECT_EQ(g1.name, "source1");
    EXPECT_VEC(g1.size, 0.0015, 0.001);
    EXPECT_DOUBLE_EQ(g1.sizeVariation, 0.2);
    EXPECT_EQ(g1.sizeMode, "gauss");
    EXPECT_EQ(g1.cornerCount, 9);
    EXPECT_EQ(g1.cornerVariation, 2);
    EXPECT_EQ(g1.cornerCountMode, "equal");
    EXPECT_EQ(g1.cornerAngles, "rand2");
    EXPECT_DOUBLE_EQ(g1.rotation, -0.785);
    EXPECT_EQ(g1.rotationMode, "gauss");
    const auto& rel = s.machines.sources[1];
    EXPECT_EQ(rel.placement, "rel");
    EXPECT_VEC(rel.position, 0.02, 0.006);
    EXPECT_DOUBLE_EQ(rel.width, 0.006);
    EXPECT_DOUBLE_EQ(rel.interval, 0.005);
    EXPECT_DOUBLE_EQ(rel.from, 0.002);
    EXPECT_DOUBLE_EQ(rel.to, 0.03);
    EXPECT_EQ(rel.insert.shape, "source2");
    const auto& g2 = s.shapes[1];
    EXPECT_VEC(g2.size, 0.0015, 0.0015);
    EXPECT_DOUBLE_EQ(g2.sizeVariation, 0.1);  // DROPSOURCE defaults
    EXPECT_EQ(g2.cornerVariation, 2);
    EXPECT_EQ(g2.sizeMode, "equal");
    EXPECT_EQ(g2.cornerCount, 6);
    EXPECT_EQ(g2.cornerCountMode, "const");
    EXPECT_EQ(g2.cornerAngles, "regular");  // written Random_Pos_Corners
    EXPECT_EQ(g2.rotationMode, "equal");
    EXPECT_TRUE(accepted(s).initial.particles.empty());
}

TEST(GsiCorpus, SourceGrainShapes) {
    const SceneDef s = load("source_shapes.gsi");
    ASSERT_EQ(s.machines.sources.size(), 2u);
    for (const auto& src : s.machines.sources) EXPECT_EQ(src.placement, "abs");  // TYPE default
    const auto& g1 = s.shapes[0];
    EXPECT_VEC(g1.size, 0.0015, 0.0012);
    EXPECT_EQ(g1.sizeMode, "const");
    EXPECT_EQ(g1.cornerCount, 8);
    EXPECT_EQ(g1.cornerCountMode, "gauss");
    EXPECT_EQ(g1.cornerAngles, "full");
    EXPECT_DOUBLE_EQ(g1.rotation, -0.2);
    EXPECT_EQ(g1.rotationMode, "const");
    const auto& g2 = s.shapes[1];
    EXPECT_VEC(g2.size, 0.002, 0.001);
    EXPECT_EQ(g2.cornerAngles, "special_rectangle");
    EXPECT_EQ(g2.sizeMode, "const");
    EXPECT_EQ(g2.rotationMode, "const");
    EXPECT_TRUE(accepted(s).initial.particles.empty());
}

TEST(GsiCorpus, SyntaxFeatures) {
    const GsiDocument d = parsed("syntax_features.gsi");
    EXPECT_EQ(d.identification, "  Syntax corpus\t--- identification text, kept as written");
    EXPECT_EQ(d.echoes,
              (std::vector<std::string>{"syntax corpus: an echoed line", "no blank after the dollar"}));
    ASSERT_EQ(d.objects.size(), 5u);  // GENERAL, DISPLAY, WALL, PARTICLE, DISPLAY; nothing after END_OF_FILE
    EXPECT_EQ(d.objects[1].kind, GsiObjectKind::Display);
    EXPECT_EQ(d.objects[1].find("SCREEN")->numbers, (std::vector<Real>{320, 240}));
    const auto* last = d.display();  // only the last DISPLAY counts
    ASSERT_NE(last, nullptr);
    EXPECT_EQ(last, &d.objects[4]);
    EXPECT_EQ(last->find("X_RANGE")->numbers, (std::vector<Real>{-0.06, 0.06}));
    EXPECT_EQ(last->find("Y_RANGE")->numbers, (std::vector<Real>{-0.02, 0.04}));
    EXPECT_EQ(last->find("SCREEN")->numbers, (std::vector<Real>{640, 0}));  // 0: keep the aspect ratio
    EXPECT_DOUBLE_EQ(last->find("INTERVAL")->numbers[0], 50);
    EXPECT_DOUBLE_EQ(last->find("MODUS")->numbers[0], 3);
    EXPECT_EQ(d.general().find("GAMMA")->numbers, (std::vector<Real>{0.5}));

    const SceneDef s = load("syntax_features.gsi");
    EXPECT_DOUBLE_EQ(s.dem.dt, 2e-5);
    EXPECT_DOUBLE_EQ(s.run.endTime, 0.02);
    EXPECT_DOUBLE_EQ(s.output.seriesInterval, 100 * 2e-5);
    EXPECT_EQ(s.run.title, "Syntax/MiXeD_Case");
    EXPECT_DOUBLE_EQ(law(s, "gamma"), 0.5);
    ASSERT_EQ(s.walls.size(), 1u);
    EXPECT_VEC(s.walls[0].offset, 0.001, 0);  // OFFSET 0.001: the second number 0
    EXPECT_EQ(s.walls[0].points.size(), 4u);
    EXPECT_VEC(s.walls[0].points[1], 0.05, -0.015);  // the corner line's trailing text ignored
    ASSERT_EQ(s.particles.size(), 1u);
    EXPECT_VEC(s.particles[0].position, 0.001, 0);  // COM 0.001
    EXPECT_EQ(s.shapes[0].corners.size(), 5u);
    EXPECT_EQ(accepted(s).initial.particles.size(), 1u);
}

TEST(GsiCorpus, CompressedScene) {
    const std::string path = kCorpus + "settling_squares.gsi.gz";
    const SceneDef s = load("settling_squares.gsi.gz");
    EXPECT_DOUBLE_EQ(s.dem.dt, 1e-5);
    EXPECT_DOUBLE_EQ(s.run.endTime, 0.02);
    EXPECT_DOUBLE_EQ(s.output.seriesInterval, 500 * 1e-5);
    ASSERT_EQ(s.walls.size(), 1u);
    EXPECT_EQ(s.walls[0].loc.file, path);
    EXPECT_EQ(s.walls[0].loc.line, 12);  // the lines of the decompressed text
    ASSERT_EQ(s.blocks.size(), 1u);
    EXPECT_EQ(s.blocks[0].lattice, BlockDef::Lattice::Rect);
    EXPECT_EQ(s.blocks[0].jitter, BlockDef::Jitter::None);
    EXPECT_VEC(s.blocks[0].grid, 0.01, 0.008);
    EXPECT_VEC(s.shapes[0].size, 0.003, 0.003);
    EXPECT_EQ(s.shapes[0].cornerAngles, "special_rectangle");
    EXPECT_EQ(accepted(s).initial.particles.size(), 4u);  // x -0.015 .. 0.015 in the row y 0.0041
}

// ---------------------------------------------------------------------------------------------
// (c) Malformed files: a SceneError naming file:line.

namespace {

struct Expectation {
    int line = 0;
    std::string text;
};

/// The "# expect LINE: TEXT" lines of a malformed file.
std::vector<Expectation> expectationsOf(const std::string& path) {
    std::vector<Expectation> out;
    std::stringstream lines(textOf(path));
    const std::string tag = "# expect ";
    for (std::string l; std::getline(lines, l);)
        if (l.rfind(tag, 0) == 0) {
            const auto colon = l.find(": ", tag.size());
            out.push_back({std::stoi(l.substr(tag.size(), colon - tag.size())), l.substr(colon + 2)});
        }
    return out;
}

}  // namespace

TEST(GsiCorpus, MalformedFilesFailAtTheirLine) {
    std::vector<std::string> paths;
    for (const auto& e : fs::directory_iterator(kCorpus + "bad"))
        if (e.path().extension() == ".gsi") paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
    EXPECT_GE(paths.size(), 10u);
    for (const auto& path : paths) {
        SCOPED_TRACE(path);
        const auto expected = expectationsOf(path);
        ASSERT_FALSE(expected.empty()) << "no '# expect LINE: TEXT' line";
        try {
            accepted(granulab::io::readGsiFile(path));
            ADD_FAILURE() << "accepted";
        } catch (const SceneError& e) {
            const std::string what = e.what();
            for (const auto& x : expected) {
                EXPECT_NE(what.find(path + ":" + std::to_string(x.line) + ":"), std::string::npos) << what;
                const bool found =
                    std::any_of(e.diagnostics().begin(), e.diagnostics().end(), [&](const auto& d) {
                        return d.loc.file == path && d.loc.line == x.line &&
                               d.message.find(x.text) != std::string::npos;
                    });
                EXPECT_TRUE(found) << "line " << x.line << ": " << x.text << "\n" << what;
            }
        }
    }
}
