// SPDX-License-Identifier: MIT
// Honest runs (issue 11 items 11-14 and the help item): SIGINT/SIGTERM stop a run cleanly with a
// checkpoint that resumes bit for bit, a damaged checkpoint is refused naming the file, an
// output folder belongs to one run (--overwrite), every command lists itself with an example.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <nlohmann/json.hpp>
#include <thread>

#include "../support.hpp"

using namespace granulab;
namespace fs = std::filesystem;

namespace {

const char* kTwoDisks = R"([run]
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
velocity = [0.5, 0.0]
material = "g"
[[particle]]
position = [0.05, 0.0]
radius = 0.01
material = "g"
[output]
checkpoint_interval = 0.005
)";

/// Starts `granulab args...` in `workDir` (output into workDir/<log>), waits until `waitFor`
/// exists, sends `signal` and returns the exit status (-1: it did not end within a minute).
int runAndSignal(const std::vector<std::string>& args, const fs::path& workDir, const fs::path& waitFor,
                 int signal, const std::string& log) {
    const pid_t pid = fork();
    if (pid == 0) {
        if (chdir(workDir.c_str()) != 0) _exit(127);
        if (!freopen(log.c_str(), "w", stdout) || !freopen(log.c_str(), "a", stderr)) _exit(127);
        std::vector<char*> argv;
        std::string binary = GRANULAB_BINARY;
        argv.push_back(binary.data());
        std::vector<std::string> copy = args;
        for (auto& a : copy) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(binary.c_str(), argv.data());
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    bool signalled = false;
    int raw = 0;
    while (std::chrono::steady_clock::now() < deadline) {
        if (waitpid(pid, &raw, WNOHANG) == pid) return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
        if (!signalled && fs::exists(workDir / waitFor)) {
            kill(pid, signal);
            signalled = true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    kill(pid, SIGKILL);
    waitpid(pid, &raw, 0);
    return -1;
}

nlohmann::json summaryOf(const fs::path& dir) {
    return nlohmann::json::parse(test::readText(dir / "summary.json"));
}

void overwriteAt(const fs::path& file, std::size_t at, const std::string& bytes) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(at));
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

// Item 14: Ctrl-C finishes the step, writes checkpoint, series row and summary ("interrupted"),
// prints the resume command and exits 130; the resumed run ends bit for bit where an
// uninterrupted one does.
TEST(Cli, SigintStopsCleanlyAndTheResumedRunIsBitForBit) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    const std::string scene = std::string(GRANULAB_SOURCE_DIR) + "/examples/disks_in_box.toml";
    const std::vector<std::string> sets = {"--set", "output.checkpoint_interval=0.002",
                                           "--set", "output.snapshot_interval=0.01",
                                           "--set", "output.series_interval=0.001"};
    std::vector<std::string> args = {"run", scene, "--quiet", "--out", "int", "--set", "run.end_time=10"};
    args.insert(args.end(), sets.begin(), sets.end());
    const int status = runAndSignal(args, dir, "int/checkpoint.bin", SIGINT, "int.log");
    const std::string log = test::readText(dir / "int.log");
    ASSERT_EQ(status, 130) << log;
    EXPECT_NE(log.find("interrupted by SIGINT"), std::string::npos) << log;
    EXPECT_NE(log.find("resume with: granulab run"), std::string::npos) << log;
    EXPECT_NE(log.find("--resume int"), std::string::npos) << log;
    const auto js = summaryOf(dir / "int");
    EXPECT_EQ(js["status"], "interrupted");
    EXPECT_NE(js["resume"].get<std::string>().find("--resume int"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "int/final.csv"));  // the end state of a finished run only
    const double stopped = js["sim_time"].get<double>();
    ASSERT_GT(stopped, 0.0);
    ASSERT_LT(stopped, 10.0);
    // A series row at the stop.
    const std::string series = test::readText(dir / "int/series.csv");
    const std::string lastRow = series.substr(series.rfind('\n', series.size() - 2) + 1);
    EXPECT_NEAR(std::stod(lastRow), stopped, 1e-12) << lastRow;

    std::string common = fmt::format(" --quiet --set run.end_time={:.17g}", stopped + 0.004);
    for (std::size_t k = 1; k < sets.size(); k += 2) common += " --set " + sets[k];
    const auto resumed = test::runGranulab("run '" + scene + "'" + common + " --resume int", dir);
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    EXPECT_EQ(summaryOf(dir / "int")["status"], "completed");
    const auto full = test::runGranulab("run '" + scene + "'" + common + " --out full", dir);
    ASSERT_EQ(full.status, 0) << full.output;
    const std::string expected = test::readText(dir / "full/final.csv");
    ASSERT_GT(expected.size(), 1000u);
    EXPECT_EQ(expected, test::readText(dir / "int/final.csv"));
}

// Item 14 for the event-driven engine: SIGTERM stops after a whole event (exit 143) and the run
// resumes to the same final state.
TEST(Cli, SigtermStopsAnEdmdRunWhichResumes) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    test::writeText(dir / "gas.toml",
                    "[run]\nengine = \"edmd\"\ndimension = 2\nseed = 3\nend_time = 1e6\n[edmd]\ncount = 400\n"
                    "volume_fraction = 0.3\nradius = 1.0\nrestitution = 1.0\nequilibrate = 5\n"
                    "analysis_files = false\n[output]\nvtk = false\ncheckpoint_interval = 5.0\n"
                    "series_interval = 5.0\n");
    const int status = runAndSignal({"run", "gas.toml", "--quiet", "--out", "int"}, dir, "int/checkpoint.bin",
                                    SIGTERM, "int.log");
    const std::string log = test::readText(dir / "int.log");
    ASSERT_EQ(status, 143) << log;
    EXPECT_NE(log.find("interrupted by SIGTERM"), std::string::npos) << log;
    const auto js = summaryOf(dir / "int");
    EXPECT_EQ(js["status"], "interrupted");
    const double stopped = js["sim_time"].get<double>();
    ASSERT_GT(stopped, 0.0);
    const std::string end = fmt::format(" -q --set run.end_time={:.17g}", std::ceil(stopped) + 2.0);
    const auto resumed = test::runGranulab("run gas.toml --resume int" + end, dir);
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    ASSERT_EQ(test::runGranulab("run gas.toml --out full" + end, dir).status, 0);
    EXPECT_EQ(test::readText(dir / "full/final.csv"), test::readText(dir / "int/final.csv"));
}

