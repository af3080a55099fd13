// SPDX-License-Identifier: MIT
// gc2d's restart files (gc2d spec 9.1, 9.4; app/dem/gc2d_restart.hpp, io/gci_file.hpp): a run writes
// the numbered gso/gco of its setup dumps; renamed to a gsi and a gci they continue the run, and the
// continuation agrees with the uninterrupted run. Also the gci's identification check and a
// GENERAL change on a restart (friction off), as gc2d allows.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../support.hpp"

using namespace granulab;
namespace fs = std::filesystem;

namespace {

// Random heptagons (2 mm semi-axes, turned at random) on a 5.5 mm FCC grid dropped onto a floor between two
// walls: by t = 0.1 s they rest on each other with lasting contacts (springs and overlap areas). dt = 5e-6 s;
// a setup dump every 20000 steps (t = 0.1 s).
const char* kPile = R"(PARAMETER v1.4
restart test pile
Delta_T 5e-6
Time 0 0.12
G 9.81
Steps_Data 2000
Steps_Setup 20000
Basename pile
WALL
	Corners
		-0.02 -0.01
		0.02 -0.01
		0.02 0
		-0.02 0
	END
WALL
	Corners
		-0.03 0
		-0.02 0
		-0.02 0.05
		-0.03 0.05
	END
WALL
	Corners
		0.02 0
		0.03 0
		0.03 0.05
		0.02 0.05
	END
GENERATE_BLOCK
	X_Range -0.018 0.018
	Y_Range 0.003 0.03
	Grid_Distance 0.0055 0.0055
	Grid_Type FCC
	Part_Size 0.002 0.002
	Part_Num_Corners 7
	Part_Random_Pos_Corners RAND1
	Random_Rot EQUAL
END_OF_FILE
)";

/// Largest |a - b| of column `key` over the rows of two final.csv files (matched by id).
double maxDifference(const fs::path& a, const fs::path& b, const std::string& key) {
    std::vector<std::string> ca, cb;
    const auto ra = test::readCsv(a, ca), rb = test::readCsv(b, cb);
    EXPECT_EQ(ra.size(), rb.size());
    double worst = 0;
    for (std::size_t i = 0; i < ra.size() && i < rb.size(); ++i) {
        EXPECT_EQ(ra[i].at("id"), rb[i].at("id"));
        worst = std::max(worst, std::abs(std::stod(ra[i].at(key)) - std::stod(rb[i].at(key))));
    }
    return worst;
}

std::size_t count(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
}

}  // namespace

