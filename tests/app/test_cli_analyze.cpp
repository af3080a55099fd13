// SPDX-License-Identifier: MIT
// `granulab analyze` of a dem run end to end (gc2d spec section 7): a settled bed in a box is run
// with contact output, analysed with the default set and with chosen analyses; the tables exist,
// carry units, and agree with what the run itself reports (the wall forces of series.csv, the
// weight of the grains); bad requests exit with status 2 and say why.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "../support.hpp"

using namespace granulab;

namespace {

namespace fs = std::filesystem;

const char* kBed = R"([run]
seed = 5
end_time = 3.0
[output]
snapshot_interval = 1.0
[dem]
dt = 2.0e-4
gravity = [0.0, -10.0]
[[dem.damping]]
gamma = 0.5
[[material]]
name = "grain"
density = 1.0
[[material]]
name = "side"
[[contact]]
materials = ["grain", "*"]
normal = "hooke"
kn = 1.0e5
damping = "restitution"
e = 0.5
tangential = "cundall_strack"
mu = 0.5
[[contact]]
materials = ["grain", "side"]
normal = "hooke"
kn = 1.0e5
damping = "restitution"
e = 0.5
[[block]]
lattice = "hexagonal"
spacing = 1.15
region = [0.6, 0.6, 11.4, 6.0]
radius = { distribution = "uniform", min = 0.45, max = 0.55 }
material = "grain"
[[wall]]
name = "floor"
points = [[0.0, 0.0], [12.0, 0.0]]
material = "grain"
[[wall]]
name = "left"
points = [[0.0, 0.0], [0.0, 20.0]]
material = "side"
[[wall]]
name = "right"
points = [[12.0, 0.0], [12.0, 20.0]]
material = "side"
)";

/// The notes and rows of an analysis table (io/analysis_table.hpp format).
struct Table {
    std::vector<std::string> notes, header;
    std::vector<std::vector<double>> rows;
    std::size_t col(const std::string& name) const {
        for (std::size_t k = 0; k < header.size(); ++k)
            if (header[k].rfind(name + " [", 0) == 0) return k;
        ADD_FAILURE() << "no column " << name;
        return 0;
    }
};

Table readTable(const fs::path& p) {
    Table t;
    std::ifstream in(p);
    EXPECT_TRUE(in.good()) << p;
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("# ", 0) == 0) {
            t.notes.push_back(line.substr(2));
            continue;
        }
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        if (t.header.empty()) {
            t.header = cells;
            continue;
        }
        std::vector<double> row;
        for (const auto& c : cells) row.push_back(std::stod(c));
        EXPECT_EQ(row.size(), t.header.size()) << line;
        t.rows.push_back(row);
    }
    return t;
}

class AnalyzeDem : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_dir = new test::ScratchDir("AnalyzeDem_bed");
        std::ofstream(s_dir->path / "bed.toml") << kBed;
        const auto r = test::runGranulab("run bed.toml -q --out out", s_dir->path, 300);
        ASSERT_EQ(r.status, 0) << r.output;
    }
    static void TearDownTestSuite() {
        delete s_dir;
        s_dir = nullptr;
    }
    static fs::path out() { return s_dir->path / "out"; }
    static inline test::ScratchDir* s_dir = nullptr;
};

TEST_F(AnalyzeDem, DefaultSetWritesEveryTableWithUnits) {
    const auto r = test::runGranulab("analyze out", s_dir->path, 120);
    ASSERT_EQ(r.status, 0) << r.output;
    const fs::path dir = out() / "analysis" / "snapshot_000003";
    for (const char* name : {"wall_mean_pressure", "floor_pressure", "force_directions", "force_magnitudes",
                             "coordination", "repose_profile", "packing_fraction", "stress"}) {
        const Table t = readTable(dir / (std::string(name) + ".csv"));
        ASSERT_FALSE(t.header.empty()) << name;
        for (const auto& h : t.header) EXPECT_NE(h.find(" ["), std::string::npos) << name << ": " << h;
        EXPECT_FALSE(t.rows.empty()) << name;
    }
    EXPECT_NE(r.output.find("floor"), std::string::npos) << r.output;
}

TEST_F(AnalyzeDem, ReposeOverAGivenRangeIsATableNote) {
    // --range: the integral method over a chosen half-pile (a crater's slopes), in the table's notes.
    const auto r = test::runGranulab("analyze out repose --range 0:6 --range 6:12 -q", s_dir->path, 120);
    ASSERT_EQ(r.status, 0) << r.output;
    const Table t = readTable(out() / "analysis" / "snapshot_000003" / "repose_profile.csv");
    int found = 0;
    for (const auto& n : t.notes)
        for (const char* key : {"repose_range_1_deg = ", "repose_range_2_deg = ", "range_2_x1 = 12 m"})
            if (n.rfind(key, 0) == 0) ++found;
    EXPECT_EQ(found, 3) << r.output;
}

