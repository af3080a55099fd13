// SPDX-License-Identifier: MIT
// `granulab run` (app/run.hpp): scene -> engine table -> Simulation -> run loop.
#include "app/run.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "app/engine_table.hpp"
#include "app/run_loop.hpp"
#include "app/simulation_options.hpp"
#include "core/timer.hpp"
#include "io/scene_override.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

std::string defaultOutDir(const std::string& scenePath) {
    return (fs::path("out") / fs::path(scenePath).stem()).string();
}

int runCommand(const RunOptions& opt) {
    const double startWall = wallSeconds();
    // SceneError -> exit 2 in main; problems of --set values are located at the --set.
    const model::SceneDef scene =
        io::withOverrideLocations(opt.overrides, [&] { return app::readScene(opt.scene, opt.overrides); });
    const EngineEntry& engine = engineOf(scene);
    const std::unique_ptr<Simulation> sim = io::withOverrideLocations(opt.overrides, [&] {
        return engine.build(scene, {opt.scene, opt.quiet});
    });
    for (const auto& w : sim->warnings()) fmt::print(stderr, "warning: {}\n", w);
    const std::string dir = !opt.outDir.empty()
                                ? opt.outDir
                                : (!opt.resumeDir.empty() ? opt.resumeDir : defaultOutDir(opt.scene));
    fs::create_directories(dir);
    return runSimulation(*sim, scene, {engine.name, opt.scene, dir, opt.resumeDir, opt.quiet, startWall});
}

}  // namespace granulab::app
