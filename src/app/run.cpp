// SPDX-License-Identifier: MIT
// `granulab run` (app/run.hpp): scene -> engine table -> Simulation -> run loop. The output
// folder belongs to one run: a fresh run into a folder with another run's outputs is refused
// unless --overwrite removes them first (io/output_folder.hpp); --resume appends. With
// output.gc2d the folder is locked by <basename>.glk (gc2d spec 9.1), which --ignore-lock passes.
#include "app/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "app/engine_table.hpp"
#include "app/run_loop.hpp"
#include "app/simulation_options.hpp"
#include "core/communicator.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "io/gc2d_outputs.hpp"
#include "io/output_folder.hpp"
#include "io/scene_override.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

namespace {

/// `word` as one shell word (single quotes when it holds anything but plain path characters).
std::string shellWord(const std::string& word) {
    const bool plain = !word.empty() && word.find_first_not_of(
                                            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                            "0123456789_@%+=:,./-") == std::string::npos;
    if (plain) return word;
    std::string s = "'";
    for (const char c : word) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return s + "'";
}

/// The command that continues this run from `dir`/checkpoint.bin.
std::string resumeCommand(const RunOptions& opt, const std::string& dir) {
    std::string s = "granulab run " + shellWord(opt.scene);
    for (const auto& o : opt.overrides) s += " --set " + shellWord(o.key + "=" + o.value);
    return s + " --resume " + shellWord(dir);
}

bool sameFolder(const std::string& a, const std::string& b) {
    std::error_code ec;
    return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

bool resumesHere(const RunOptions& opt, const std::string& dir) {
    return !opt.resumeDir.empty() && sameFolder(opt.resumeDir, dir);
}

/// gc2d's lock (spec 9.1; output.gc2d): the name of the lock file in the output folder, or ""
/// when the scene writes no gc2d files.
std::string gc2dLockName(const model::SceneDef& scene) {
    return scene.output.gc2d.enabled ? io::gc2dFileName(scene.output.gc2d.basename, "glk") : "";
}

/// Refuses a folder holding the lock of an earlier gc2d-style run unless --ignore-lock (gc2d's -l)
/// or --overwrite (which removes the earlier run's files, the lock among them); a run resumed into
/// its own folder continues under its own lock.
void checkGc2dLock(const RunOptions& opt, const std::string& dir, const std::string& lock) {
    if (lock.empty() || opt.ignoreLock || opt.overwrite || resumesHere(opt, dir)) return;
    const fs::path path = fs::path(dir) / lock;
    std::error_code ec;
    if (!fs::exists(path, ec)) return;
    throw SceneError(makeDiagnostic(
        dir, 0, "",
        fmt::format(
            "holds the lock file {} of a run with gc2d's files (output.gc2d), whose results would "
            "be overwritten (gc2d spec 9.1); pass --overwrite to replace that run's files, --ignore-lock "
            "(-l) to run anyway, --resume {} to continue that run, or choose another --out",
            lock, shellWord(dir))));
}

/// A fresh run (or a resume written elsewhere) must not mix its files with another run's.
/// `ownLock`: the gc2d lock file this run takes over (--ignore-lock), not counted as an output.
void claimOutputFolder(const RunOptions& opt, const std::string& dir, const std::string& ownLock) {
    if (resumesHere(opt, dir)) {  // resume appends
        if (opt.overwrite)
            throw SceneError(makeDiagnostic(dir, 0, "--overwrite",
                                            "would remove the checkpoint that --resume continues; "
                                            "resume without --overwrite, or write to another --out"));
        return;
    }
    auto outputs = io::runOutputsIn(dir);
    if (!ownLock.empty() && opt.ignoreLock)
        outputs.erase(std::remove(outputs.begin(), outputs.end(), ownLock), outputs.end());
    if (outputs.empty()) return;
    if (opt.overwrite) {
        io::removeRunOutputs(dir);
        return;
    }
    std::string list;
    for (std::size_t k = 0; k < outputs.size() && k < 4; ++k) list += (k ? ", " : "") + outputs[k];
    if (outputs.size() > 4) list += ", ...";
    throw SceneError(makeDiagnostic(
        dir, 0, "",
        fmt::format("the folder holds the output of another run ({}); pass --overwrite to replace it "
                    "(only granulab's own output files are removed), --resume {} to continue it, or "
                    "choose another --out",
                    list, shellWord(dir))));
}

}  // namespace

std::string defaultOutDir(const std::string& scenePath) {
    fs::path p(scenePath);
    if (!p.has_filename()) p = p.parent_path();  // a cfddem folder written as DIR/
    std::error_code ec;
    return (fs::path("out") / (fs::is_directory(p, ec) ? p.filename() : p.stem())).string();
}

int runCommand(const RunOptions& opt) {
    const double startWall = wallSeconds();
    Communicator& comm = worldCommunicator();
    // Under mpirun every rank reads the scene and builds its part of the engine (the same scene
    // errors on every rank; main prints them once); only the root prints and writes files.
    const bool quiet = opt.quiet || !comm.root();
    // SceneError -> exit 2 in main; problems of --set values are located at the --set.
    const model::SceneDef scene =
        io::withOverrideLocations(opt.overrides, [&] { return app::readScene(opt.scene, opt.overrides); });
    const EngineEntry& engine = engineOf(scene);
    if (comm.size() > 1 && !engine.severalRanks)
        throw SceneError(makeDiagnostic(
            scene.run.loc.file, scene.run.loc.line, "run.engine",
            fmt::format("the {} engine runs on one process; this run was started on {} MPI ranks: start "
                        "it without mpirun (engines that run on several ranks: edmd)",
                        engine.name, comm.size())));
    const std::unique_ptr<Simulation> sim = io::withOverrideLocations(opt.overrides, [&] {
        return engine.build(scene, {opt.scene, quiet});
    });
    if (comm.root())
        for (const auto& w : sim->warnings()) fmt::print(stderr, "warning: {}\n", w);
    const std::string dir = !opt.outDir.empty()
                                ? opt.outDir
                                : (!opt.resumeDir.empty() ? opt.resumeDir : defaultOutDir(opt.scene));
    // The root claims the folder; its verdict reaches every rank, which all stop alike (main
    // prints the root's message).
    std::vector<Diagnostic> refusal;
    if (comm.root()) {
        try {
            const std::string lock = gc2dLockName(scene);
            checkGc2dLock(opt, dir, lock);  // before the folder check: its own message
            claimOutputFolder(opt, dir, lock);
            fs::create_directories(dir);
            if (!lock.empty()) {  // before the first file of the run is written
                std::ofstream created(fs::path(dir) / lock, std::ios::app);
                if (!created)
                    throw SceneError(makeDiagnostic(dir, 0, "output.gc2d",
                                                    fmt::format("cannot create the lock file {}", lock)));
            }
        } catch (const SceneError& e) {
            refusal = e.diagnostics();
        }
    }
    std::array<double, 1> refused{refusal.empty() ? 0.0 : 1.0};
    comm.allMax(refused);
    if (refused[0] > 0)
        throw SceneError(
            comm.root() ? refusal
                        : std::vector<Diagnostic>{makeDiagnostic(dir, 0, "", "refused by the root rank")});
    RunContext ctx;
    ctx.engine = engine.name;
    ctx.scenePath = opt.scene;
    ctx.dir = dir;
    ctx.resumeDir = opt.resumeDir;
    ctx.resumeCommand = resumeCommand(opt, dir);
    ctx.quiet = quiet;
    ctx.startWall = startWall;
    return runSimulation(*sim, scene, ctx);
}

}  // namespace granulab::app
