// SPDX-License-Identifier: MIT
// Command-line behaviour: the bad-input table (each malformed scene gives its specific message
// and exit status 2), bit-for-bit resume, determinism (also across thread counts), info/help/version.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../support.hpp"

using namespace granulab;

namespace {
const char* kGood = R"([run]
end_time = 0.01
[dem]
dt = 1e-5
[[material]]
name = "g"
density = 1.0
[[contact]]
materials = ["g", "g"]
kn = 1e4
[[particle]]
position = [0.0, 0.0]
radius = 0.01
material = "g"
[[particle]]
position = [0.05, 0.0]
radius = 0.01
material = "g"
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
    const auto pos = s.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) s.replace(pos, from.size(), to);
    return s;
}

struct BadCase {
    const char* name;
    std::string scene;  ///< scene text ("" = do not write the file)
    std::string extraArgs;
    std::vector<std::string> expect;  ///< substrings of the message
};
}  // namespace

TEST(Cli, BadInputTable) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    const std::string kHex =
        "[[shape]]\nname = \"hex\"\nkind = \"regular\"\ncorner_count = 6\nradius = 0.01\n";
    const BadCase cases[] = {
        {"syntax", "[run\nend_time = 1\n", "", {"bad.toml:1", "syntax error"}},
        {"unknown_key",
         replace(kGood, "dt = 1e-5", "dtt = 1e-5"),
         "",
         {"bad.toml:4", "dem.dtt", "did you mean 'dt'"}},
        {"negative_radius",
         replace(kGood, "radius = 0.01\nmaterial = \"g\"\n[[particle]]",
                 "radius = -0.01\nmaterial = \"g\"\n[[particle]]"),
         "",
         {"bad.toml:11", "particle[0].radius", "must be > 0", "(0, inf)"}},
        {"overlap", replace(kGood, "[0.05, 0.0]", "[0.015, 0.0]"), "", {"overlap by", "bad.toml:15"}},
        {"nan", replace(kGood, "dt = 1e-5", "dt = nan"), "", {"bad.toml:4", "dem.dt", "finite"}},
        {"missing_file", "", "", {"missing.toml", "cannot open scene file"}},
        {"unstable_dt",
         replace(kGood, "dt = 1e-5", "dt = 1e-3"),
         "",
         {"dem.dt", "above the stability limit", "allowed (0,"}},
        {"unknown_material",
         replace(kGood, "materials = [\"g\", \"g\"]", "materials = [\"g\", \"gg\"]"),
         "",
         {"unknown material 'gg'"}},
        {"missing_law_parameter",
         replace(kGood, "kn = 1e4", "kt = 1e4"),
         "",
         {"missing required parameter 'kn'", "kt"}},
        {"unknown_law",
         replace(kGood, "kn = 1e4", "kn = 1e4\nnormal = \"hook\""),
         "",
         {"unknown normal law 'hook'", "did you mean 'hooke'"}},
        {"bad_range",
         replace(kGood, "kn = 1e4", "kn = 1e4\ndamping = \"restitution\"\ne = 1.5"),
         "",
         {"e = 1.5 is out of range", "[0, 1]"}},
        {"bad_set", kGood, "--set dem.dt", {"expected key=value"}},
        {"set_unknown_key",
         kGood,
         "--set dem.tdt=1",
         {"--set", "dem.tdt", "unknown key", "did you mean 'dt'"}},
        {"no_checkpoint", kGood, "--resume nowhere", {"nowhere", "no checkpoint"}},
        {"zero_spacing",
         kGood + std::string("[[block]]\nregion = [1.0, 1.0, 2.0, 2.0]\nradius = 0.01\nmaterial = \"g\"\n"),
         "",
         {"block[0].spacing", "must be > 0"}},
        {"unreachable_restitution",
         replace(replace(kGood, "kn = 1e4",
                         "normal = \"hertz\"\ndamping = \"restitution\"\ne = 0.02\nclip_attraction = true"),
                 "density = 1.0", "density = 1.0\nyoungs_modulus = 1e9\npoisson = 0.3"),
         "",
         {"contact[0].e", "below the smallest restitution", "clipped"}},
        {"hertz_without_modulus",
         replace(kGood, "kn = 1e4", "normal = \"hertz\""),
         "",
         {"youngs_modulus", "material 'g'"}},
        {"missing_dt", replace(kGood, "dt = 1e-5\n", ""), "", {"dem.dt", "missing"}},
        {"wildcard_material",
         replace(kGood, "name = \"g\"", "name = \"*\""),
         "",
         {"material[0].name", "wildcard"}},
        {"bool_for_number",
         replace(kGood, "kn = 1e4", "kn = true"),
         "",
         {"contact[0].kn", "expects a number"}},
        {"particle_in_wall",
         kGood + std::string("[[wall]]\npoints = [[0.005, -1.0], [0.005, 1.0]]\nmaterial = \"g\"\n"),
         "",
         {"overlaps wall[0]", "bad.toml:11", "wall is defined at bad.toml:19"}},
        // Polygon shapes (appended from line 19; the hexagon's inradius is 0.00866 m).
        {"nonconvex_polygon",
         kGood + std::string("[[shape]]\nname = \"bad\"\nkind = \"polygon\"\ncorners = [[0.0, 0.0], [0.01, "
                             "0.0], [0.002, 0.002], [0.0, 0.01]]\n"),
         "",
         {"bad.toml:19", "shape[0].corners", "not convex at corner 2"}},
        {"polygon_radius",
         kGood + kHex +
             "[[particle]]\nshape = \"hex\"\nposition = [0.1, 0.0]\nradius = 0.01\nmaterial = \"g\"\n",
         "",
         {"bad.toml:27", "particle[2].radius",
          "radius belongs to disks; the size of shape 'hex' comes from its [[shape]]"}},
        {"polygon_overlap",
         kGood + kHex + "[[particle]]\nshape = \"hex\"\nposition = [0.1, 0.0]\nmaterial = \"g\"\n" +
             "[[particle]]\nshape = \"hex\"\nposition = [0.1, 0.015]\nmaterial = \"g\"\n",
         "",
         {"bad.toml:24", "polygon particles 2 and 3 overlap at start", "defined at bad.toml:28"}},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        std::string file = "bad.toml";
        if (c.scene.empty())
            file = "missing.toml";
        else
            test::writeText(dir / file, c.scene);
        const auto r =
            test::runGranulab(fmt::format("run {} --quiet --out out_{} {}", file, c.name, c.extraArgs), dir);
        EXPECT_EQ(r.status, 2) << r.output;
        for (const auto& e : c.expect)
            EXPECT_NE(r.output.find(e), std::string::npos) << "missing '" << e << "' in:\n" << r.output;
    }
}

