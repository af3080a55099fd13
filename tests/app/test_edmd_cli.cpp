// SPDX-License-Identifier: MIT
// `granulab run` with run.engine = "edmd" (issue 5): the outputs of the user contract
// (summary.json keys, series.csv columns, final.csv, analysis files), a resumed run equal to an
// uninterrupted one bit for bit, the same scene giving the same result twice, and bad [edmd]
// input answered with file:line, key, allowed range and exit status 2.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../support.hpp"

using namespace granulab;

namespace {
const char* kGas = R"([run]
engine = "edmd"
dimension = 2
seed = 3
end_time = 4.0

[edmd]
count = 400
volume_fraction = 0.3
radius = 1.0
restitution = 0.9
equilibrate = 20
series_points = 8

[output]
snapshot_interval = 1.0
)";

std::string replaceOnce(std::string s, const std::string& from, const std::string& to) {
    const auto pos = s.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) s.replace(pos, from.size(), to);
    return s;
}
}  // namespace

TEST(EdmdCli, RunWritesTheContractOutputs) {
    const test::ScratchDir scratch;
    test::writeText(scratch.path / "gas.toml", kGas);
    const auto r = test::runGranulab("run gas.toml --out out -q", scratch.path);
    ASSERT_EQ(r.status, 0) << r.output;
    const auto js = nlohmann::json::parse(test::readText(scratch.path / "out/summary.json"));
    for (const char* key : {"engine", "particles", "sim_time", "wall_time_s", "events", "collisions",
                            "events_per_s", "collisions_per_s", "bytes_per_particle", "theory"})
        EXPECT_TRUE(js.contains(key)) << key;
    EXPECT_EQ(js["engine"], "edmd");
    EXPECT_EQ(js["particles"], 400);
    EXPECT_DOUBLE_EQ(js["sim_time"].get<double>(), 4.0);
    EXPECT_GT(js["collisions"].get<double>(), 500);  // ~1.2 per particle and s at nu = 0.3
    const std::string series = test::readText(scratch.path / "out/series.csv");
    EXPECT_EQ(series.rfind("time,tau,events,collisions", 0), 0u);
    for (const char* column :
         {"temperature_haff", "collision_frequency", "reduced_pressure", "kurtosis", "q_x", "nu_q50"})
        EXPECT_NE(series.find(column), std::string::npos) << column;
    EXPECT_EQ(std::count(series.begin(), series.end(), '\n'), 1 + 1 + 8);  // header, t = 0, 8 rows
    for (const char* file :
         {"final.csv", "theory.csv", "snapshots.pvd", "checkpoint.bin", "analysis/gr_000000.csv",
          "analysis/clusters_000004.csv", "analysis/velocity_000001.csv", "analysis/density_000002.csv"})
        EXPECT_TRUE(std::filesystem::exists(scratch.path / "out" / file)) << file;
    EXPECT_EQ(test::readText(scratch.path / "out/final.csv")
                  .rfind("id,shape,x,y,vx,vy,omega,radius,mass,collisions\n", 0),
              0u);
    // The gas snapshots render like DEM ones (smooth spheres carry no angle array).
    const auto render = test::runGranulab("render out --png -q", scratch.path);
    EXPECT_EQ(render.status, 0) << render.output;
    EXPECT_TRUE(std::filesystem::exists(scratch.path / "out/png/frame_000000.png"));
}

TEST(EdmdCli, ResumeIsBitForBitAndRunsAreDeterministic) {
    const test::ScratchDir scratch;
    test::writeText(scratch.path / "gas.toml", kGas);
    ASSERT_EQ(test::runGranulab("run gas.toml --out full -q", scratch.path).status, 0);
    ASSERT_EQ(test::runGranulab("run gas.toml --out again -q", scratch.path).status, 0);
    EXPECT_EQ(test::readText(scratch.path / "full/final.csv"),
              test::readText(scratch.path / "again/final.csv"));
    // Half the run, then resume to the end: same particles and the same series rows.
    ASSERT_EQ(
        test::runGranulab("run gas.toml --out part -q --set run.end_time=2.0 --set edmd.series_points=4",
                          scratch.path)
            .status,
        0);
    const auto r = test::runGranulab("run gas.toml --resume part -q", scratch.path);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(test::readText(scratch.path / "full/final.csv"),
              test::readText(scratch.path / "part/final.csv"));
    EXPECT_EQ(test::readText(scratch.path / "full/series.csv"),
              test::readText(scratch.path / "part/series.csv"));
}