// Item 12: any change of checkpoint.bin after it was written is exit status 2 naming the file.
TEST(Cli, DamagedCheckpointIsRefusedNamingTheFile) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    test::writeText(dir / "two.toml", kTwoDisks);
    ASSERT_EQ(test::runGranulab("run two.toml --quiet --out base", dir).status, 0);
    const std::string good = test::readText(dir / "base/checkpoint.bin");
    ASSERT_GT(good.size(), 200u);
    const std::size_t middle = good.size() / 2;
    struct Damage {
        const char* name;
        std::string bytes;  ///< the damaged file
        const char* expect;
    };
    std::string flipped = good;
    flipped[middle] = static_cast<char>(flipped[middle] ^ 0x08);
    std::string nan = good;
    nan.replace(middle - 32, 64, std::string(64, '\xff'));
    const Damage damages[] = {{"flip", flipped, "checksum mismatch"},
                              {"nan", nan, "checksum mismatch"},
                              {"cut", good.substr(0, middle), "damaged"},
                              {"stub", good.substr(0, 20), "damaged"},
                              {"empty", "", "not a granulab checkpoint"}};
    for (const auto& d : damages) {
        SCOPED_TRACE(d.name);
        fs::create_directories(dir / d.name);
        test::writeText(dir / d.name / "checkpoint.bin", d.bytes);
        const auto r = test::runGranulab(
            fmt::format("run two.toml --quiet --resume {} --set run.end_time=0.02", d.name), dir);
        EXPECT_EQ(r.status, 2) << r.output;
        EXPECT_NE(r.output.find(std::string(d.name) + "/checkpoint.bin"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(d.expect), std::string::npos) << r.output;
    }
    // The undamaged file resumes.
    fs::create_directories(dir / "copy");
    fs::copy_file(dir / "base/checkpoint.bin", dir / "copy/checkpoint.bin");
    const auto r = test::runGranulab("run two.toml --quiet --resume copy --set run.end_time=0.02", dir);
    EXPECT_EQ(r.status, 0) << r.output;
    // Single bytes anywhere in the payload are caught too.
    for (const std::size_t at : {std::size_t{9}, std::size_t{40}, good.size() - 20, good.size() - 1}) {
        SCOPED_TRACE(at);
        fs::create_directories(dir / "any");
        fs::copy_file(dir / "base/checkpoint.bin", dir / "any/checkpoint.bin",
                      fs::copy_options::overwrite_existing);
        overwriteAt(dir / "any/checkpoint.bin", at, std::string(1, static_cast<char>(good[at] ^ 0x40)));
        const auto a = test::runGranulab("run two.toml --quiet --resume any --set run.end_time=0.02", dir);
        EXPECT_EQ(a.status, 2) << a.output;
        EXPECT_NE(a.output.find("any/checkpoint.bin"), std::string::npos) << a.output;
    }
}

