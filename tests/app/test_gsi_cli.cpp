// SPDX-License-Identifier: MIT
// gc2d's gsi scenes on the command line (io/gsi_scene.hpp): `granulab run scene.gsi` runs the
// thesis's piston sample and every scene of the corpus tests/data/gsi; a malformed gsi (the files of
// tests/data/gsi/bad) exits with status 2 naming file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

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
    // Every scene of tests/data/gsi (tests/io/test_gsi_corpus.cpp says what each one covers) maps
    // onto scene Defs the engine accepts, and runs to its end; the particle counts are those of
    // the lattices and sources, derived there. The printed thesis sample piston.gsi is left out: its
    // grains overlap on its grid (docs/coming-from-gc2d.md), and Cli.GsiPistonSampleRuns runs the
    // example instead. A new corpus file needs its line here.
    const std::map<std::string, int> particles = {
        {"belt_conveyor.gsi", 2},        {"block_defaults.gsi", 25},     {"block_rect_jitter.gsi", 14},
        {"drag_spring_defaults.gsi", 2}, {"drop_pile.gsi", 25},          {"general_keywords.gsi", 1},
        {"gravity_linear.gsi", 11},      {"gravity_step.gsi", 3},        {"heat_default_time.gsi", 3},
        {"particle_state.gsi", 3},       {"restart_state.gsi", 2},       {"piston_down.gsi", 3},
        {"pulled_block.gsi", 2},         {"settling_squares.gsi.gz", 4}, {"source_defaults.gsi", 3},
        {"source_shapes.gsi", 4},        {"sources_abs_rel.gsi", 9},     {"syntax_features.gsi", 1},
        {"tilted_gravity.gsi", 20},      {"vib_walls.gsi", 6},           {"vibrated_bed.gsi", 60},
    };
    const std::filesystem::path dir = std::filesystem::path(GRANULAB_SOURCE_DIR) / "tests/data/gsi";
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        const std::string n = e.path().filename().string();
        if (e.is_regular_file() && (n.ends_with(".gsi") || n.ends_with(".gsi.gz")) && n != "piston.gsi")
            names.push_back(n);
    }
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names.size(), particles.size());
    for (const auto& name : names) {
        SCOPED_TRACE(name);
        ASSERT_TRUE(particles.count(name)) << "a corpus file without its expected particle count";
        test::ScratchDir tmp;
        const auto run = test::runGranulab("run '" + (dir / name).string() + "' --out out -q", tmp.path, 120);
        ASSERT_EQ(run.status, 0) << run.output;
        const auto summary = nlohmann::json::parse(test::readText(tmp.path / "out" / "summary.json"));
        EXPECT_EQ(summary["particles"].get<int>(), particles.at(name));
        EXPECT_EQ(summary["status"], "completed");
        if (name == "piston_down.gsi") {  // gc2d 6.3: the piston (wall4) holds PISTON_FORCE 50 N
            const auto& walls = summary["wall_forces"];
            ASSERT_EQ(walls.size(), 4u);
            EXPECT_NEAR(walls[3]["force"][1].get<double>(), 50, 0.5);
        }
    }
}

TEST(Cli, GsiMalformedFilesExitTwoWithFileAndLine) {
    // tests/data/gsi/bad: unknown object, missing END, bad numbers, comments inside CORNERS,
    // non-convex CORNERS, GENERAL re-entered, ...; each file names its error in "# expect LINE:
    // TEXT" lines (tests/io/test_gsi_corpus.cpp checks the same in-process).
    const std::filesystem::path dir = std::filesystem::path(GRANULAB_SOURCE_DIR) / "tests/data/gsi/bad";
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".gsi") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    EXPECT_GE(files.size(), 10u);
    for (const auto& file : files) {
        SCOPED_TRACE(file.string());
        int expectations = 0;
        std::stringstream lines(test::readText(file));
        test::ScratchDir tmp;
        const auto run = test::runGranulab("run '" + file.string() + "' --out out -q", tmp.path, 60);
        EXPECT_EQ(run.status, 2) << run.output;
        for (std::string l; std::getline(lines, l);) {
            if (l.rfind("# expect ", 0) != 0) continue;
            ++expectations;
            const auto colon = l.find(": ");
            const std::string where = file.string() + ":" + l.substr(9, colon - 9) + ":";
            EXPECT_NE(run.output.find(where), std::string::npos) << where << "\n" << run.output;
            EXPECT_NE(run.output.find(l.substr(colon + 2)), std::string::npos) << l << "\n" << run.output;
        }
        EXPECT_GT(expectations, 0);
    }
}
