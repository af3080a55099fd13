// SPDX-License-Identifier: MIT
// The scene machines end to end (issue 12): a silo filled and drained through an outlet that opens
// at a time keeps its mass balance at every series row, a run resumed across insertions and
// removals equals the uninterrupted one bit for bit, and bad machine input gives exit status 2
// with file:line and the allowed range.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "../support.hpp"

using namespace granulab;

namespace {

const char* kSilo = R"([run]
end_time = 0.5
seed = 3
[dem]
dt = 1e-5
gravity = [0.0, -9.81]
[[material]]
name = "glass"
density = 12.5
[[material]]
name = "steel"
[[contact]]
materials = ["glass", "*"]
normal = "hooke"
kn = 1.0e4
damping = "restitution"
e = 0.5
tangential = "cundall_strack"
mu = 0.5
[[block]]
lattice = "random"
count = 200
region = [0.005, 0.03, 0.095, 0.15]
radius = { distribution = "uniform", min = 0.0018, max = 0.0026 }
material = "glass"
[[wall]]
points = [[0.0, 0.2], [0.0, 0.0], [0.04, 0.0]]
material = "steel"
[[wall]]
points = [[0.06, 0.0], [0.1, 0.0], [0.1, 0.2]]
material = "steel"
[[outlet]]
name = "orifice"
edge = [[0.06, 0.0], [0.04, 0.0]]
open_at = 0.15
material = "steel"
[[source]]
position = [0.05, 0.17]
interval = 0.01
from = 0.2
to = 0.4
radius = 0.002
material = "glass"
[output]
series_interval = 0.01
checkpoint_interval = 0.05
)";

TEST(Cli, SiloMassBalanceHoldsAtEveryRow) {
    test::ScratchDir dir;
    test::writeText(dir.path / "silo.toml", kSilo);
    const auto r = test::runGranulab("run silo.toml -q --out out", dir.path, 300);
    ASSERT_EQ(r.status, 0) << r.output;
    std::vector<std::string> header;
    const auto rows = test::readCsv(dir.path / "out/series.csv", header);
    ASSERT_GT(rows.size(), 40u);
    const double m0 = std::stod(rows.front().at("mass"));
    for (const auto& row : rows) {
        const double m = std::stod(row.at("mass")), in = std::stod(row.at("mass_in")),
                     out = std::stod(row.at("mass_out"));
        EXPECT_NEAR(m, m0 + in - out, 1e-12 * m0) << "t = " << row.at("time");
        EXPECT_DOUBLE_EQ(std::stod(row.at("removed")), std::stod(row.at("outlet_orifice_removed")));
        if (std::stod(row.at("time")) < 0.15) {
            EXPECT_EQ(std::stod(row.at("removed")), 0.0);  // lid closed
        }
    }
    const auto& last = rows.back();
    EXPECT_GT(std::stod(last.at("removed")), 10.0);  // the silo drained after the outlet opened
    EXPECT_EQ(std::stod(last.at("inserted")) + std::stod(last.at("skipped")), 21.0);  // drops at 0.2 ... 0.4
    const auto summary = nlohmann::json::parse(test::readText(dir.path / "out/summary.json"));
    EXPECT_EQ(summary["flow"]["removed"].get<double>(), std::stod(last.at("removed")));
}

TEST(Cli, ResumeWithAChangedLawContinues) {
    // gc2d 6.7 by restart: friction switched off in the scene given to --resume.
    test::ScratchDir dir;
    test::writeText(dir.path / "silo.toml", kSilo);
    ASSERT_EQ(test::runGranulab("run silo.toml -q --out part --set run.end_time=0.3", dir.path, 300).status,
              0);
    const auto r = test::runGranulab("run silo.toml -q --resume part --set contact[0].mu=0.0", dir.path, 300);
    ASSERT_EQ(r.status, 0) << r.output;
    std::vector<std::string> header;
    EXPECT_NEAR(std::stod(test::readCsv(dir.path / "part/series.csv", header).back().at("time")), 0.5, 1e-9);
}

TEST(Cli, ResumeAcrossInsertionAndRemovalIsBitForBit) {
    test::ScratchDir dir;
    test::writeText(dir.path / "silo.toml", kSilo);
    ASSERT_EQ(test::runGranulab("run silo.toml -q --out full", dir.path, 300).status, 0);
    // Stop at 0.3 s (outlet open, source pouring), then resume to the end.
    ASSERT_EQ(test::runGranulab("run silo.toml -q --out part --set run.end_time=0.3", dir.path, 300).status,
              0);
    const auto r = test::runGranulab("run silo.toml -q --resume part", dir.path, 300);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(test::readText(dir.path / "part/final.csv"), test::readText(dir.path / "full/final.csv"));
    EXPECT_EQ(test::readText(dir.path / "part/series.csv"), test::readText(dir.path / "full/series.csv"));
}