TEST(EdmdCli, BadInputNamesTheKeyAndExitsWithTwo) {
    const test::ScratchDir scratch;
    struct Case {
        const char* name;
        std::string scene;
        std::vector<std::string> expect;
    };
    const Case cases[] = {
        {"negative_radius",
         replaceOnce(kGas, "radius = 1.0", "radius = -1.0"),
         {"edmd.radius", "must be > 0", "(0, inf)"}},
        {"unknown_key",
         replaceOnce(kGas, "restitution = 0.9", "restitutoin = 0.9"),
         {"bad.toml:11", "edmd.restitutoin", "did you mean"}},
        {"restitution_range",
         replaceOnce(kGas, "restitution = 0.9", "restitution = 1.5"),
         {"edmd.restitution", "[0, 1]"}},
        {"three_of_three",
         replaceOnce(kGas, "count = 400", "count = 400\nbox = [100.0, 100.0]"),
         {"exactly two of box, count"}},
        {"no_end", replaceOnce(kGas, "end_time = 4.0", ""), {"run.end_time", "exactly one run length"}},
        {"dem_section",
         std::string(kGas) + "[dem]\ndt = 1e-5\n",
         {"bad.toml:", "[dem] belongs to the dem engine"}},
        {"too_dense_lattice",
         replaceOnce(kGas, "volume_fraction = 0.3", "volume_fraction = 0.85"),
         {"edmd.volume_fraction", "cannot place"}},
        {"small_box",
         replaceOnce(replaceOnce(kGas, "count = 400", "box = [5.0, 5.0]"), "volume_fraction = 0.3",
                     "volume_fraction = 0.1"),
         {"edmd.box", "must hold 3 diameters", "edmd.count", "allowed [2,"}},
        {"dimension",
         replaceOnce(kGas, "dimension = 2", "dimension = 4"),
         {"run.dimension", "disks (2) or spheres (3)"}},
        {"cells_per_particle_range",
         replaceOnce(kGas, "restitution = 0.9", "restitution = 0.9\ncells_per_particle = -2.0"),
         {"bad.toml:7", "edmd.cells_per_particle", "(0, 10000]", "0 (automatic)"}},
        {"cell_grid_name",
         replaceOnce(kGas, "restitution = 0.9", "restitution = 0.9\ncell_grid = \"fre\""),
         {"bad.toml:12", "edmd.cell_grid", "did you mean 'free'", "allowed: auto, morton, free"}},
        {"end_tau_elastic",
         replaceOnce(replaceOnce(kGas, "end_time = 4.0", ""), "restitution = 0.9",
                     "restitution = 1.0\nend_tau = 2.0"),
         {"edmd.end_tau", "restitution below 1"}},
    };
    for (const auto& c : cases) {
        test::writeText(scratch.path / "bad.toml", c.scene);
        const auto r = test::runGranulab("run bad.toml --out out -q", scratch.path);
        EXPECT_EQ(r.status, 2) << c.name << ": " << r.output;
        for (const auto& s : c.expect)
            EXPECT_NE(r.output.find(s), std::string::npos) << c.name << ": missing '" << s << "' in\n"
                                                           << r.output;
    }
}

TEST(EdmdCli, CellGridKeysReachTheEngine) {
    // 400 disks at nu = 0.3 (L = 64.7, diameter 2): the automatic C/N = 1.5 gives 24 free cells
    // per axis (also the default "auto" on one process); "morton" the nearest power of two, 32;
    // cells_per_particle = 0.5
    // fewer, 6 more (edmd spec 2.4, AT-6). summary.json's cells_per_axis is the engine's grid.
    const test::ScratchDir scratch;
    test::writeText(scratch.path / "gas.toml", replaceOnce(kGas, "end_time = 4.0", "end_time = 0.5"));
    auto cells = [&](const std::string& set) {
        const auto r = test::runGranulab("run gas.toml --out out --overwrite -q " + set, scratch.path);
        EXPECT_EQ(r.status, 0) << set << ": " << r.output;
        const auto js = nlohmann::json::parse(test::readText(scratch.path / "out/summary.json"));
        return js["cells_per_axis"].get<std::vector<int>>();
    };
    EXPECT_EQ(cells(""), (std::vector<int>{24, 24}));
    EXPECT_EQ(cells("--set edmd.cell_grid=morton"), (std::vector<int>{32, 32}));
    EXPECT_EQ(cells("--set edmd.cell_grid=free"), (std::vector<int>{24, 24}));
    EXPECT_EQ(cells("--set edmd.cell_grid=free --set edmd.cells_per_particle=0.5"),
              (std::vector<int>{14, 14}));
    EXPECT_EQ(cells("--set edmd.cell_grid=free --set edmd.cells_per_particle=6"), (std::vector<int>{32, 32}));
    EXPECT_EQ(cells("--set edmd.cell_grid=morton --set edmd.cells_per_particle=0.25"),
              (std::vector<int>{8, 8}));
}

TEST(EdmdCli, AnalyzeMeasuresTheFinalStateAndMasterEquationWritesItsCurves) {
    const test::ScratchDir scratch;
    test::writeText(scratch.path / "gas.toml", kGas);
    ASSERT_EQ(test::runGranulab("run gas.toml --out out -q", scratch.path).status, 0);
    const auto r = test::runGranulab("analyze out", scratch.path);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("q_x"), std::string::npos) << r.output;
    const auto js = nlohmann::json::parse(test::readText(scratch.path / "out/analysis/final_summary.json"));
    EXPECT_EQ(js["particles"], 400);
    // A gas at area fraction 0.3: the contact value is near Henderson's 1.77 (loose: 400 disks,
    // one snapshot, slightly cooled and correlated by eps = 0.9).
    EXPECT_GT(js["g_contact"].get<double>(), 1.2);
    EXPECT_LT(js["g_contact"].get<double>(), 2.6);
    EXPECT_NEAR(js["M1"].get<double>() * js["clusters"].get<double>(), 400, 1e-9);  // M1 = N / n_tot
    EXPECT_EQ(test::runGranulab("analyze missing_folder", scratch.path).status, 2);
    const auto m = test::runGranulab(
        "master-equation --lambda 4 --xi 2 --smax 50 --t-end 20 --points 5 --out me", scratch.path);
    ASSERT_EQ(m.status, 0) << m.output;
    const std::string moments = test::readText(scratch.path / "me_moments.csv");
    EXPECT_EQ(moments.rfind("t,M1,M2,total,mass\n", 0), 0u);
    EXPECT_EQ(std::count(moments.begin(), moments.end(), '\n'), 6);
    EXPECT_EQ(test::runGranulab("master-equation --lambda -1", scratch.path).status, 2);
}
