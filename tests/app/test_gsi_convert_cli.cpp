// SPDX-License-Identifier: MIT
// `granulab convert` between gsi and TOML (io/scene_toml_writer.hpp, io/gsi_writer.hpp) and the
// generator-script input (io/gsi_script.hpp) with gc2d's command-line options: converting and
// running gives the same run, bit for bit, in both directions.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../support.hpp"

using namespace granulab;
namespace fs = std::filesystem;

namespace {

const std::string kCorpus = std::string(GRANULAB_SOURCE_DIR) + "/tests/data/gsi/";

}  // namespace

TEST(Cli, GsiConvertRoundTripsRunTheSame) {
    // Scenes with every kind of object: sources (REL and ABS), a DRAG spring, variable g, HEAT_
    // scaling, a piston, vibrating walls, belts, both lattices with jitter.
    const std::vector<std::string> scenes = {"drop_pile",         "pulled_block",      "gravity_step",
                                             "heat_default_time", "piston_down",       "vib_walls",
                                             "belt_conveyor",     "block_rect_jitter", "sources_abs_rel"};
    test::ScratchDir tmp;
    for (const std::string& name : scenes) {
        SCOPED_TRACE(name);
        const std::string gsi = kCorpus + name + ".gsi";
        const std::string shortRun = " -q -l --set run.end_time=0.004";
        auto r = test::runGranulab("convert " + gsi + " " + name + ".toml", tmp.path, 60);
        ASSERT_EQ(r.status, 0) << r.output;
        r = test::runGranulab("convert " + name + ".toml " + name + "_back.gsi", tmp.path, 60);
        ASSERT_EQ(r.status, 0) << r.output;
        r = test::runGranulab("run " + gsi + " --out " + name + "_gsi" + shortRun, tmp.path, 120);
        ASSERT_EQ(r.status, 0) << r.output;
        r = test::runGranulab("run " + name + ".toml --out " + name + "_toml" + shortRun, tmp.path, 120);
        ASSERT_EQ(r.status, 0) << r.output;
        r = test::runGranulab("run " + name + "_back.gsi --out " + name + "_back" + shortRun, tmp.path, 120);
        ASSERT_EQ(r.status, 0) << r.output;
        const std::string reference = test::readText(tmp.path / (name + "_gsi") / "final.csv");
        ASSERT_GT(reference.size(), 50u);
        EXPECT_EQ(test::readText(tmp.path / (name + "_toml") / "final.csv"), reference) << "gsi -> toml";
        EXPECT_EQ(test::readText(tmp.path / (name + "_back") / "final.csv"), reference) << "toml -> gsi";
    }
}

TEST(Cli, GsiConvertRefusesWhatGsiCannotSay) {
    test::ScratchDir tmp;
    const std::string disks = std::string(GRANULAB_SOURCE_DIR) + "/examples/disks_in_box.toml";
    const auto r = test::runGranulab("convert " + disks + " box.gsi", tmp.path, 60);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("gsi cannot express"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("dem.integrator"), std::string::npos) << r.output;  // every problem at once
    EXPECT_NE(r.output.find("[[contact]]"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(tmp.path / "box.gsi"));
    const auto wrongOut = test::runGranulab("convert " + kCorpus + "drop_pile.gsi pile.gsi", tmp.path, 60);
    EXPECT_EQ(wrongOut.status, 2) << wrongOut.output;
}

TEST(Cli, GsiGeneratorScriptNeedsAllowScript) {
    test::ScratchDir tmp;
    // A generator (gc2d's .gsi.pl, here a shell script) whose first argument is DELTA_T.
    test::writeText(tmp.path / "gen.gsi.sh",
                    "#!/bin/sh\n"
                    "echo 'PARAMETER v1.4'\necho 'from a script'\n"
                    "echo \"Delta_T $1\"\necho 'Time 0 0.001'\n"
                    "echo 'PARTICLE'\necho 'Corners'\necho '-0.001 -0.001'\necho '0.001 -0.001'\n"
                    "echo '0.001 0.001'\necho '-0.001 0.001'\necho 'END'\necho 'END_OF_FILE'\n");
    fs::permissions(tmp.path / "gen.gsi.sh", fs::perms::owner_all, fs::perm_options::add);
    auto r = test::runGranulab("info gen.gsi.sh -P 2e-5", tmp.path, 60);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--allow-script"), std::string::npos) << r.output;
    r = test::runGranulab("info --allow-script gen.gsi.sh -P 2e-5", tmp.path, 60);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("2e-05"), std::string::npos) << r.output;  // -P reached the script
    r = test::runGranulab("run --allow-script -i gen.gsi.sh -P 2e-5 --out scripted -q -t 1", tmp.path, 60);
    EXPECT_EQ(r.status, 0) << r.output;  // gc2d's -i and -t
    EXPECT_TRUE(fs::exists(tmp.path / "scripted" / "final.csv"));

    // Errors in the generated text name its lines; a failing script names its status.
    test::writeText(tmp.path / "bad.gsi.sh", "#!/bin/sh\necho 'PARAMETER v1.4'\necho ''\necho 'Delta_T x'\n");
    fs::permissions(tmp.path / "bad.gsi.sh", fs::perms::owner_all, fs::perm_options::add);
    r = test::runGranulab("info --allow-script bad.gsi.sh", tmp.path, 60);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("bad.gsi.sh (output):3"), std::string::npos) << r.output;
    test::writeText(tmp.path / "fail.gsi.sh", "#!/bin/sh\necho 'no such grain' >&2\nexit 3\n");
    fs::permissions(tmp.path / "fail.gsi.sh", fs::perms::owner_all, fs::perm_options::add);
    r = test::runGranulab("info --allow-script fail.gsi.sh", tmp.path, 60);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("exit status 3"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("no such grain"), std::string::npos) << r.output;
}