struct BadMachine {
    const char* name;
    std::string addition;             ///< appended to a valid scene
    std::vector<std::string> expect;  ///< substrings of the message
};

TEST(Cli, BadMachineInputIsExitTwoWithLocationAndRange) {
    const std::string base = R"([run]
end_time = 0.1
[dem]
dt = 1e-5
[[material]]
name = "glass"
density = 12.5
[[contact]]
materials = ["glass", "glass"]
kn = 1.0e4
[[wall]]
points = [[0.0, 0.0], [1.0, 0.0]]
material = "glass"
)";
    const std::vector<BadMachine> cases = {
        {"vib_type",
         "vib_type = \"wobble\"\nvib_width = 0.001\nvib_frequency = 20\n",
         {"bad.toml:", "vib_type", "cosine", "tapping"}},
        {"nonconvex",
         "[[wall]]\npoints = [[0, 0], [1, 0], [0.5, 0.2], [1, 1], [0, 1]]\nclosed = true\nkind = "
         "\"polygon\"\n"
         "material = \"glass\"\n",
         {"bad.toml:", "wall[1].points", "convex"}},
        {"outlet_zero",
         "[[outlet]]\nedge = [[0.5, 0.0], [0.5, 0.0]]\n",
         {"bad.toml:", "outlet[0].edge", "zero length"}},
        {"source_outside",
         "[[source]]\nposition = [50.0, 50.0]\nradius = 0.002\nmaterial = \"glass\"\n",
         {"bad.toml:", "source[0].position", "outside every wall"}},
        {"window_reversed",
         "[gravity]\ntype = \"linear\"\nmagnitude = [9.81, 1.0]\nwindow = [2.0, 1.0]\n",
         {"bad.toml:", "gravity.window", "0 <= from <= to"}},
        {"piston_and_vib",
         "vib_type = \"cosine\"\nvib_width = 0.001\nvib_frequency = 20\npiston_force = 10.0\n",
         {"bad.toml:", "wall[0]", "piston", "vibrating"}},
        {"mu_one",
         "[[shape]]\nname = \"sq\"\nkind = \"regular\"\ncorner_count = 4\nradius = 0.01\n"
         "[[contact]]\nmaterials = [\"glass\", \"steel\"]\nnormal = \"area\"\nE = 1e5\ntangential = "
         "\"gc2d\"\n"
         "mu = 1.0\n[[material]]\nname = \"steel\"\n",
         {"bad.toml:", "mu", "[0, 1)"}},
        {"boundary_ccw",
         "[[boundary]]\npoints = [[0, 0], [1, 0], [1, 1], [0, 1]]\nedges = [[0, 1, \"wall\"], [1, 2, "
         "\"wall\"], "
         "[2, 3, \"wall\"], [3, 0, \"outlet\"]]\nmaterial = \"glass\"\n",
         {"bad.toml:", "boundary[0].edges", "clockwise"}},
        {"source_interval",
         "[[source]]\nposition = [0.5, 0.1]\ninterval = 1e-9\nradius = 0.002\nmaterial = \"glass\"\n",
         {"bad.toml:", "source[0].interval", "allowed [dt, inf)"}},
        {"inlet_outward",
         "[[inlet]]\nedge = [[0.0, 1.0], [1.0, 1.0]]\nrate = 10\nradius = 0.002\n"
         "velocity = [0.0, 1.0]\nmaterial = \"glass\"\n",
         {"bad.toml:", "inlet[0].velocity", "into the domain"}},
    };
    for (const auto& c : cases) {
        test::ScratchDir dir;
        test::writeText(dir.path / "bad.toml", base + c.addition);
        for (const char* command : {"info", "run"}) {
            const auto r = test::runGranulab(
                fmt::format("{} bad.toml{}", command, std::string(command) == "run" ? " -q" : ""), dir.path,
                60);
            EXPECT_EQ(r.status, 2) << c.name << " " << command << ": " << r.output;
            for (const auto& e : c.expect)
                EXPECT_NE(r.output.find(e), std::string::npos) << c.name << " lacks '" << e << "':\n"
                                                               << r.output;
        }
    }
}

}  // namespace
