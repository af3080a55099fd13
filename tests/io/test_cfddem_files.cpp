// SPDX-License-Identifier: MIT
// The cfddem seed's three input files (io/cfddem_files.hpp; cfddem spec 6.2-6.5): the Defs they
// map to, both layouts of the values and both spellings of the start file, errors with file:line,
// and the exact round trip through the native TOML text (io/scene_toml_writer.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../support.hpp"
#include "../support/cfddem_trio.hpp"
#include "io/cfddem_files.hpp"
#include "io/scene_toml_writer.hpp"

using namespace granulab;
using test::CfddemTrio;
using test::replaced;

namespace {

namespace fs = std::filesystem;

/// The errors of reading `trio` (empty when it reads).
std::string errorsOf(const CfddemTrio& trio, const fs::path& dir) {
    trio.write(dir);
    try {
        io::readCfddemFolder(dir.string());
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

const model::ContactDef& lawFor(const model::SceneDef& s, const std::string& a) {
    for (const auto& c : s.contacts)
        if (c.materialA == a) return c;
    throw std::runtime_error("no law for " + a);
}

}  // namespace

TEST(CfddemFiles, ReadsTheThreeFilesIntoDemDefs) {
    test::ScratchDir tmp;
    const CfddemTrio trio;
    trio.write(tmp.path);
    EXPECT_TRUE(io::isCfddemFolder(tmp.path.string()));
    const model::SceneDef s = io::readCfddemFolder(tmp.path.string());
    EXPECT_EQ(s.path, (tmp.path / "conditions.txt").string());
    EXPECT_EQ(s.run.engine, "dem");
    EXPECT_EQ(s.run.title, "Datei mit Bedingungen");
    EXPECT_EQ(s.run.endTime, 0.1);
    // conditions.txt
    EXPECT_EQ(s.dem.dt, 2e-5);
    EXPECT_EQ(s.dem.integrator, "pc");
    EXPECT_EQ(s.dem.pcTolerance, 1e-3);
    EXPECT_EQ(s.dem.pcIterations, 4);
    EXPECT_EQ(s.dem.pcCorrector, 0.5);
    EXPECT_EQ(s.dem.massModel, "sphere");
    EXPECT_TRUE(s.dem.overlapGuard);
    EXPECT_EQ(s.dem.gravity.y, -9.81);
    EXPECT_TRUE(s.dem.weight && s.dem.particleContacts && s.dem.wallContacts);
    EXPECT_EQ(s.dem.loc.line, 3);  // #DT
    ASSERT_TRUE(s.fluid.present);
    EXPECT_EQ(s.fluid.density, 1.25);
    EXPECT_EQ(s.fluid.drag, "quadratic");
    EXPECT_EQ(s.fluid.cw, 0.47);
    EXPECT_TRUE(s.fluid.buoyancy);
    EXPECT_EQ(s.fluid.timing, "even");
    EXPECT_TRUE(s.fluid.fields.empty());
    EXPECT_FALSE(s.attraction.present);
    EXPECT_DOUBLE_EQ(s.output.seriesInterval, 250 * 2e-5);
    EXPECT_DOUBLE_EQ(s.output.snapshotInterval, 2500 * 2e-5);
    EXPECT_TRUE(s.output.vtk);
    EXPECT_TRUE(s.output.particleSeries);
    // startvalue.txt: three particles, one material; the inlet's (nu 0.25) is a second one
    ASSERT_EQ(s.particles.size(), 3u);
    EXPECT_EQ(s.particles[1].position.x, 0.10);
    EXPECT_EQ(s.particles[1].position.y, 0.22);
    EXPECT_EQ(s.particles[1].velocity.x, 0.1);
    EXPECT_EQ(s.particles[2].velocity.y, -0.2);
    EXPECT_EQ(s.particles[2].angle, 0.5);
    EXPECT_EQ(s.particles[2].omega, 1.0);
    EXPECT_EQ(s.particles[2].radius, 0.012);
    EXPECT_EQ(s.particles[0].material, "m1");
    EXPECT_EQ(s.particles[2].loc.line, 3);  // all #RX on line 3
    ASSERT_EQ(s.materials.size(), 3u);
    EXPECT_EQ(s.materials[0].name, "m1");
    EXPECT_EQ(s.materials[0].density, 1000.0);
    EXPECT_EQ(s.materials[0].youngsModulus, 1e7);
    EXPECT_EQ(s.materials[0].poisson, 0.3);
    EXPECT_EQ(s.materials[1].name, "wall");
    EXPECT_EQ(s.materials[1].density, 0.0);
    EXPECT_EQ(s.materials[1].youngsModulus, 1e8);
    EXPECT_EQ(s.materials[2].name, "m2");
    EXPECT_EQ(s.materials[2].poisson, 0.25);
    // boundary.txt: 0-based edges, types, wall material, the inlet's state and rate (#PS)
    ASSERT_EQ(s.machines.boundaries.size(), 1u);
    const auto& b = s.machines.boundaries[0];
    ASSERT_EQ(b.points.size(), 6u);
    EXPECT_EQ(b.points[3].x, 0.12);
    ASSERT_EQ(b.edges.size(), 6u);
    EXPECT_EQ(b.edges[0].from, 0);
    EXPECT_EQ(b.edges[0].to, 1);
    EXPECT_EQ(b.edges[5].to, 0);
    EXPECT_EQ(b.edges[0].type, "inlet");
    EXPECT_EQ(b.edges[1].type, "wall");
    EXPECT_EQ(b.edges[3].type, "outlet");
    EXPECT_EQ(b.material, "wall");
    EXPECT_EQ(b.rate, 20.0);
    EXPECT_EQ(b.insert.material, "m2");
    EXPECT_EQ(b.insert.radius.value, 0.008);
    EXPECT_EQ(b.insert.velocity.y, -1.5);
    EXPECT_TRUE(s.machines.inlets.empty());
    // [[contact]]: the seed's laws; particle-wall with mu = #WM
    ASSERT_EQ(s.contacts.size(), 2u);
    const auto& pp = lawFor(s, "*");
    EXPECT_EQ(pp.materialB, "*");
    EXPECT_EQ(pp.normal, "hertz");
    EXPECT_EQ(pp.damping, "lehr");
    EXPECT_EQ(pp.tangential, "mindlin");
    EXPECT_EQ(pp.rolling, "spring_dashpot");
    EXPECT_EQ(pp.params.at("D_n").value, 0.3);
    EXPECT_EQ(pp.params.at("D_t").value, 0.2);
    EXPECT_EQ(pp.params.at("D_r").value, 0.1);
    EXPECT_EQ(pp.params.at("k_r").value, 0.001);
    EXPECT_EQ(pp.params.at("mu").value, 0.5);
    EXPECT_EQ(pp.params.at("mu").loc.line, 13);
    const auto& pw = lawFor(s, "wall");
    EXPECT_EQ(pw.materialB, "*");
    EXPECT_EQ(pw.params.at("mu").value, 0.4);
    EXPECT_EQ(pw.params.at("D_n").value, 0.3);
    EXPECT_NE(pw.params.at("mu").loc.file.find("boundary.txt"), std::string::npos);
}

TEST(CfddemFiles, OneLineAndOneValuePerLineLayoutsGiveTheSameScene) {
    test::ScratchDir tmp;
    CfddemTrio a;
    CfddemTrio b;
    // One line per particle and key, interleaved, with a trailing comment.
    b.start = R"(info
#RX 0.05
#RY 0.20
#VX 0
#VY 0
#PH 0
#OM 0
#RA 0.01
#RH 1000
#EM 1e7
#NU 0.3
#RX 0.10 // second ball
#RY 0.22
#VX 0.1
#VY 0
#PH 0
#OM 0
#RA 0.01
#RH 1000
#EM 1e7
#NU 0.3
#RX 0.15
#RY 0.18
#VX 0
#VY -0.2
#PH 0.5
#OM 1
#RA 0.012
#RH 1000
#EM 1e7
#NU 0.3
)";
    // All points on one line, separated by commas and tabs.
    b.boundary = replaced(b.boundary, "#PX 0\n#PX 0.2\n#PX 0.2\n#PX 0.12\n#PX 0.08\n#PX 0\n",
                          "#PX 0,0.2,\t0.2 ; 0.12 0.08 +0\n");
    a.write(tmp.path / "a");
    b.write(tmp.path / "b");
    const model::SceneDef sa = io::readCfddemFolder((tmp.path / "a").string());
    const model::SceneDef sb = io::readCfddemFolder((tmp.path / "b").string());
    ASSERT_EQ(sa.particles.size(), sb.particles.size());
    for (std::size_t k = 0; k < sa.particles.size(); ++k) {
        EXPECT_EQ(sa.particles[k].position, sb.particles[k].position);
        EXPECT_EQ(sa.particles[k].velocity, sb.particles[k].velocity);
        EXPECT_EQ(sa.particles[k].angle, sb.particles[k].angle);
        EXPECT_EQ(sa.particles[k].omega, sb.particles[k].omega);
        EXPECT_EQ(sa.particles[k].radius, sb.particles[k].radius);
        EXPECT_EQ(sa.particles[k].material, sb.particles[k].material);
    }
    EXPECT_EQ(sb.particles[1].loc.line, 12);  // the line of its #RX
    ASSERT_EQ(sb.machines.boundaries.size(), 1u);
    EXPECT_EQ(sa.machines.boundaries[0].points, sb.machines.boundaries[0].points);
}

TEST(CfddemFiles, AcceptsBothSpellingsOfTheStartFileButNotBoth) {
    test::ScratchDir tmp;
    CfddemTrio trio;
    trio.startName = "startvalues.txt";
    trio.write(tmp.path);
    EXPECT_TRUE(io::isCfddemFolder(tmp.path.string()));
    EXPECT_EQ(io::readCfddemFolder(tmp.path.string()).particles.size(), 3u);
    test::writeText(tmp.path / "startvalue.txt", trio.start);
    try {
        io::readCfddemFolder(tmp.path.string());
        FAIL() << "both start files accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("both startvalue.txt and startvalues.txt"), std::string::npos)
            << e.what();
    }
}

TEST(CfddemFiles, RecognisesTheFolder) {
    test::ScratchDir tmp;
    EXPECT_FALSE(io::isCfddemFolder(tmp.path.string()));
    EXPECT_FALSE(io::hasCfddemFiles(tmp.path.string()));
    EXPECT_FALSE(io::isCfddemFolder((tmp.path / "nothing").string()));
    test::writeText(tmp.path / "conditions.txt", "x\n");
    EXPECT_FALSE(io::isCfddemFolder(tmp.path.string()));
    EXPECT_TRUE(io::hasCfddemFiles(tmp.path.string()));
    EXPECT_FALSE(io::hasCfddemFiles((tmp.path / "conditions.txt").string()));  // a file, not a folder
}

TEST(CfddemFiles, BadInputIsReportedWithFileAndLine) {
    test::ScratchDir tmp;
    const CfddemTrio base;
    struct Case {
        const char* name;
        CfddemTrio trio;
        std::string expected;
    };
    std::vector<Case> cases;
    const auto add = [&](const char* name, std::string CfddemTrio::*file, const std::string& from,
                         const std::string& to, const std::string& expected) {
        CfddemTrio t = base;
        t.*file = replaced(t.*file, from, to);
        cases.push_back({name, t, expected});
    };
    add("bad number", &CfddemTrio::start, "#RY 0.20 0.22", "#RY 0.20 0.2x2",
        "startvalue.txt:4: #RY: '0.2x2' is not a number");
    add("mismatched lengths", &CfddemTrio::start, "#RY 0.20 0.22 0.18", "#RY 0.20 0.22",
        "startvalue.txt:4: #RY: 2 values, but #RX has 3 (one per particle)");
    add("edge index 0", &CfddemTrio::boundary, "#E1 1 2 3", "#E1 0 2 3",
        "boundary.txt:11: #E1: edge 1: point index 0 out of range; allowed 1 ... 6");
    add("edge index too big", &CfddemTrio::boundary, "#E2 2 3 4 5 6 1", "#E2 2 3 4 5 6 7",
        "boundary.txt:12: #E2: edge 6: point index 7 out of range; allowed 1 ... 6");
    add("edge type", &CfddemTrio::boundary, "#EB 3 1 1 2 1 1", "#EB 3 1 1 4 1 1",
        "boundary.txt:13: #EB: edge 4: type 4 is not allowed; allowed: 1 (wall), 2 (outlet), 3 (inlet)");
    add("unknown key", &CfddemTrio::start, "#OM 0 0 1", "#OX 0 0 1",
        "startvalue.txt:8: #OX: unknown key (did you mean '#OM'?)");
    add("case of a key", &CfddemTrio::conditions, "#Fw 1", "#fw 1",
        "conditions.txt:16: #fw: unknown key (keys are case-sensitive: did you mean '#Fw'?)");
    add("key of another file", &CfddemTrio::boundary, "#WM 0.4", "#WM 0.4\n#PS 3",
        "boundary.txt:17: #PS: this key belongs to conditions.txt, not to boundary.txt");
    add("negative radius", &CfddemTrio::start, "#RA 0.01 0.01 0.012", "#RA 0.01 -0.01 0.012",
        "startvalue.txt:9: #RA: radius must be > 0 [m], got -0.01");
    add("Poisson ratio", &CfddemTrio::start, "#NU 0.3 0.3 0.3", "#NU 0.3 0.5 0.3",
        "startvalue.txt:12: #NU: Poisson ratio must be in [0, 0.5), got 0.5");
    add("two time steps", &CfddemTrio::conditions, "#DT 2e-5", "#DT 2e-5 1e-5",
        "conditions.txt:3: #DT: expects one value, got 2");
    add("flag", &CfddemTrio::conditions, "#FG 0", "#FG 2",
        "conditions.txt:17: #FG: a switch is 0 (off) or 1 (on), got 2");
    add("whole number", &CfddemTrio::conditions, "#PK 4", "#PK 2.5",
        "conditions.txt:6: #PK: expects a whole number in [0, 1000], got 2.5");
    add("z of a point", &CfddemTrio::boundary, "#PZ 0 0 0 0 0 0", "#PZ 0 0 0 0 0.1 0",
        "boundary.txt:9: #PZ: the model is 2D: z must be 0 [m], got 0.1");
    add("missing end time", &CfddemTrio::conditions, "#TE 0.1\n", "",
        "conditions.txt: #TE: missing: the end time t_end [s]");
    add("inlet state per inlet", &CfddemTrio::boundary, "#VY -1.5", "#VY -1.5 -2",
        "boundary.txt:19: #VY: 2 values, but the boundary has 1 (1 inlet edge, or one for all)");
    add("missing wall friction", &CfddemTrio::boundary, "#WM 0.4\n", "",
        "boundary.txt: #WM: missing: the wall-particle friction coefficient (the boundary has wall edges)");
    add("CFD without fluid", &CfddemTrio::conditions, "#RF 1.25", "#RF 0\n#CF cfd",
        "conditions.txt:13: #CF: the CFD fields need a fluid: set the fluid density #RF > 0 [kg/m^3]");
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const std::string errors = errorsOf(cases[k].trio, tmp.path / std::to_string(k));
        EXPECT_NE(errors.find(cases[k].expected), std::string::npos)
            << cases[k].name << ": expected '" << cases[k].expected << "' in\n"
            << errors;
    }
}

