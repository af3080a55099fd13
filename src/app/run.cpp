// SPDX-License-Identifier: MIT
// `granulab run` (app/run.hpp): scene -> engine table -> Simulation -> run loop. The output
// folder belongs to one run: a fresh run into a folder with another run's outputs is refused
// unless --overwrite removes them first (io/output_folder.hpp); --resume appends.
#include "app/run.hpp"

#include <fmt/format.h>

#include <array>
#include <filesystem>
#include <system_error>

#include "app/engine_table.hpp"
#include "app/run_loop.hpp"
#include "app/simulation_options.hpp"
#include "core/communicator.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
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

/// A fresh run (or a resume written elsewhere) must not mix its files with another run's.
void claimOutputFolder(const RunOptions& opt, const std::string& dir) {
    if (!opt.resumeDir.empty() && sameFolder(opt.resumeDir, dir)) {  // resume appends
        if (opt.overwrite)
            throw SceneError(makeDiagnostic(dir, 0, "--overwrite",
                                            "would remove the checkpoint that --resume continues; "
                                            "resume without --overwrite, or write to another --out"));
        return;
    }
    const auto outputs = io::runOutputsIn(dir);
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
            claimOutputFolder(opt, dir);
            fs::create_directories(dir);
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