// Item 13: a second run into a folder with another run's outputs is refused (exit 2, naming
// --overwrite); --overwrite removes that run's files (and only those) first; --resume appends.
TEST(Cli, OutputFolderBelongsToOneRun) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    test::writeText(dir / "two.toml", kTwoDisks);
    ASSERT_EQ(
        test::runGranulab("run two.toml --quiet --out out --set output.snapshot_interval=0.001", dir).status,
        0);
    ASSERT_TRUE(fs::exists(dir / "out/vtk/particles_000008.vtp"));
    test::writeText(dir / "out/notes.txt", "mine");
    test::writeText(dir / "out/vtk/mine.txt", "mine too");
    auto r = test::runGranulab("run two.toml --quiet --out out", dir);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("output of another run"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--overwrite"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(dir / "out/vtk/particles_000008.vtp"));  // nothing touched
    r = test::runGranulab("run two.toml --quiet --out out --overwrite", dir);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out/vtk/particles_000008.vtp"));  // the old run's snapshots are gone
    EXPECT_TRUE(fs::exists(dir / "out/vtk/particles_000001.vtp"));   // the new run's end snapshot
    EXPECT_EQ(test::readText(dir / "out/notes.txt"), "mine");        // the user's files stay
    EXPECT_EQ(test::readText(dir / "out/vtk/mine.txt"), "mine too");
    // Resume appends; with --overwrite it would remove its own checkpoint: refused.
    r = test::runGranulab("run two.toml --quiet --resume out --set run.end_time=0.02", dir);
    EXPECT_EQ(r.status, 0) << r.output;
    r = test::runGranulab("run two.toml --quiet --resume out --overwrite --set run.end_time=0.03", dir);
    EXPECT_EQ(r.status, 2) << r.output;
    // An empty folder, or one with only other files, is simply used.
    fs::create_directories(dir / "empty");
    fs::create_directories(dir / "other");
    test::writeText(dir / "other/readme.txt", "x");
    EXPECT_EQ(test::runGranulab("run two.toml --quiet --out empty", dir).status, 0);
    EXPECT_EQ(test::runGranulab("run two.toml --quiet --out other", dir).status, 0);
}

// Item 11 and the help item: a folder given as the scene; `help` lists every command and every
// command's --help shows an example.
TEST(Cli, HelpListsEveryCommandWithAnExample) {
    const test::ScratchDir scratch;
    const auto& dir = scratch.path;
    auto r = test::runGranulab("help", dir);
    ASSERT_EQ(r.status, 0);
    for (const char* command : {"run", "info", "render", "analyze", "master-equation", "help"}) {
        SCOPED_TRACE(command);
        EXPECT_NE(r.output.find(std::string("granulab ") + command + " "), std::string::npos) << r.output;
        const auto h = test::runGranulab(std::string(command) + " --help", dir);
        EXPECT_EQ(h.status, 0) << h.output;
        EXPECT_NE(h.output.find(std::string("example: granulab ") + command), std::string::npos) << h.output;
    }
    EXPECT_NE(r.output.find("130"), std::string::npos);
    EXPECT_NE(r.output.find("--overwrite"), std::string::npos);
    fs::create_directories(dir / "scenes");
    for (const char* command : {"run", "info"}) {
        r = test::runGranulab(std::string(command) + " scenes", dir);
        EXPECT_EQ(r.status, 2) << r.output;
        EXPECT_NE(r.output.find("scenes: is a directory, expected a scene file (.toml)"), std::string::npos)
            << r.output;
    }
}