TEST(CfddemFiles, MissingFilesAreNamed) {
    test::ScratchDir tmp;
    CfddemTrio().write(tmp.path);
    fs::remove(tmp.path / "boundary.txt");
    fs::remove(tmp.path / "startvalue.txt");
    try {
        io::readCfddemFolder(tmp.path.string());
        FAIL() << "missing files accepted";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find((tmp.path / "boundary.txt").string() + ": missing: the boundary file"),
                  std::string::npos)
            << what;
        EXPECT_NE(what.find("missing: startvalue.txt or startvalues.txt"), std::string::npos) << what;
    }
}

TEST(CfddemFiles, InletsWithTheirOwnStatesBecomeInlets) {
    test::ScratchDir tmp;
    CfddemTrio trio;
    // A second inlet: the top edge split in two (points 7 = (0.1, 0.3)), radii per inlet.
    trio.boundary = replaced(trio.boundary, "#PX 0\n#PY 0.3 0.3 0 0 0 0\n#PZ 0 0 0 0 0 0\n#PB 3 3 1 2 2 1",
                             "#PX 0\n#PX 0.1\n#PY 0.3 0.3 0 0 0 0 0.3\n#PZ 0 0 0 0 0 0 0\n#PB 3 3 1 2 2 1 3");
    trio.boundary = replaced(trio.boundary, "#E1 1 2 3 4 5 6\n#E2 2 3 4 5 6 1\n#EB 3 1 1 2 1 1",
                             "#E1 1 7 2 3 4 5 6\n#E2 7 2 3 4 5 6 1\n#EB 3 3 1 1 2 1 1");
    trio.boundary = replaced(trio.boundary, "#RA 0.008", "#RA 0.008 0.006");
    trio.write(tmp.path);
    const model::SceneDef s = io::readCfddemFolder(tmp.path.string());
    ASSERT_EQ(s.machines.inlets.size(), 2u);
    EXPECT_EQ(s.machines.inlets[0].a, (Vec2{0, 0.3}));
    EXPECT_EQ(s.machines.inlets[0].b, (Vec2{0.1, 0.3}));
    EXPECT_EQ(s.machines.inlets[0].insert.radius.value, 0.008);
    EXPECT_EQ(s.machines.inlets[1].insert.radius.value, 0.006);
    EXPECT_EQ(s.machines.inlets[1].rate, 20.0);
    EXPECT_EQ(s.machines.inlets[1].insert.material, "m2");  // same (rho, E, nu)
    ASSERT_EQ(s.machines.boundaries.size(), 1u);
    EXPECT_EQ(s.machines.boundaries[0].edges.size(), 5u);  // the inlet edges left the boundary
}

