// SPDX-License-Identifier: MIT
// The engine table (app/engine_table.hpp). To add an engine: write its adapter (a Simulation,
// app/<engine>/), its scene section reader (io/<engine>_sections) and add one row here.
#include "app/engine_table.hpp"

#include <fmt/format.h>

#include "app/convert.hpp"
#include "app/dem/dem_engine.hpp"
#include "app/edmd/edmd_engine.hpp"
#include "core/error.hpp"
#include "io/dem_sections.hpp"
#include "io/edmd_sections.hpp"
#include "io/gsi_scene.hpp"
#include "io/gsi_script.hpp"

namespace granulab::app {

const std::vector<EngineEntry>& engineTable() {
    static const std::vector<EngineEntry> table = {
        {"dem", "time-driven soft-particle DEM in 2D: disks and convex polygons (gc2d, cfddem)",
         io::demSceneSections, makeDemSimulation, demInfo, demAnalyze, "", true},
        {"edmd", "event-driven MD of inelastic hard disks and spheres (edmd)", io::edmdSceneSections,
         makeEdmdSimulation, edmdInfo, edmdAnalyze, "", true},
    };
    return table;
}

const EngineEntry* findEngine(const std::string& name) {
    for (const auto& e : engineTable())
        if (e.name == name) return &e;
    return nullptr;
}

std::string engineNamesText() {
    std::string s;
    for (const auto& e : engineTable()) s += (s.empty() ? "" : ", ") + e.name;
    return s;
}

const EngineEntry& engineOf(const model::SceneDef& scene) {
    if (const EngineEntry* e = findEngine(scene.run.engine)) return *e;
    throw SceneError(
        makeDiagnostic(scene.run.loc.file, scene.run.loc.line, "run.engine",
                       fmt::format("unknown engine '{}'; allowed: {}", scene.run.engine, engineNamesText())));
}

std::vector<io::SceneSections> sceneSections() {
    std::vector<io::SceneSections> list;
    for (const auto& e : engineTable()) list.push_back(e.sections());
    return list;
}

namespace {
ScriptPolicy& scriptPolicy() {
    static ScriptPolicy policy;
    return policy;
}
}  // namespace

void setScriptPolicy(ScriptPolicy policy) {
    scriptPolicy() = std::move(policy);
}

model::SceneDef readScene(const std::string& path, const std::vector<io::Override>& overrides) {
    // A folder of the cfddem seed's input files (conditions.txt, boundary.txt, startvalue.txt).
    if (isCfddemInput(path)) return readCfddemScene(path, overrides);
    if (io::isGsiPath(path)) return readGsiScene(path, overrides);  // gc2d's scene language
    if (io::isGsiScript(path)) {  // a gsi generator (gc2d's .gsi.pl), only when allowed
        model::SceneDef scene = io::readGsiScript(path, scriptPolicy().args, scriptPolicy().allowed);
        scene.path = path;
        return withOverrides(std::move(scene), overrides);
    }
    return io::readScene(path, overrides, sceneSections());
}

model::SceneDef readSceneText(const std::string& text, const std::string& path,
                              const std::vector<io::Override>& overrides) {
    if (io::isGsiPath(path)) return withOverrides(io::gsiToScene(io::parseGsi(text, path)), overrides);
    return io::readSceneText(text, path, overrides, sceneSections());
}

}  // namespace granulab::app