TEST_F(AnalyzeDem, WallForcesAgreeWithTheRunAndCarryTheWeight) {
    ASSERT_EQ(test::runGranulab("analyze out pressure -q", s_dir->path, 120).status, 0);
    const Table t = readTable(out() / "analysis" / "snapshot_000003" / "wall_mean_pressure.csv");
    ASSERT_EQ(t.rows.size(), 3u);
    // The series row at the end holds the wall forces of the same force evaluation.
    std::vector<std::string> header;
    const auto series = test::readCsv(out() / "series.csv", header);
    ASSERT_FALSE(series.empty());
    const auto& last = series.back();
    const double floorFy = t.rows[0][t.col("Fy")];
    EXPECT_NEAR(floorFy, std::stod(last.at("wall_floor_fy")), 1e-9 * std::abs(floorFy));
    EXPECT_NEAR(t.rows[1][t.col("Fx")], std::stod(last.at("wall_left_fx")), 1e-9 * std::abs(floorFy));
    // Settled bed, frictionless side walls: the floor carries the weight (final.csv masses).
    const auto grains = test::readCsv(out() / "final.csv", header);
    double weight = 0;
    for (const auto& g : grains) weight += 10.0 * std::stod(g.at("mass"));
    EXPECT_NEAR(-floorFy, weight, 5e-3 * weight);
    EXPECT_NEAR(t.rows[0][t.col("p")], weight / 12.0, 5e-3 * weight / 12.0);  // p = F/l (Eq. 2.36)
}

TEST_F(AnalyzeDem, CoarseGrainedStressCarriesTheWeightAbove) {
    // Momentum balance of the kernel coarse-graining (Goldhirsch's line integral): in a static bed
    // between frictionless side walls, integral of sigma^c_zz over x at height y = the smoothed
    // weight above y, sum_i m_i g P(y_i + eta > y), eta with the kernel's y-marginal, wherever the
    // floor is beyond the kernel's reach. Gaussian w = 1 (about d), cut off at 3w and normalised
    // inside; the grid spacing d makes the x integral (trapezoid over a smooth field) exact far below
    // the tolerance, which is the settled bed's residual acceleration and damping force (1e-3 of the weight).
    const double w = 1.0, g = 10.0;
    ASSERT_EQ(test::runGranulab("analyze out coarse --kernel-width 1.0 -q", s_dir->path, 120).status, 0);
    const Table t = readTable(out() / "analysis" / "snapshot_000003" / "coarse_grain.csv");
    std::vector<std::string> header;
    const auto grains = test::readCsv(out() / "final.csv", header);
    // The truncated Gaussian's marginal m(y) ~ exp(-y^2/2w^2) erf(sqrt(9w^2 - y^2)/(sqrt2 w)), |y| < 3w,
    // and its upper tail S(t) = P(eta > t), tabulated by the trapezoid rule.
    const int n = 6000;
    std::vector<double> cdf(n + 1, 0.0);
    const auto marginal = [&](double y) {
        return std::exp(-y * y / (2 * w * w)) *
               std::erf(std::sqrt(std::max(0.0, 9 * w * w - y * y)) / (std::sqrt(2.0) * w));
    };
    const double h = 6 * w / n;
    for (int k = 1; k <= n; ++k)
        cdf[k] = cdf[k - 1] + 0.5 * h * (marginal(-3 * w + (k - 1) * h) + marginal(-3 * w + k * h));
    const auto tail = [&](double s) {  // P(eta > s)
        if (s <= -3 * w) return 1.0;
        if (s >= 3 * w) return 0.0;
        const double u = (s + 3 * w) / h;
        const int k = std::min(n - 1, static_cast<int>(u));
        return 1.0 - (cdf[k] + (u - k) * (cdf[k + 1] - cdf[k])) / cdf[n];
    };
    double weight = 0;
    for (const auto& gr : grains) weight += g * std::stod(gr.at("mass"));
    std::map<double, double> integral;  // row y -> sum over x of sigmac_zz dx
    const std::size_t cx = t.col("x"), cz = t.col("z"), cs = t.col("sigmac_zz");
    ASSERT_GT(t.rows.size(), 10u);
    const double dx = t.rows[1][cx] - t.rows[0][cx];
    for (const auto& row : t.rows) integral[row[cz]] += row[cs] * dx;
    int checked = 0;
    for (const auto& [y, value] : integral) {
        if (y < 3 * w + 0.1) continue;  // the floor's contacts within the kernel's reach
        double expected = 0;
        for (const auto& gr : grains)
            expected += g * std::stod(gr.at("mass")) * tail(y - std::stod(gr.at("y")));
        EXPECT_NEAR(value, expected, 1e-3 * weight) << "y = " << y;
        ++checked;
    }
    EXPECT_GE(checked, 3);
}

