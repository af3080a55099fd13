// SPDX-License-Identifier: MIT
// `granulab convert` and the cfddem folder as a scene path (app/convert.hpp).
#include "app/convert.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "app/engine_table.hpp"
#include "app/exit_codes.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/cfddem_files.hpp"
#include "io/gsi_scene.hpp"
#include "io/scene_toml_writer.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

namespace {

/// Locations of `to` (read from the TOML text named `textName`) pointed back at the matching Def of
/// `from` (read from the three files); locations of --set values are kept.
class LocationRestorer {
public:
    LocationRestorer(std::string textName, std::string fallback)
        : m_text(std::move(textName)), m_fallback(std::move(fallback)) {}

    void operator()(SourceLoc& to, const SourceLoc* from) const {
        if (to.file != m_text) return;  // from a --set
        to = from ? *from : SourceLoc{m_fallback, 0, 0};
    }
    template <class T, class Fn>
    void each(std::vector<T>& to, const std::vector<T>& from, Fn&& fn) const {
        for (std::size_t k = 0; k < to.size(); ++k) fn(to[k], k < from.size() ? &from[k] : nullptr);
    }
    void restore(model::SceneDef& to, const model::SceneDef& from) const {
        const auto& self = *this;
        self(to.run.loc, &from.run.loc);
        self(to.dem.loc, &from.dem.loc);
        each(to.materials, from.materials,
             [&](auto& t, const auto* f) { self(t.loc, f ? &f->loc : nullptr); });
        each(to.contacts, from.contacts, [&](model::ContactDef& t, const model::ContactDef* f) {
            self(t.loc, f ? &f->loc : nullptr);
            for (auto& [key, p] : t.params) {
                const model::LawParamDef* fp = nullptr;
                if (f)
                    if (const auto it = f->params.find(key); it != f->params.end()) fp = &it->second;
                self(p.loc, fp ? &fp->loc : nullptr);
            }
        });
        each(to.particles, from.particles,
             [&](auto& t, const auto* f) { self(t.loc, f ? &f->loc : nullptr); });
        each(to.machines.boundaries, from.machines.boundaries, [&](auto& t, const auto* f) {
            self(t.loc, f ? &f->loc : nullptr);
            self(t.insert.radius.loc, f ? &f->insert.radius.loc : nullptr);
        });
        each(to.machines.inlets, from.machines.inlets, [&](auto& t, const auto* f) {
            self(t.loc, f ? &f->loc : nullptr);
            self(t.insert.radius.loc, f ? &f->insert.radius.loc : nullptr);
        });
        self(to.fluid.loc, from.fluid.present ? &from.fluid.loc : nullptr);
        each(to.fluid.fieldLocs, from.fluid.fieldLocs, [&](auto& t, const auto* f) { self(t, f); });
        self(to.attraction.loc, from.attraction.present ? &from.attraction.loc : nullptr);
        self(to.output.loc, &from.output.loc);
    }

private:
    std::string m_text, m_fallback;
};

std::vector<std::string> convertHeader(const std::string& dir) {
    return {fmt::format("granulab scene converted from the cfddem seed's input files in {}", dir),
            "(conditions.txt, boundary.txt, startvalue.txt; `granulab convert`, docs/scene-format.md",
            "\"The cfddem seed's input files\"). SI units."};
}

}  // namespace

bool isCfddemInput(const std::string& path) {
    return io::hasCfddemFiles(path);
}

model::SceneDef readCfddemScene(const std::string& dir, const std::vector<io::Override>& overrides) {
    return withOverrides(io::readCfddemFolder(dir), overrides);
}

model::SceneDef readGsiScene(const std::string& path, const std::vector<io::Override>& overrides) {
    return withOverrides(io::readGsiFile(path), overrides);
}

model::SceneDef withOverrides(model::SceneDef scene, const std::vector<io::Override>& overrides) {
    if (overrides.empty()) return scene;
    // The overrides act on the TOML form of the scene, like on a scene file; paths stay relative
    // to the scene's own file (the text "lives" at scene.path).
    const std::string textName = scene.path + " (as TOML)";
    std::string text;
    try {
        text = io::sceneToToml(scene, scene.path);
    } catch (const std::invalid_argument& e) {
        throw SceneError(
            makeDiagnostic(scene.path, 0, "--set", fmt::format("cannot apply --set here: {}", e.what())));
    }
    model::SceneDef changed = app::readSceneText(text, textName, overrides);
    LocationRestorer(textName, scene.path).restore(changed, scene);
    changed.path = scene.path;
    return changed;
}

int convertCommand(const ConvertOptions& opt) {
    std::error_code ec;
    if (!fs::is_directory(opt.dir, ec))
        throw SceneError(
            makeDiagnostic(opt.dir, 0, "",
                           "not a folder; `granulab convert DIR scene.toml` reads the cfddem seed's "
                           "folder holding conditions.txt, boundary.txt and startvalue.txt"));
    const model::SceneDef scene = io::readCfddemFolder(opt.dir);
    if (fs::is_directory(opt.out, ec))
        throw SceneError(
            makeDiagnostic(opt.out, 0, "", "is a folder; name the scene file to write, e.g. scene.toml"));
    if (fs::exists(opt.out, ec) && !opt.overwrite)
        throw SceneError(makeDiagnostic(opt.out, 0, "", "exists; pass --overwrite to replace it"));
    std::string text;
    try {
        text = io::sceneToToml(scene, opt.out, convertHeader(opt.dir));
    } catch (const std::invalid_argument& e) {
        throw SceneError(makeDiagnostic(opt.dir, 0, "", e.what()));
    }
    io::writeFileAtomically(opt.out, text);
    if (!opt.quiet) {
        std::size_t inlets = scene.machines.inlets.size();
        for (const auto& b : scene.machines.boundaries)
            for (const auto& e : b.edges) inlets += e.type == "inlet" ? 1 : 0;
        fmt::print("wrote {}: {} particle(s), {} material(s), {} inlet edge(s), end time {} s, dt {} s\n",
                   opt.out, scene.particles.size(), scene.materials.size(), inlets, scene.run.endTime,
                   scene.dem.dt);
        fmt::print("check it with: granulab info {}\n", opt.out);
    }
    return kExitOk;
}

}  // namespace granulab::app
