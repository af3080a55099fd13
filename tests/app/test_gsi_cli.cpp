// SPDX-License-Identifier: MIT
// gc2d's gsi scenes on the command line (io/gsi_scene.hpp): `granulab run scene.gsi` runs the
// thesis's piston sample; a malformed gsi exits with status 2 naming file:line.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "../support.hpp"

using namespace granulab;

TEST(Cli, GsiPistonSampleRuns) {
    test::ScratchDir tmp;
    const std::string scene = std::string(GRANULAB_SOURCE_DIR) + "/examples/gc2d/piston.gsi";
    const auto run = test::runGranulab("run " + scene + " --out piston -q", tmp.path, 240);
    ASSERT_EQ(run.status, 0) << run.output;
    const auto summary = nlohmann::json::parse(test::readText(tmp.path / "piston" / "summary.json"));
    EXPECT_EQ(summary["particles"].get<int>(), 1173);  // the FCC block of 7-9-gons
    EXPECT_EQ(summary["integrator"], "gear");
    EXPECT_NEAR(summary["sim_time"].get<double>(), 0.2, 1.5e-5);  // whole steps of 1.5e-5 s
    // The piston (wall1) pushes the grains along +x against the far wall (wall4), which then
    // feels them; gravity is off.
    const auto& walls = summary["wall_forces"];
    ASSERT_EQ(walls.size(), 4u);
    EXPECT_LT(walls[0]["force"][0].get<double>(), 0);  // the grains push back on the piston
}

TEST(Cli, GsiErrorsExitTwoWithFileAndLine) {
    test::ScratchDir tmp;
    test::writeText(tmp.path / "bad.gsi",
                    "PARAMETER v1.4\n\nDelta_T 1e-5\nWALL\nCorners\n0 0\n1 0\n# no\n0 1\nEND\n");
    const auto run = test::runGranulab("run bad.gsi --out bad -q", tmp.path, 60);
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find("bad.gsi:8"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("a CORNERS block allows no comments"), std::string::npos) << run.output;
}

TEST(Cli, GsiCorpusScenesRun) {
    // tests/data/gsi: each file exercises other objects and keywords (a REL drop source, a tapping
    // floor with SPECIAL_RECTANGLE grains, variable gravity with heating and cohesion, a pulled
    // block on a belt with a DISPLAY); each maps onto scene Defs the engine accepts, and runs.
    const std::pair<const char*, int> corpus[] = {
        {"drop_pile", 25}, {"vibrated_bed", 60}, {"tilted_gravity", 20}, {"pulled_block", 2}};
    for (const auto& [name, particles] : corpus) {
        test::ScratchDir tmp;
        const std::string scene = std::string(GRANULAB_SOURCE_DIR) + "/tests/data/gsi/" + name + ".gsi";
        const auto run = test::runGranulab("run " + scene + " --out out -q", tmp.path, 120);
        ASSERT_EQ(run.status, 0) << name << "\n" << run.output;
        const auto summary = nlohmann::json::parse(test::readText(tmp.path / "out" / "summary.json"));
        EXPECT_EQ(summary["particles"].get<int>(), particles) << name;
        EXPECT_EQ(summary["status"], "completed") << name;
    }
}