TEST_F(AnalyzeDem, JanssenTableKeepsTheChosenDepths) {
    // The plumbing of `janssen` (the fit itself is tested in tests/analysis/test_janssen.cpp and on
    // a real silo in Cli.StraightSiloSaturatesAsJanssenPredicts; this bed is 4 grains deep, too
    // shallow for a meaningful fit): the rows are the chosen depths, with the theory columns and
    // the fitted k and mu_j in the notes.
    const auto r = test::runGranulab(
        "analyze out janssen --silo straight:6 --window 12:1 --step 12:0.5 --depth 0.4:3", s_dir->path, 120);
    ASSERT_EQ(r.status, 0) << r.output;
    const Table t = readTable(out() / "analysis" / "snapshot_000003" / "janssen.csv");
    ASSERT_GE(t.rows.size(), 3u);
    for (const auto& row : t.rows) {
        EXPECT_GE(row[t.col("z")], 0.4);
        EXPECT_LE(row[t.col("z")], 3.0);
        EXPECT_TRUE(std::isfinite(row[t.col("sigma_zz_theory")]));
    }
    int fitted = 0;
    for (const auto& n : t.notes) fitted += n.rfind("k = ", 0) == 0 || n.rfind("mu_j = ", 0) == 0;
    EXPECT_EQ(fitted, 2);
}

TEST_F(AnalyzeDem, EverySnapshotAndChosenTime) {
    ASSERT_EQ(test::runGranulab("analyze out coordination --every 1 -q", s_dir->path, 120).status, 0);
    for (int k = 0; k <= 3; ++k)
        EXPECT_TRUE(fs::exists(out() / "analysis" / fmt::format("snapshot_{:06d}", k) / "coordination.csv"))
            << k;
    const auto r = test::runGranulab("analyze out forces --at 1.1", s_dir->path, 120);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("snapshot 1 "), std::string::npos) << r.output;
}

TEST_F(AnalyzeDem, BadRequestsExitWithStatus2) {
    auto r = test::runGranulab("analyze out bogus", s_dir->path, 60);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("unknown analysis"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("janssen"), std::string::npos) << r.output;  // the list of analyses
    r = test::runGranulab("analyze out janssen", s_dir->path, 60);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--silo"), std::string::npos) << r.output;
    r = test::runGranulab("analyze out janssen --silo conical:1", s_dir->path, 60);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("straight, stepped, slanted, parabolic"), std::string::npos) << r.output;
    r = test::runGranulab("analyze out stress --window 0:1", s_dir->path, 60);
    EXPECT_EQ(r.status, 2);
    r = test::runGranulab("analyze out strain", s_dir->path, 60);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--reference"), std::string::npos) << r.output;
    r = test::runGranulab("analyze out pressure --wall roof", s_dir->path, 60);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("floor (0)"), std::string::npos) << r.output;  // names the walls there are
}

TEST(AnalyzeDemFiles, MissingContactFilesAreNamed) {
    const test::ScratchDir dir;
    std::ofstream(dir.path / "bed.toml") << kBed;
    ASSERT_EQ(
        test::runGranulab("run bed.toml -q --out out --set run.end_time=0.1 --set output.contacts=false",
                          dir.path, 120)
            .status,
        0);
    EXPECT_FALSE(fs::exists(dir.path / "out" / "vtk" / "contacts_000000.npy"));
    auto r = test::runGranulab("analyze out pressure", dir.path, 60);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("output.contacts"), std::string::npos) << r.output;
    r = test::runGranulab("analyze out packing -q", dir.path, 60);  // needs no contacts
    EXPECT_EQ(r.status, 0) << r.output;
    // A damaged contact file is bad input that names the file.
    ASSERT_EQ(test::runGranulab("run bed.toml -q --out out2 --set run.end_time=0.1", dir.path, 120).status,
              0);
    const fs::path npy = dir.path / "out2" / "vtk" / "contacts_000001.npy";
    ASSERT_TRUE(fs::exists(npy));
    fs::resize_file(npy, fs::file_size(npy) - 7);
    r = test::runGranulab("analyze out2 forces", dir.path, 60);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("contacts_000001.npy"), std::string::npos) << r.output;
}

