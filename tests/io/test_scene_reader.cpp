// SPDX-License-Identifier: MIT
// Scene reader: overrides, unknown keys with hints, file:line in messages, the engines' section
// readers (io/scene_reader.hpp SceneSections).
#include <gtest/gtest.h>

#include "../support/scene.hpp"
#include "io/scene_reader.hpp"
#include "io/toml_table_reader.hpp"

using namespace granulab;

namespace {
const char* kScene = R"([run]
end_time = 1.0
[dem]
dt = 1e-4
[[material]]
name = "g"
density = 2.0
[[contact]]
materials = ["g", "g"]
kn = 1e5
)";

std::string errorsOf(const std::string& text, const std::vector<io::Override>& ov = {}) {
    try {
        test::readSceneText(text, "s.toml", ov);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(SceneReader, ReadsValuesAndAppliesOverrides) {
    const auto sc = test::readSceneText(
        kScene, "s.toml",
        {io::parseOverride("dem.dt=2e-5"), io::parseOverride("dem.integrator=verlet"),
         io::parseOverride("contact[0].kn=3e5"), io::parseOverride("material[0].density=4")});
    EXPECT_DOUBLE_EQ(sc.dem.dt, 2e-5);
    EXPECT_EQ(sc.dem.integrator, "verlet");
    EXPECT_DOUBLE_EQ(sc.contacts[0].params.at("kn").value, 3e5);
    EXPECT_DOUBLE_EQ(sc.materials[0].density, 4.0);
    EXPECT_DOUBLE_EQ(sc.run.endTime, 1.0);
}

TEST(SceneReader, UnknownKeyHasHintAndLine) {
    const std::string err = errorsOf(std::string(kScene) + "[output]\nsnapshot_intervall = 0.1\n");
    EXPECT_NE(err.find("s.toml:12"), std::string::npos) << err;
    EXPECT_NE(err.find("did you mean 'snapshot_interval'"), std::string::npos) << err;
}

TEST(SceneReader, AllErrorsReportedTogether) {
    const std::string err = errorsOf("[run]\nend_time = \"x\"\n[dem]\ndtt = 1\n[bogus]\n");
    EXPECT_NE(err.find("end_time"), std::string::npos) << err;
    EXPECT_NE(err.find("dtt"), std::string::npos) << err;
    EXPECT_NE(err.find("bogus"), std::string::npos) << err;
}

TEST(SceneReader, OverrideOfMissingArrayElementIsAnError) {
    const std::string err = errorsOf(kScene, {io::parseOverride("contact[3].kn=1")});
    EXPECT_NE(err.find("no element [3]"), std::string::npos) << err;
    EXPECT_THROW(io::parseOverride("novalue"), SceneError);
}

TEST(SceneReader, UnknownEngineListsTheEnginesOfTheTable) {
    const std::string err = errorsOf("[run]\nengine = \"nope\"\nend_time = 1.0\n[dem]\ndt = 1e-4\n");
    EXPECT_NE(err.find("s.toml:2: run.engine: 'nope' is not allowed; allowed: dem, edmd"), std::string::npos)
        << err;
    // No engine runs: its sections are neither read nor reported as another engine's.
    EXPECT_EQ(err.find("[dem]"), std::string::npos) << err;
}

TEST(SceneReader, SectionOfAnotherEngineNamesItsEngine) {
    const std::string dem = errorsOf(std::string(kScene) + "[edmd]\ncount = 10\n");
    EXPECT_NE(
        dem.find("s.toml:11: edmd: [edmd] belongs to the edmd engine; this scene runs run.engine = \"dem\""),
        std::string::npos)
        << dem;
    const std::string edmd =
        errorsOf("[run]\nengine = \"edmd\"\nend_time = 1.0\n[edmd]\ncount = 10\n[[wall]]\n");
    EXPECT_NE(edmd.find("wall: [wall] belongs to the dem engine; this scene runs run.engine = \"edmd\""),
              std::string::npos)
        << edmd;
    EXPECT_EQ(errorsOf("[run]\nengine = \"edmd\"\nend_time = 1.0\n"),
              "error: s.toml:1: edmd: missing section [edmd] (the event-driven gas: count or "
              "volume_fraction, radius)\n");
}

namespace {
// A third engine defined here only: a new engine needs a SceneSections row and its reader, and
// no edit of io/scene_reader.cpp.
std::int64_t toyGrains = 0;

void readToy(io::TableReader& root, model::SceneDef& scene) {
    io::withTable(root, "toy", [&](io::TableReader& t) {
        t.integer("grains", toyGrains);
        t.string("label", scene.run.title);
    });
    io::forEachTable(root, "material", [&](io::TableReader& t, std::size_t) {
        scene.materials.emplace_back();
        t.string("name", scene.materials.back().name);
    });
}

std::vector<io::SceneSections> withToy() {
    io::SceneSections toy;
    toy.engine = "toy";
    toy.sections = {"toy", "material"};  // shares [[material]] with dem
    toy.required = "toy";
    toy.requiredHint = "needs at least grains";
    toy.needsEndTime = false;
    toy.read = &readToy;
    auto engines = test::sceneSections();
    engines.push_back(toy);
    return engines;
}

std::string toyErrorsOf(const std::string& text, const std::vector<io::SceneSections>& engines = withToy()) {
    try {
        io::readSceneText(text, "toy.toml", {}, engines);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(SceneReader, ThirdEngineReadsItsOwnSectionsThroughItsRow) {
    toyGrains = 0;
    const auto sc = io::readSceneText("[run]\nengine = \"toy\"\n[toy]\ngrains = 7\nlabel = \"t\"\n",
                                      "toy.toml", {io::parseOverride("toy.grains=9")}, withToy());
    EXPECT_EQ(toyGrains, 9);
    EXPECT_EQ(sc.run.engine, "toy");
    EXPECT_EQ(sc.run.title, "t");
    // The other engines still read their scenes with the toy row in the table.
    EXPECT_DOUBLE_EQ(io::readSceneText(kScene, "s.toml", {}, withToy()).dem.dt, 1e-4);

    EXPECT_NE(toyErrorsOf("[run]\nengine = \"toy\"\n[toy]\ngrainz = 7\n")
                  .find("toy.toml:4: toy.grainz: unknown key "
                        "(did you mean 'grains'?)"),
              std::string::npos);
    EXPECT_NE(
        toyErrorsOf("[run]\nengine = \"toy\"\n").find("toy: missing section [toy] (needs at least grains)"),
        std::string::npos);
    EXPECT_NE(
        toyErrorsOf("[run]\nengine = \"toy\"\n[toy]\n[dem]\ndt = 1.0\n")
            .find("toy.toml:4: dem: [dem] belongs to the dem engine; this scene runs run.engine = \"toy\""),
        std::string::npos);
    EXPECT_NE(
        toyErrorsOf(std::string(kScene) + "[toy]\ngrains = 1\n")
            .find("toy.toml:11: toy: [toy] belongs to the toy engine; this scene runs run.engine = \"dem\""),
        std::string::npos);
    // [[material]] is shared by dem and toy: read by the running one, no error for the other.
    const auto shared =
        io::readSceneText("[run]\nengine = \"toy\"\n[toy]\ngrains = 1\n[[material]]\nname = \"g\"\n",
                          "toy.toml", {}, withToy());
    ASSERT_EQ(shared.materials.size(), 1u);
    EXPECT_EQ(shared.materials[0].name, "g");
    EXPECT_NE(toyErrorsOf("[run]\nengine = \"toy\"\n[toy]\n[[material]]\ndensity = 1.0\n")
                  .find("material[0].density: unknown key"),
              std::string::npos);
    EXPECT_NE(toyErrorsOf("[run]\nengine = \"nope\"\n")
                  .find("run.engine: 'nope' is not allowed; allowed: dem, edmd, toy"),
              std::string::npos);
    // A table without the default engine: run.engine must be given.
    EXPECT_NE(toyErrorsOf("[run]\n[toy]\n", {withToy().back()})
                  .find("toy.toml:1: run.engine: missing: the engine, "
                        "allowed: toy"),
              std::string::npos);
}