TEST(CfddemFiles, ConditionsSwitchTheForcesAndOutputs) {
    test::ScratchDir tmp;
    CfddemTrio trio;
    trio.conditions = replaced(trio.conditions, "#Fg 1", "#Fg 0");
    trio.conditions = replaced(trio.conditions, "#Fw 1", "#Fw 0");
    trio.conditions = replaced(trio.conditions, "#FA 1", "#FA 0");
    trio.conditions = replaced(trio.conditions, "#FG 0", "#FG 1");
    trio.conditions = replaced(trio.conditions, "#FP 1", "#FP 0");
    trio.conditions = replaced(trio.conditions, "#FB 1", "#FB 0");
    trio.conditions = replaced(trio.conditions, "#SC 250", "#SC 0");
    trio.conditions = replaced(trio.conditions, "#SV 2500", "#SV 0");
    trio.conditions += "#CF \"cfd data/U.vtk\" more\n";
    trio.write(tmp.path);
    const model::SceneDef s = io::readCfddemFolder(tmp.path.string());
    EXPECT_FALSE(s.dem.weight);
    EXPECT_FALSE(s.dem.particleContacts);
    EXPECT_FALSE(s.dem.wallContacts);
    EXPECT_EQ(s.fluid.drag, "none");
    EXPECT_FALSE(s.fluid.buoyancy);
    EXPECT_EQ(s.fluid.fields, (std::vector<std::string>{"cfd data/U.vtk", "more"}));
    ASSERT_EQ(s.fluid.fieldLocs.size(), 2u);
    EXPECT_EQ(s.fluid.fieldLocs[0].line, 23);
    ASSERT_TRUE(s.attraction.present);
    EXPECT_EQ(s.attraction.constant, 6.674e-11);
    EXPECT_EQ(s.output.seriesInterval, 0.0);
    EXPECT_FALSE(s.output.particleSeries);
    EXPECT_FALSE(s.output.vtk);

    // No fluid density: no [fluid]; no walls: no wall law and no wall material.
    CfddemTrio dry;
    dry.conditions = replaced(dry.conditions, "#RF 1.25\n", "");
    dry.boundary = replaced(dry.boundary, "#EB 3 1 1 2 1 1", "#EB 3 2 2 2 2 2");
    dry.write(tmp.path / "dry");
    const model::SceneDef d = io::readCfddemFolder((tmp.path / "dry").string());
    EXPECT_FALSE(d.fluid.present);
    EXPECT_EQ(d.contacts.size(), 1u);
    EXPECT_EQ(d.materials.size(), 2u);
    EXPECT_TRUE(d.machines.boundaries.at(0).material.empty());
}