TEST(AnalyzeDemFiles, InRunAnalysesEqualTheAnalysisAfterTheRun) {
    // output.analyses writes, at every snapshot and during the run, the tables that `granulab
    // analyze --at T` writes afterwards: the same code on the same files, byte for byte.
    const test::ScratchDir dir;
    std::ofstream(dir.path / "bed.toml") << kBed;
    auto r = test::runGranulab(
        "run bed.toml -q --out out --set run.end_time=2.0 'output.analyses=[\"pressure\", \"packing\"]'",
        dir.path, 300);
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* snap : {"snapshot_000000", "snapshot_000001", "snapshot_000002"})
        for (const char* table : {"wall_mean_pressure.csv", "packing_fraction.csv"})
            EXPECT_TRUE(fs::exists(dir.path / "out" / "analysis" / snap / table)) << snap << "/" << table;
    // At t = 0 the lattice block has not reached the floor yet: no floor profile then.
    EXPECT_FALSE(fs::exists(dir.path / "out" / "analysis" / "snapshot_000000" / "floor_pressure.csv"));
    EXPECT_TRUE(fs::exists(dir.path / "out" / "analysis" / "snapshot_000002" / "floor_pressure.csv"));
    const fs::path inRun = dir.path / "out" / "analysis" / "snapshot_000001";
    const std::string pressure = test::readText(inRun / "floor_pressure.csv");
    const std::string packing = test::readText(inRun / "packing_fraction.csv");
    r = test::runGranulab("analyze out pressure packing --at 1.0 -q", dir.path, 60);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(test::readText(inRun / "floor_pressure.csv"), pressure);
    EXPECT_EQ(test::readText(inRun / "packing_fraction.csv"), packing);

    // Names are checked with the scene: unknown, needing an option, or needing the contact files.
    const std::pair<const char*, const char*> bad[] = {
        {"'output.analyses=[\"presure\"]'", "did you mean 'pressure'"},
        {"'output.analyses=[\"janssen\"]'", "needs --silo"},
        {"'output.analyses=[\"forces\"]' output.contacts=false", "output.contacts = true"},
    };
    for (const auto& [set, message] : bad) {
        r = test::runGranulab(std::string("run bed.toml -q --out bad --set ") + set, dir.path, 60);
        EXPECT_EQ(r.status, 2) << set;
        EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("output.analyses"), std::string::npos) << r.output;
    }
}

TEST(AnalyzeDemFiles, FloorDrawnInPiecesIsOneFloor) {
    // A floor drawn as three collinear walls (two plates and a stamp between them, gc2d 4.3.2),
    // none named `floor`: the profile runs over all three, and integrated over x (sum of p times
    // the window step: every contact lies in 2b/step windows of width 2b) it carries the weight.
    const test::ScratchDir dir;
    // kBed with its one floor wall cut into three (the side walls stay as they are).
    std::string scene = kBed;
    const std::string floor = "name = \"floor\"\npoints = [[0.0, 0.0], [12.0, 0.0]]\nmaterial = \"grain\"\n";
    const auto at = scene.find(floor);
    ASSERT_NE(at, std::string::npos);
    scene.replace(at, floor.size(),
                  "name = \"plate_a\"\npoints = [[0.0, 0.0], [5.0, 0.0]]\nmaterial = \"grain\"\n"
                  "[[wall]]\nname = \"stamp\"\npoints = [[5.0, 0.0], [7.0, 0.0]]\nmaterial = \"grain\"\n"
                  "[[wall]]\nname = \"plate_b\"\npoints = [[7.0, 0.0], [12.0, 0.0]]\nmaterial = \"grain\"\n");
    std::ofstream(dir.path / "bed.toml") << scene;
    auto r = test::runGranulab("run bed.toml -q --out out", dir.path, 300);
    ASSERT_EQ(r.status, 0) << r.output;
    // Windows of 0.4 m stepped by 0.1 m from wall to wall: a floor contact lies at least a grain
    // radius (0.45 m) from the side walls, so it is counted in 2b/step = 4 windows like any other
    // (with the default 10 m windows the end windows would miss part of the floor).
    r = test::runGranulab("analyze out pressure -q --half-width 0.2", dir.path, 60);
    ASSERT_EQ(r.status, 0) << r.output;
    const Table t = readTable(dir.path / "out" / "analysis" / "snapshot_000003" / "floor_pressure.csv");
    bool named = false;
    double step = 0;
    for (const auto& n : t.notes) {
        named = named || n == "floor = plate_a + stamp + plate_b";
        if (n.rfind("step = ", 0) == 0) step = std::stod(n.substr(7));
    }
    EXPECT_TRUE(named);
    ASSERT_GT(step, 0);
    double load = 0, weight = 0;
    for (const auto& row : t.rows)
        if (!std::isnan(row[t.col("p")])) load += row[t.col("p")] * step;
    std::vector<std::string> header;
    for (const auto& g : test::readCsv(dir.path / "out" / "final.csv", header))
        weight += 10.0 * std::stod(g.at("mass"));
    EXPECT_NEAR(load, weight, 5e-3 * weight);
}

}  // namespace
