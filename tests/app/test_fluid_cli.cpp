// SPDX-License-Identifier: MIT
// granulab run with [fluid] end to end (cfddem spec 5.5; docs/scene-format.md "[fluid]"): bad
// field files and scenes exit with status 2 naming the file and the array; a series of fields
// with their own times is read file by file, each once; a run resumed between two fields is
// bit-identical to the uninterrupted one (lazy loading and the per-particle cell interpolants keep
// no history that a checkpoint would miss).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../support.hpp"

namespace granulab {
namespace {

/// A legacy ASCII UNSTRUCTURED_GRID of 6 x 6 nodes over [0, 1]^2 with quad cells and the velocity
/// s (2 (y - 0.5), 1 + x), at time `time` (FieldData TimeValue, as foamToVTK writes it). `u`
/// replaces the velocity array's text (e.g. to put a NaN in it); `name` the array's name.
std::string quadField(Real scale, Real time, const std::string& name = "U", const std::string& u = "") {
    std::string s = "# vtk DataFile Version 3.0\nquads\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    s += fmt::format("FIELD FieldData 1\nTimeValue 1 1 double\n{}\n", time);
    s += "POINTS 36 double\n";
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i) s += fmt::format("{} {} 0\n", 0.2 * i, 0.2 * j);
    s += "CELLS 25 125\n";
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
            const int k = i + 6 * j;
            s += fmt::format("4 {} {} {} {}\n", k, k + 1, k + 7, k + 6);
        }
    s += "CELL_TYPES 25\n";
    for (int k = 0; k < 25; ++k) s += "9\n";
    s += fmt::format("POINT_DATA 36\nVECTORS {} double\n", name);
    if (!u.empty()) return s + u;
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i)
            s += fmt::format("{} {} 0\n", scale * 2 * (0.2 * j - 0.5), scale * (1 + 0.2 * i));
    return s;
}

/// Twenty water droplets (R = 5 mm) in a 1 m box of air, blown by the fields in `fields`.
std::string dropletScene(const std::string& fields, const std::string& more = "") {
    return fmt::format(R"(
[run]
end_time = 0.03
seed = 4
[dem]
dt = 5.0e-5
mass_model = "sphere"
gravity = [0.0, -9.81]
[[material]]
name = "water"
density = 1000.0
[[contact]]
materials = ["*", "*"]
normal = "hooke"
kn = 1000.0
damping = "restitution"
e = 0.5
[[block]]
lattice = "random"
count = 20
region = [0.1, 0.1, 0.9, 0.9]
radius = 0.005
material = "water"
velocity = [0.3, 0.0]
[[wall]]
points = [[0.0, 1.0], [0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
material = "water"
[fluid]
density = 1.2
viscosity = 1.8e-5
drag = "schiller_naumann"
fields = {}
{}
[output]
snapshot_interval = 0.01
series_interval = 0.002
)",
                       fields, more);
}

TEST(Cli, FluidFieldProblemsExitWithStatusTwoNamingFileAndArray) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    test::writeText(dir / "good.vtk", quadField(1, 0));
    test::writeText(dir / "velocity.vtk", quadField(1, 0, "velocity"));
    std::string nan = quadField(1, 0);
    nan.replace(nan.rfind("\n0 ") + 1, 1, "nan");
    test::writeText(dir / "nan.vtk", nan);
    const std::string good = quadField(1, 0);
    test::writeText(dir / "cut.vtk", good.substr(0, good.size() / 2));
    test::writeText(dir / "jitter.vtk",
                    test::replaceAll(good, "\n0.2 0.2 0\n", "\n0.21 0.2 0\n"));  // no tensor grid
    struct Case {
        std::string name, scene;
        std::vector<std::string> expect;
    };
    const std::vector<Case> cases = {
        {"no_array", dropletScene("\"velocity.vtk\""), {"velocity.vtk", "'U'", "velocity"}},
        {"nan", dropletScene("\"nan.vtk\""), {"nan.vtk", "U"}},
        {"truncated", dropletScene("\"cut.vtk\""), {"cut.vtk"}},
        {"missing", dropletScene("\"nowhere.vtk\""), {"nowhere.vtk", "fluid.fields"}},
        {"bilinear_on_cells",
         dropletScene("\"jitter.vtk\"", "interpolation = \"bilinear\""),
         {"jitter.vtk", "tensor grid"}},
        {"outside",
         test::replaceAll(dropletScene("\"good.vtk\""), "region = [0.1, 0.1, 0.9, 0.9]",
                          "region = [0.5, 0.5, 1.4, 0.9]"),
         {"outside the flow field", "good.vtk"}},
        {"disk_mass_model",
         test::replaceAll(dropletScene("\"good.vtk\""), "mass_model = \"sphere\"", "mass_model = \"disk\""),
         {"dem.mass_model = \"sphere\""}},
        {"time_step",
         test::replaceAll(dropletScene("\"good.vtk\"", "viscosity = 1000.0"), "viscosity = 1.8e-5\n", ""),
         {"relaxation time", "dem.dt"}},
    };
    for (const auto& c : cases) {
        test::writeText(dir / (c.name + ".toml"), c.scene);
        const auto r =
            test::runGranulab(fmt::format("run {}.toml --quiet --out out_{}", c.name, c.name), dir);
        EXPECT_EQ(r.status, 2) << c.name << "\n" << r.output;
        for (const auto& e : c.expect)
            EXPECT_NE(r.output.find(e), std::string::npos) << c.name << ": missing '" << e << "' in:\n"
                                                           << r.output;
    }
}

