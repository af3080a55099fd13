// SPDX-License-Identifier: MIT
// The cfddem seed's three input files on the command line (app/convert.hpp): `granulab run DIR`
// and `granulab convert DIR s.toml` + `granulab run s.toml` give byte-identical outputs, --set
// works on a folder, and malformed files exit with status 2 naming file:line.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "../support.hpp"
#include "../support/cfddem_trio.hpp"

using namespace granulab;
using test::CfddemTrio;
using test::replaced;

namespace {

namespace fs = std::filesystem;

/// A legacy VTK field of uniform updraft (0.5 m/s) over the test box and beyond.
const char* kUpdraft = R"(# vtk DataFile Version 3.0
uniform updraft
ASCII
DATASET STRUCTURED_POINTS
DIMENSIONS 3 3 1
ORIGIN -0.1 -0.1 0
SPACING 0.2 0.3 1
POINT_DATA 9
VECTORS U float
0 0.5 0  0 0.5 0  0 0.5 0
0 0.5 0  0 0.5 0  0 0.5 0
0 0.5 0  0 0.5 0  0 0.5 0
)";

void expectSameFile(const fs::path& a, const fs::path& b) {
    ASSERT_TRUE(fs::exists(a)) << a;
    ASSERT_TRUE(fs::exists(b)) << b;
    const std::string ta = test::readText(a), tb = test::readText(b);
    EXPECT_FALSE(ta.empty()) << a;
    EXPECT_TRUE(ta == tb) << a << " and " << b << " differ";
}

}  // namespace

TEST(Cli, CfddemTrioRunsAsAFolderAndAsItsConvertedScene) {
    test::ScratchDir tmp;
    CfddemTrio trio;
    trio.conditions += "#CF cfd/updraft.vtk\n";
    trio.write(tmp.path / "trio");
    fs::create_directories(tmp.path / "trio" / "cfd");
    test::writeText(tmp.path / "trio" / "cfd" / "updraft.vtk", kUpdraft);

    const auto direct = test::runGranulab("run trio --out direct -q", tmp.path, 120);
    ASSERT_EQ(direct.status, 0) << direct.output;
    // Converted into another folder: the field path is rewritten relative to the scene file.
    const auto conv = test::runGranulab("convert trio scenes/trio.toml", tmp.path, 60);
    ASSERT_EQ(conv.status, 0) << conv.output;
    EXPECT_NE(conv.output.find("wrote scenes/trio.toml: 3 particle(s)"), std::string::npos) << conv.output;
    const std::string toml = test::readText(tmp.path / "scenes" / "trio.toml");
    EXPECT_NE(toml.find("fields = [\"../trio/cfd/updraft.vtk\"]"), std::string::npos) << toml;
    const auto converted = test::runGranulab("run scenes/trio.toml --out converted -q", tmp.path, 120);
    ASSERT_EQ(converted.status, 0) << converted.output;

    for (const char* f : {"final.csv", "series.csv", "CSV/r_x.csv", "CSV/v_y.csv", "CSV/omega.csv"})
        expectSameFile(tmp.path / "direct" / f, tmp.path / "converted" / f);
    // The inlet emitted (20/s over 0.1 s: 2 balls) and the air is the file's.
    std::vector<std::string> header;
    const auto rows = test::readCsv(tmp.path / "direct" / "final.csv", header);
    EXPECT_EQ(rows.size(), 5u);
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(rows[0].at("fluid_uy"), "0.5");
    const auto summary = nlohmann::json::parse(test::readText(tmp.path / "direct" / "summary.json"));
    EXPECT_EQ(summary["status"], "completed");
}

TEST(Cli, CfddemTrioConvertRefusesToOverwrite) {
    test::ScratchDir tmp;
    CfddemTrio().write(tmp.path / "trio");
    ASSERT_EQ(test::runGranulab("convert trio s.toml -q", tmp.path).status, 0);
    const auto again = test::runGranulab("convert trio s.toml", tmp.path);
    EXPECT_EQ(again.status, 2) << again.output;
    EXPECT_NE(again.output.find("s.toml: exists; pass --overwrite to replace it"), std::string::npos)
        << again.output;
    EXPECT_EQ(test::runGranulab("convert trio s.toml --overwrite -q", tmp.path).status, 0);
    // A TOML scene converts to gsi only (granulab convert reads TOML as the other direction).
    const auto notFolder = test::runGranulab("convert s.toml t.toml", tmp.path);
    EXPECT_EQ(notFolder.status, 2) << notFolder.output;
    EXPECT_NE(notFolder.output.find("t.toml: name the gsi scene to write (.gsi)"), std::string::npos)
        << notFolder.output;
    const auto neither = test::runGranulab("convert s.txt t.toml", tmp.path);
    EXPECT_EQ(neither.status, 2) << neither.output;
    EXPECT_NE(neither.output.find("s.txt: neither a folder, a .gsi nor a .toml scene"), std::string::npos)
        << neither.output;
}