TEST(Cli, ResumeContinuesBitForBitAndRunsAreDeterministic) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    const std::string scene = std::string(GRANULAB_SOURCE_DIR) + "/examples/disks_in_box.toml";
    const std::string common = " --quiet --set run.end_time=0.03 --set output.snapshot_interval=0.01";
    auto run = [&](const std::string& args) {
        const auto r = test::runGranulab("run '" + scene + "'" + common + " " + args, dir);
        EXPECT_EQ(r.status, 0) << r.output;
    };
    run("--out full");
    run("--out again");
    run("--out split --set run.end_time=0.0137");
    run("--resume split");
    const auto other =
        test::runGranulab("run '" + scene + "'" + common + " --resume full --set dem.integrator=gear", dir);
    EXPECT_EQ(other.status, 2) << other.output;  // a checkpoint holds the state of its own integrator
    EXPECT_NE(other.output.find("integrator 'verlet'"), std::string::npos) << other.output;
    const std::string full = test::readText(dir / "full/final.csv");
    ASSERT_GT(full.size(), 1000u);
    EXPECT_EQ(full, test::readText(dir / "again/final.csv"));  // deterministic
    EXPECT_EQ(full, test::readText(dir / "split/final.csv"));  // resumed run = uninterrupted run
    // The resumed series continues the first part without duplicated times.
    const std::string series = test::readText(dir / "split/series.csv");
    EXPECT_NE(series.find("\n0.030000000000000002,"), std::string::npos);
    EXPECT_EQ(series.find("\n0.0137"), series.rfind("\n0.0137"));
}

TEST(Cli, AnyThreadCountGivesTheSameFinalStateAndTheDefaultSaysWhy) {
    // docs/physics/dem-threads.md: 1, 2 and 3 threads and the automatic count (which may change
    // the count during the run) write the same final.csv; 1,500 disks run on one thread by default,
    // and summary.json says so and why.
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    const std::string scene = std::string(GRANULAB_SOURCE_DIR) + "/examples/disks_in_box.toml";
    // 400 disks: below the threaded size (World::kParticlesPerThread), so the default runs one thread.
    const std::string common = " --quiet --set run.end_time=0.02 --set block[0].count=400";
    for (const std::string t : {"1", "2", "3", "0"}) {
        const auto r =
            test::runGranulab("run '" + scene + "'" + common + " --threads " + t + " --out t" + t, dir);
        ASSERT_EQ(r.status, 0) << r.output;
    }
    const std::string one = test::readText(dir / "t1/final.csv");
    ASSERT_GT(one.size(), 1000u);
    for (const char* t : {"t2", "t3", "t0"}) EXPECT_EQ(one, test::readText(dir / t / "final.csv")) << t;
    const auto summary = nlohmann::json::parse(test::readText(dir / "t0/summary.json"));
    EXPECT_EQ(summary["threads"], 1);
    EXPECT_EQ(summary["threads_choice"]["mode"], "automatic");
    EXPECT_NE(summary["threads_choice"]["reason"].get<std::string>().find("too few for 2 threads"),
              std::string::npos)
        << summary["threads_choice"];
    const auto asked = nlohmann::json::parse(test::readText(dir / "t3/summary.json"));
    EXPECT_EQ(asked["threads"], 3);  // an explicit count is kept exactly
    EXPECT_EQ(asked["threads_choice"]["mode"], "explicit");
}