TEST(Cli, FluidSeriesIsReadFileByFileAndResumesBitForBit) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    std::filesystem::create_directories(dir / "cfd");
    for (int k = 0; k < 3; ++k)  // times 0, 0.01, 0.02 s; names that sort differently as text
        test::writeText(dir / fmt::format("cfd/case_{}.vtk", k == 2 ? 10 : k),
                        quadField(1 + 0.5 * k, 0.01 * k));
    test::writeText(dir / "drops.toml", dropletScene("\"cfd\"", "time_interpolation = true"));
    const std::string common = " --quiet --set output.checkpoint_interval=0.005";
    const auto run = [&](const std::string& args) {
        const auto r = test::runGranulab("run drops.toml" + common + " " + args, dir);
        EXPECT_EQ(r.status, 0) << r.output;
    };
    run("--out full");
    run("--out split --set run.end_time=0.0137");  // stops between the second and third field
    run("--resume split");
    const std::string full = test::readText(dir / "full/final.csv");
    ASSERT_GT(full.size(), 500u);
    EXPECT_NE(full.find("fluid_ux"), std::string::npos);
    EXPECT_EQ(full, test::readText(dir / "split/final.csv"));
    const std::string summary = test::readText(dir / "full/summary.json");
    EXPECT_NE(summary.find("\"fields\": 3"), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"field_loads\": 3"), std::string::npos) << summary;  // each file read once
    EXPECT_NE(summary.find("3 field files (file times, linear in time)"), std::string::npos) << summary;
}

TEST(Cli, FluidBadLaterFieldStopsBeforeOrWhenDue) {
    // A series whose third field is cut: fluid.check = "all" refuses the scene (exit 2); "first"
    // starts, and stops with exit 3 naming the file when that field is due, the checkpoint kept.
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    std::filesystem::create_directories(dir / "cfd");
    test::writeText(dir / "cfd/a_0.vtk", quadField(1, 0));
    test::writeText(dir / "cfd/a_1.vtk", quadField(1, 0.01));
    const std::string cut = quadField(1, 0.02);
    test::writeText(dir / "cfd/a_2.vtk", cut.substr(0, cut.size() - 200));
    // The times come from a .series index, so "first" need not open the files to know them.
    test::writeText(dir / "cfd/a.vtk.series",
                    R"({"file-series-version": "1.0", "files": [{"name": "a_0.vtk", "time": 0}, )"
                    R"({"name": "a_1.vtk", "time": 0.01}, {"name": "a_2.vtk", "time": 0.02}]})");
    test::writeText(dir / "all.toml", dropletScene("\"cfd/a.vtk.series\""));
    test::writeText(dir / "first.toml", dropletScene("\"cfd/a.vtk.series\"", "check = \"first\""));
    const auto all = test::runGranulab("run all.toml --quiet --out all", dir);
    EXPECT_EQ(all.status, 2) << all.output;
    EXPECT_NE(all.output.find("a_2.vtk"), std::string::npos) << all.output;
    const auto first = test::runGranulab("run first.toml --quiet --out first", dir);
    EXPECT_EQ(first.status, 3) << first.output;
    EXPECT_NE(first.output.find("a_2.vtk"), std::string::npos) << first.output;
    EXPECT_NE(first.output.find("could not be loaded at t = 0.02"), std::string::npos) << first.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "first/checkpoint.bin"));
}

TEST(Cli, FluidEvenTimingRefusesAResumeWithAnotherEnd) {
    // The seed's rule spreads the fields over run.end_time (Eq. 4.2): resuming with another end
    // would move every field's time, so the checkpoint refuses it; the same end resumes.
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    std::filesystem::create_directories(dir / "cfd");
    for (int k = 0; k < 2; ++k) test::writeText(dir / fmt::format("cfd/f_{}.vtk", k), quadField(1 + k, 0));
    test::writeText(dir / "even.toml", dropletScene("\"cfd\"", "timing = \"even\""));
    auto r = test::runGranulab("run even.toml --quiet --out run --set run.end_time=0.01", dir);
    ASSERT_EQ(r.status, 0) << r.output;
    r = test::runGranulab("run even.toml --quiet --resume run", dir);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("fluid.timing"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace granulab
