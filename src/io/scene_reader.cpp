// SPDX-License-Identifier: MIT
// TOML scene reader (docs/scene-format.md "[run]", "[output]", "Errors and exit status"): the
// generic part. Every table is read through a TableReader that remembers which keys it consumed,
// so that anything left over is reported as an unknown key with a hint; each engine's sections
// are read by the `read` of its SceneSections row.
#include "io/scene_reader.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/suggest.hpp"
#include "io/toml_table_reader.hpp"

namespace granulab::io {

namespace {

using model::SceneDef;

const SceneSections* findEngine(const std::vector<SceneSections>& engines, const std::string& name) {
    const auto it = std::find_if(engines.begin(), engines.end(),
                                 [&](const SceneSections& e) { return e.engine == name; });
    return it != engines.end() ? &*it : nullptr;
}

std::vector<std::string> engineNames(const std::vector<SceneSections>& engines) {
    std::vector<std::string> names;
    for (const auto& e : engines) names.push_back(e.engine);
    return names;
}

/// Most threads run.threads accepts.
constexpr std::int64_t kMaxThreads = 4096;

/// Reads [run]; run.engine must name one of `engines`. Returns the running engine, nullptr when
/// run.engine is not one of them (reported here), whose needsEndTime says whether run.end_time
/// is required.
const SceneSections* readRun(TableReader& r, model::RunDef& run, const std::vector<SceneSections>& engines) {
    run.loc = r.loc();
    const bool engineOk = r.choice("engine", run.engine, engineNames(engines));
    const SceneSections* running = nullptr;
    if (engineOk || !r.table().get("engine")) running = findEngine(engines, run.engine);
    if (!running && !r.table().get("engine"))  // a default engine that the table does not list
        r.diags().error(run.loc, "run.engine",
                        fmt::format("missing: the engine, allowed: {}", joinList(engineNames(engines))));
    std::int64_t dim = run.dimension;
    if (r.integer("dimension", dim)) run.dimension = static_cast<int>(dim);
    std::int64_t seed = static_cast<std::int64_t>(run.seed);
    if (r.integer("seed", seed)) run.seed = static_cast<std::uint64_t>(seed);
    if (!r.number("end_time", run.endTime) && !r.table().get("end_time") && running && running->needsEndTime)
        r.diags().error(run.loc, "run.end_time", "missing: simulated end time [s], allowed (0, inf)");
    r.number("benchmark_from", run.benchmarkFrom);
    r.number("start_time", run.startTime);
    std::int64_t threads = run.threads;
    if (r.integer("threads", threads)) {
        if (threads < 0 || threads > kMaxThreads)
            r.diags().error(run.loc, "run.threads",
                            fmt::format("{} threads: allowed 0 (every core this process may use) to {}",
                                        threads, kMaxThreads));
        else
            run.threads = static_cast<int>(threads);
    }
    r.boolean("load_balance", run.loadBalance);
    r.string("title", run.title);
    return running;
}

void readOutput(TableReader& r, model::OutputDef& o) {
    o.loc = r.loc();
    r.number("snapshot_interval", o.snapshotInterval);
    r.number("series_interval", o.seriesInterval);
    r.number("checkpoint_interval", o.checkpointInterval);
    r.boolean("vtk", o.vtk);
    r.boolean("contacts", o.contacts);
    r.boolean("particle_series", o.particleSeries);
    r.strings("analyses", o.analyses);
    r.boolean("gc2d", o.gc2d.enabled);
    r.string("gc2d_basename", o.gc2d.basename);
    r.integer("gc2d_next_data_number", o.gc2d.nextDataNumber);
    r.integer("gc2d_next_setup_number", o.gc2d.nextSetupNumber);
    r.number("gc2d_setup_interval", o.gc2d.setupInterval);
    r.number("gc2d_line_interval", o.gc2d.lineInterval);
}

/// Reads the sections of the running engine (nullptr: run.engine is unknown, its error is
/// reported and no engine's sections are read). A section of another engine is reported where it
/// stands; it is not read, so its keys are not checked.
void readEngineSections(TableReader& r, SceneDef& scene, const SceneSections* running,
                        const std::vector<SceneSections>& engines) {
    const std::string& path = r.file();
    if (running) {
        if (!r.table().get(running->required))
            r.diags().error(
                {path, 1, 1}, running->required,
                fmt::format("missing section [{}] ({})", running->required, running->requiredHint));
        if (running->read) running->read(r, scene);
    }
    std::vector<std::string> seen = running ? running->sections : std::vector<std::string>{};
    for (const auto& e : engines) {
        if (&e == running) continue;
        for (const auto& section : e.sections) {
            // A section shared with the running engine has been read; one shared by two others is
            // reported once, for its first engine.
            if (std::find(seen.begin(), seen.end(), section) != seen.end()) continue;
            seen.push_back(section);
            const toml::node* n = r.node(section);  // a known key either way
            if (n && running)
                r.diags().error(
                    locOf(*n, path), section,
                    fmt::format("[{}] belongs to the {} engine; this scene runs run.engine = \"{}\"", section,
                                e.engine, running->engine));
        }
    }
}

SceneDef buildScene(toml::table& root, const std::string& path, const std::vector<Override>& overrides,
                    const std::vector<SceneSections>& engines) {
    Diagnostics diags;
    for (const auto& ov : overrides) applyOverride(root, ov, diags);
    SceneDef scene;
    scene.path = path;
    TableReader r(root, "", path, diags);
    // Without [run] the default engine (model::RunDef) runs.
    const SceneSections* running = findEngine(engines, scene.run.engine);
    withTable(r, "run", [&](TableReader& t) { running = readRun(t, scene.run, engines); });
    if (!root.get("run")) diags.error({path, 1, 1}, "run", "missing section [run] (needs at least end_time)");
    readEngineSections(r, scene, running, engines);
    withTable(r, "output", [&](TableReader& t) { readOutput(t, scene.output); });
    r.finish();
    diags.throwIfAny();
    return scene;
}

}  // namespace

SceneDef readSceneText(const std::string& text, const std::string& path,
                       const std::vector<Override>& overrides, const std::vector<SceneSections>& engines) {
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        const auto& b = e.source().begin;
        throw SceneError(makeDiagnostic(path, static_cast<int>(b.line), "",
                                        fmt::format("syntax error: {}", e.description())));
    }
    return buildScene(root, path, overrides, engines);
}

SceneDef readScene(const std::string& path, const std::vector<Override>& overrides,
                   const std::vector<SceneSections>& engines) {
    if (std::error_code ec; std::filesystem::is_directory(path, ec))
        throw SceneError(makeDiagnostic(path, 0, "", "is a directory, expected a scene file (.toml)"));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(makeDiagnostic(path, 0, "", "cannot open scene file (missing or unreadable)"));
    std::ostringstream ss;
    ss << in.rdbuf();
    return readSceneText(ss.str(), path, overrides, engines);
}

}  // namespace granulab::io