TEST(Cli, InfoHelpVersion) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    const std::string scene = std::string(GRANULAB_SOURCE_DIR) + "/examples/disks_in_box.toml";
    auto r = test::runGranulab("info '" + scene + "'", dir);
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("1500 disks"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("advised dt"), std::string::npos) << r.output;
    r = test::runGranulab("help laws", dir);
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("cundall_strack"), std::string::npos);
    EXPECT_NE(r.output.find("area_potential"), std::string::npos);  // the row of the registry
    r = test::runGranulab("help restitution", dir);
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("0.30     0.3723    0.4168    0.4849"), std::string::npos)
        << r.output;  // spec table
    r = test::runGranulab("help nonsense", dir);
    EXPECT_EQ(r.status, 2);
    r = test::runGranulab("--version", dir);
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("granulab 0."), std::string::npos);
    r = test::runGranulab("frobnicate", dir);
    EXPECT_EQ(r.status, 2);
}

TEST(Cli, UnstableRunStopsWithDiagnosisAndKeepsCheckpoint) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    // Two disks collide at 100 m/s: the overlap of the soft contact exceeds the radius (the
    // spring is far too soft for that speed), which the engine must diagnose and stop.
    std::string scene = kGood;
    scene = replace(scene, "end_time = 0.01", "end_time = 0.002");
    scene = replace(scene, "radius = 0.01\nmaterial = \"g\"\n[[particle]]",
                    "radius = 0.01\nvelocity = [50.0, 0.0]\nmaterial = \"g\"\n[[particle]]");
    scene += R"(velocity = [-50.0, 0.0]
[output]
checkpoint_interval = 0.0001
)";
    test::writeText(dir / "unstable.toml", scene);
    const auto r = test::runGranulab("run unstable.toml --quiet --out out", dir);
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find("unstable"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("last good checkpoint"), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "out/checkpoint.bin"));
    EXPECT_NE(test::readText(dir / "out/summary.json").find("\"status\": \"unstable\""), std::string::npos);
}

TEST(Cli, EveryBundledExampleValidates) {
    const test::ScratchDir scratch;
    int seen = 0;
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(std::string(GRANULAB_SOURCE_DIR) + "/examples")) {
        if (entry.path().extension() != ".toml") continue;
        ++seen;
        const auto r = test::runGranulab("info '" + entry.path().string() + "'", scratch.path);
        EXPECT_EQ(r.status, 0) << entry.path() << "\n" << r.output;
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << entry.path() << "\n" << r.output;
    }
    EXPECT_GE(seen, 4);
}

// The one checkpoint container (io/checkpoint.hpp): a file of an older format is refused with
// exit status 2 and a message naming its version, for both engines' old layouts.
TEST(Cli, OldCheckpointFormatsAreRefusedNamingTheirVersion) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    const std::string scene = std::string(GRANULAB_SOURCE_DIR) + "/examples/disks_in_box.toml";
    struct Old {
        const char* name;
        std::uint64_t magic;
        bool versioned;
        const char* expect;
    };
    const Old olds[] = {{"dem_v4", 0x544b434c42414e47ULL, true, "format version 4"},  // "GNABLCKT", version 4
                        {"edmd_v1", 0x31444d4445424c47ULL, false, "format version 1"}};  // "GLBEDMD1"
    for (const auto& old : olds) {
        std::filesystem::create_directories(dir / old.name);
        std::string bytes(reinterpret_cast<const char*>(&old.magic), sizeof old.magic);
        const std::uint32_t version = 4;
        if (old.versioned) bytes.append(reinterpret_cast<const char*>(&version), sizeof version);
        bytes.append(64, '\0');
        test::writeText(dir / old.name / "checkpoint.bin", bytes);
        const auto r = test::runGranulab(fmt::format("run '{}' --quiet --resume {}", scene, old.name), dir);
        EXPECT_EQ(r.status, 2) << r.output;
        EXPECT_NE(r.output.find(old.expect), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("without --resume"), std::string::npos) << r.output;
    }
    // A checkpoint of the other engine is refused too.
    test::writeText(dir / "gas.toml",
                    "[run]\nengine = \"edmd\"\ndimension = 2\nend_time = 0.5\n[edmd]\ncount = 100\n"
                    "volume_fraction = 0.2\nradius = 1.0\nequilibrate = 0\n[output]\nvtk = false\n");
    ASSERT_EQ(test::runGranulab("run gas.toml --quiet --out gas --set edmd.analysis_files=false", dir).status,
              0);
    const auto r = test::runGranulab(fmt::format("run '{}' --quiet --resume gas", scene), dir);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("written by the edmd engine"), std::string::npos) << r.output;
}