TEST(Cli, CfddemTrioMalformedFilesExitTwoWithFileAndLine) {
    test::ScratchDir tmp;
    const CfddemTrio base;
    struct Case {
        std::string file, from, to, expected;
    };
    const std::vector<Case> cases = {
        {"start", "#RY 0.20 0.22", "#RY 0.20 zwei", "startvalue.txt:4: #RY: 'zwei' is not a number"},
        {"start", "#RY 0.20 0.22 0.18", "#RY 0.20 0.22", "startvalue.txt:4: #RY: 2 values, but #RX has 3"},
        {"boundary", "#E1 1 2 3", "#E1 0 2 3", "boundary.txt:11: #E1: edge 1: point index 0 out of range"},
        {"boundary", "#E2 2 3 4 5 6 1", "#E2 2 3 4 5 6 9",
         "boundary.txt:12: #E2: edge 6: point index 9 out of range"},
        {"conditions", "#MU 0.5", "#MY 0.5", "conditions.txt:13: #MY: unknown key (did you mean '#MU'?)"},
        {"boundary", "", "", "boundary.txt: missing: the boundary file"},
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const auto& c = cases[k];
        CfddemTrio t = base;
        std::string& text = c.file == "start" ? t.start : c.file == "boundary" ? t.boundary : t.conditions;
        if (!c.from.empty()) text = replaced(text, c.from, c.to);
        const fs::path dir = tmp.path / ("case" + std::to_string(k));
        t.write(dir);
        if (c.from.empty()) fs::remove(dir / "boundary.txt");
        for (const std::string command : {"run", "info", "convert"}) {
            const std::string args =
                command + " case" + std::to_string(k) + (command == "convert" ? " s.toml" : "");
            const auto r = test::runGranulab(args, tmp.path, 60);
            EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
            EXPECT_NE(r.output.find(c.expected), std::string::npos)
                << args << ": expected '" << c.expected << "' in\n"
                << r.output;
        }
    }
    EXPECT_FALSE(fs::exists(tmp.path / "s.toml"));
    // A folder without any of the three files: run reads scene files only, convert says what it needs.
    fs::create_directories(tmp.path / "empty");
    const auto empty = test::runGranulab("run empty", tmp.path, 60);
    EXPECT_EQ(empty.status, 2) << empty.output;
    EXPECT_NE(empty.output.find("empty: is a directory, expected a scene file (.toml)"), std::string::npos)
        << empty.output;
    const auto emptyConvert = test::runGranulab("convert empty s.toml", tmp.path, 60);
    EXPECT_EQ(emptyConvert.status, 2) << emptyConvert.output;
    EXPECT_NE(emptyConvert.output.find("empty: is a folder without the cfddem seed's input files"),
              std::string::npos)
        << emptyConvert.output;
}

TEST(Cli, CfddemTrioTakesSetOverridesAndNamesTheFilesLines) {
    test::ScratchDir tmp;
    CfddemTrio().write(tmp.path / "trio");
    // A shorter run; the default output folder is named after the folder (written as trio/).
    const auto r = test::runGranulab("run trio/ --set run.end_time=0.02 output.vtk=false -q", tmp.path, 60);
    ASSERT_EQ(r.status, 0) << r.output;
    const auto summary = nlohmann::json::parse(test::readText(tmp.path / "out" / "trio" / "summary.json"));
    EXPECT_DOUBLE_EQ(summary["sim_time"].get<double>(), 0.02);
    EXPECT_FALSE(fs::exists(tmp.path / "out" / "trio" / "snapshots.pvd"));
    // A bad overridden value is located at its --set.
    const auto bad = test::runGranulab("info trio --set contact[0].mu=-1", tmp.path, 60);
    EXPECT_EQ(bad.status, 2) << bad.output;
    EXPECT_NE(bad.output.find("--set contact[0].mu=-1"), std::string::npos) << bad.output;
    // An engine check of a value from the files names its line, with and without --set.
    CfddemTrio coarse;
    coarse.conditions = replaced(coarse.conditions, "#DT 2e-5", "#DT 2e-3");
    coarse.conditions = replaced(coarse.conditions, "#TE 0.1", "#TE 1");
    coarse.write(tmp.path / "coarse");
    for (const std::string extra : {"", " --set output.vtk=false"}) {
        const auto r2 = test::runGranulab("info coarse" + extra, tmp.path, 60);
        EXPECT_EQ(r2.status, 2) << r2.output;
        EXPECT_NE(r2.output.find("conditions.txt:3: dem.dt: dt = 0.002 s is above the stability limit"),
                  std::string::npos)
            << extra << "\n"
            << r2.output;
    }
}