TEST(CfddemFiles, TomlTextReadsBackToTheSameDefs) {
    test::ScratchDir tmp;
    CfddemTrio trio;
    trio.start = replaced(trio.start, "#RX 0.05", "#RX 0.0512345678901234567");
    trio.start = replaced(trio.start, "#OM 0 0 1", "#OM -0 0 1");
    trio.conditions += "#CF cfd\n";
    trio.write(tmp.path / "trio");
    const model::SceneDef a = io::readCfddemFolder((tmp.path / "trio").string());
    const std::string tomlPath = (tmp.path / "elsewhere" / "scene.toml").string();
    const std::string text = io::sceneToToml(a, tomlPath);
    const model::SceneDef b = test::readSceneText(text, tomlPath);
    EXPECT_EQ(b.run.endTime, a.run.endTime);
    EXPECT_EQ(b.run.title, a.run.title);
    EXPECT_EQ(b.dem.dt, a.dem.dt);
    EXPECT_EQ(b.dem.pcTolerance, a.dem.pcTolerance);
    EXPECT_EQ(b.dem.pcIterations, a.dem.pcIterations);
    EXPECT_EQ(b.dem.overlapGuard, a.dem.overlapGuard);
    EXPECT_EQ(b.dem.massModel, a.dem.massModel);
    EXPECT_EQ(b.dem.gravity, a.dem.gravity);
    ASSERT_EQ(b.particles.size(), a.particles.size());
    for (std::size_t k = 0; k < a.particles.size(); ++k) {
        EXPECT_EQ(b.particles[k].position, a.particles[k].position);
        EXPECT_EQ(b.particles[k].velocity, a.particles[k].velocity);
        EXPECT_EQ(b.particles[k].omega, a.particles[k].omega);
        EXPECT_EQ(std::signbit(b.particles[k].omega), std::signbit(a.particles[k].omega));
        EXPECT_EQ(b.particles[k].radius, a.particles[k].radius);
        EXPECT_EQ(b.particles[k].material, a.particles[k].material);
    }
    ASSERT_EQ(b.materials.size(), a.materials.size());
    for (std::size_t k = 0; k < a.materials.size(); ++k) {
        EXPECT_EQ(b.materials[k].name, a.materials[k].name);
        EXPECT_EQ(b.materials[k].density, a.materials[k].density);
        EXPECT_EQ(b.materials[k].youngsModulus, a.materials[k].youngsModulus);
        EXPECT_EQ(b.materials[k].poisson, a.materials[k].poisson);
    }
    ASSERT_EQ(b.contacts.size(), a.contacts.size());
    for (std::size_t k = 0; k < a.contacts.size(); ++k) {
        EXPECT_EQ(b.contacts[k].materialA, a.contacts[k].materialA);
        EXPECT_EQ(b.contacts[k].rolling, a.contacts[k].rolling);
        ASSERT_EQ(b.contacts[k].params.size(), a.contacts[k].params.size());
        for (const auto& [key, p] : a.contacts[k].params)
            EXPECT_EQ(b.contacts[k].params.at(key).value, p.value);
    }
    ASSERT_EQ(b.machines.boundaries.size(), 1u);
    const auto &ba = a.machines.boundaries[0], &bb = b.machines.boundaries[0];
    EXPECT_EQ(bb.points, ba.points);
    ASSERT_EQ(bb.edges.size(), ba.edges.size());
    for (std::size_t k = 0; k < ba.edges.size(); ++k) {
        EXPECT_EQ(bb.edges[k].from, ba.edges[k].from);
        EXPECT_EQ(bb.edges[k].to, ba.edges[k].to);
        EXPECT_EQ(bb.edges[k].type, ba.edges[k].type);
    }
    EXPECT_EQ(bb.rate, ba.rate);
    EXPECT_EQ(bb.insert.radius.value, ba.insert.radius.value);
    EXPECT_EQ(bb.insert.velocity, ba.insert.velocity);
    EXPECT_EQ(bb.insert.material, ba.insert.material);
    EXPECT_EQ(b.fluid.present, a.fluid.present);
    EXPECT_EQ(b.fluid.density, a.fluid.density);
    EXPECT_EQ(b.fluid.cw, a.fluid.cw);
    EXPECT_EQ(b.fluid.timing, a.fluid.timing);
    EXPECT_EQ(b.fluid.fields, (std::vector<std::string>{"../trio/cfd"}));  // relative to the TOML file
    EXPECT_EQ(b.output.seriesInterval, a.output.seriesInterval);
    EXPECT_EQ(b.output.snapshotInterval, a.output.snapshotInterval);
    EXPECT_EQ(b.output.particleSeries, a.output.particleSeries);
    EXPECT_EQ(b.output.vtk, a.output.vtk);
}

TEST(CfddemFiles, ALatinOneInfoLineBecomesAUtf8Title) {
    test::ScratchDir tmp;
    CfddemTrio trio;
    trio.conditions = replaced(trio.conditions, "Datei mit Bedingungen", "Bedingungen f\xFCr T6");
    trio.write(tmp.path);
    const model::SceneDef s = io::readCfddemFolder(tmp.path.string());
    EXPECT_EQ(s.run.title, "Bedingungen f\xC3\xBCr T6");
    const model::SceneDef back = test::readSceneText(io::sceneToToml(s, "s.toml"), "s.toml");
    EXPECT_EQ(back.run.title, s.run.title);
    EXPECT_THROW(io::tomlString("f\xFCr"), std::invalid_argument);
}