TEST(Cli, Gc2dRestartContinuesTheRun) {
    test::ScratchDir tmp;
    test::writeText(tmp.path / "pile.gsi", kPile);
    // The uninterrupted run to t = 0.1 s + 20 steps, with the setup dump at 0.1 s.
    const std::string end = "--set run.end_time=0.1001";
    auto run = test::runGranulab("run pile.gsi --out full -q " + end, tmp.path, 240);
    ASSERT_EQ(run.status, 0) << run.output;
    ASSERT_TRUE(fs::exists(tmp.path / "full" / "pile.0001.gso")) << run.output;
    const std::string gso = test::readText(tmp.path / "full" / "pile.0001.gso");
    const std::string gco = test::readText(tmp.path / "full" / "pile.0001.gco");
    EXPECT_NE(gso.find("TIME 0.1 0.1001"), std::string::npos) << gso.substr(0, 400);
    EXPECT_GT(count(gso, "\nPARTICLE\n"), 20u);  // every grain of the block, each its own PARTICLE
    EXPECT_NE(gso.find("PC_TRANS3"), std::string::npos);
    EXPECT_NE(gso.find("NEXT_SETUP_FILENUMBER 2"), std::string::npos);
    const std::size_t contacts = count(gco, "COLLISION");
    EXPECT_GT(contacts, 20u) << "the pile should rest on lasting contacts";

    // The restart: gso and gco renamed to a gsi and its gci.
    fs::create_directories(tmp.path / "restart");
    fs::copy_file(tmp.path / "full" / "pile.0001.gso", tmp.path / "restart" / "r.gsi");
    fs::copy_file(tmp.path / "full" / "pile.0001.gco", tmp.path / "restart" / "r.gci");
    run = test::runGranulab("run restart/r.gsi --out cont -q", tmp.path, 240);
    ASSERT_EQ(run.status, 0) << run.output;
    // 20 steps after the restart the runs agree to rounding: the text keeps every double exactly
    // (the Gear derivatives and the spring forces are written so the reader's arithmetic gives them
    // back bit for bit); the rest is the summation order of a rebuilt neighbour list.
    const fs::path full = tmp.path / "full" / "final.csv", cont = tmp.path / "cont" / "final.csv";
    // (Measured: 2e-18 m, 3e-15 m/s, 1.5e-12 rad/s; without the gci 2e-7 m, 3e-3 m/s.)
    EXPECT_LT(maxDifference(full, cont, "x"), 1e-15);
    EXPECT_LT(maxDifference(full, cont, "y"), 1e-15);
    EXPECT_LT(maxDifference(full, cont, "vx"), 1e-12);
    EXPECT_LT(maxDifference(full, cont, "vy"), 1e-12);
    EXPECT_LT(maxDifference(full, cont, "omega"), 1e-9);

    // Without its gci (the contacts forgotten: no springs, the damping of new contacts) the same
    // restart departs far more: the contact state is what the agreement above rests on.
    fs::remove(tmp.path / "restart" / "r.gci");
    run = test::runGranulab("run restart/r.gsi --out forgot -q", tmp.path, 240);
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_GT(maxDifference(full, tmp.path / "forgot" / "final.csv", "vx"), 1e-6);
}

TEST(Cli, Gc2dRestartChecksTheIdentificationAndTakesGeneralChanges) {
    test::ScratchDir tmp;
    test::writeText(tmp.path / "pile.gsi", kPile);
    auto run = test::runGranulab("run pile.gsi --out full -q --set run.end_time=0.1001", tmp.path, 240);
    ASSERT_EQ(run.status, 0) << run.output;
    const std::string gso = test::readText(tmp.path / "full" / "pile.0001.gso");
    std::string gco = test::readText(tmp.path / "full" / "pile.0001.gco");

    // A gci of another gsi: its line 2 differs.
    test::writeText(tmp.path / "r.gsi", gso);
    const std::size_t line2 = gco.find('\n') + 1;
    test::writeText(tmp.path / "r.gci",
                    gco.substr(0, line2) + "another run\n" + gco.substr(gco.find('\n', line2) + 1));
    run = test::runGranulab("run r.gsi --out mismatch -q", tmp.path, 60);
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find("r.gci:2"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("does not match line 2"), std::string::npos) << run.output;

    // A pair of ids the scene does not have is ignored with a warning, as gc2d ignores it.
    test::writeText(tmp.path / "r.gci", gco.substr(0, gco.find('\n', line2) + 1) +
                                            "COLLISION\nParticles 9999 10000\nSumm_Friction 1\nOld_Area 0\n"
                                            "END_OF_FILE\n");
    run = test::runGranulab("run r.gsi --out unknown", tmp.path, 240);
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("1 of the gci's 1 contacts were not restored"), std::string::npos)
        << run.output;

    // gc2d's restart with changed GENERAL parameters: friction off and a stronger g.
    test::writeText(tmp.path / "r.gci", gco);
    std::string changed = test::replaceAll(gso, "MUE_STATISCH 0.6", "MUE_STATISCH 0");
    changed = test::replaceAll(changed, "G 9.81", "G 20");
    ASSERT_NE(changed, gso);
    test::writeText(tmp.path / "r.gsi", changed);
    run = test::runGranulab("run r.gsi --out changed -q", tmp.path, 240);
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_GT(maxDifference(tmp.path / "full" / "final.csv", tmp.path / "changed" / "final.csv", "vy"), 1e-6);
}
