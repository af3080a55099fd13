// SPDX-License-Identifier: MIT
// `granulab convert` (cfddem folder or gsi -> TOML, TOML -> gsi) and the cfddem folder and gsi file
// as scene paths with --set (app/convert.hpp).
#include "app/convert.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "app/engine_table.hpp"
#include "app/exit_codes.hpp"
#include "core/ascii_case.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/cfddem_files.hpp"
#include "io/gsi_scene.hpp"
#include "io/gsi_script.hpp"
#include "io/gsi_writer.hpp"
#include "io/scene_toml_writer.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

namespace {

/// Locations of `to` (read from the TOML text named `textName`) pointed back at the matching Def of
/// `from` (read from the cfddem files or the gsi); locations of --set values are kept.
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
        const auto plain = [&](auto& t, const auto* f) { self(t.loc, f ? &f->loc : nullptr); };
        each(to.dem.damping, from.dem.damping, plain);
        each(to.shapes, from.shapes, plain);
        each(to.particles, from.particles, plain);
        each(to.blocks, from.blocks, [&](auto& t, const auto* f) {
            self(t.loc, f ? &f->loc : nullptr);
            self(t.radius.loc, f ? &f->radius.loc : nullptr);
        });
        each(to.heaps, from.heaps, plain);
        each(to.walls, from.walls, plain);
        each(to.springs, from.springs, plain);
        each(to.machines.drums, from.machines.drums, plain);
        each(to.machines.sources, from.machines.sources, [&](auto& t, const auto* f) {
            self(t.loc, f ? &f->loc : nullptr);
            self(t.insert.radius.loc, f ? &f->insert.radius.loc : nullptr);
        });
        each(to.machines.outlets, from.machines.outlets, plain);
        self(to.machines.gravity.loc, from.machines.gravity.present ? &from.machines.gravity.loc : nullptr);
        self(to.machines.sizeScaling.loc,
             from.machines.sizeScaling.present ? &from.machines.sizeScaling.loc : nullptr);
        each(to.machines.changes, from.machines.changes, [&](model::ChangeDef& t, const model::ChangeDef* f) {
            self(t.loc, f ? &f->loc : nullptr);
            for (auto& [key, p] : t.set) {
                const model::LawParamDef* fp = nullptr;
                if (f)
                    if (const auto it = f->set.find(key); it != f->set.end()) fp = &it->second;
                self(p.loc, fp ? &fp->loc : nullptr);
            }
        });
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
    // A gc2d restart state (gso derivatives, gci contacts, ids) has no TOML keys: it rides along.
    std::vector<std::vector<Real>> gear;
    std::vector<std::int64_t> particleIds, wallIds;
    for (auto& p : scene.particles) {
        gear.push_back(std::move(p.gear));
        p.gear.clear();
        particleIds.push_back(p.gc2dId);
    }
    for (const auto& w : scene.walls) wallIds.push_back(w.gc2dId);
    std::vector<model::RememberedContactDef> contacts = std::move(scene.rememberedContacts);
    scene.rememberedContacts.clear();
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
    for (std::size_t k = 0; k < changed.particles.size() && k < gear.size(); ++k) {
        changed.particles[k].gear = std::move(gear[k]);
        changed.particles[k].gc2dId = particleIds[k];
    }
    for (std::size_t k = 0; k < changed.walls.size() && k < wallIds.size(); ++k)
        changed.walls[k].gc2dId = wallIds[k];
    changed.rememberedContacts = std::move(contacts);
    return changed;
}

namespace {

enum class Conversion { CfddemToToml, GsiToToml, TomlToGsi };

Conversion conversionOf(const ConvertOptions& opt) {
    std::error_code ec;
    const auto endsWith = [](const std::string& s, const char* tail) {
        return asciiLower(s).ends_with(tail);
    };
    const std::string usage =
        "granulab convert reads a cfddem folder or a .gsi file and writes a .toml scene, or reads a "
        ".toml scene and writes a .gsi file";
    if (fs::is_directory(opt.dir, ec)) return Conversion::CfddemToToml;
    if (io::isGsiPath(opt.dir) || io::isGsiScript(opt.dir)) {
        if (!endsWith(opt.out, ".toml"))
            throw SceneError(
                makeDiagnostic(opt.out, 0, "", "name the TOML scene to write (.toml); " + usage));
        return Conversion::GsiToToml;
    }
    if (endsWith(opt.dir, ".toml")) {
        if (!endsWith(opt.out, ".gsi"))
            throw SceneError(makeDiagnostic(opt.out, 0, "", "name the gsi scene to write (.gsi); " + usage));
        return Conversion::TomlToGsi;
    }
    throw SceneError(makeDiagnostic(opt.dir, 0, "", "neither a folder, a .gsi nor a .toml scene; " + usage));
}

}  // namespace

int convertCommand(const ConvertOptions& opt) {
    const Conversion how = conversionOf(opt);
    std::error_code ec;
    if (fs::is_directory(opt.out, ec))
        throw SceneError(makeDiagnostic(opt.out, 0, "", "is a folder; name the scene file to write"));
    if (fs::exists(opt.out, ec) && !opt.overwrite)
        throw SceneError(makeDiagnostic(opt.out, 0, "", "exists; pass --overwrite to replace it"));
    model::SceneDef scene;
    std::string text;
    switch (how) {
        case Conversion::CfddemToToml:
            scene = io::readCfddemFolder(opt.dir);
            break;
        case Conversion::GsiToToml:
            scene = io::isGsiPath(opt.dir) ? io::readGsiFile(opt.dir) : app::readScene(opt.dir, {});
            break;
        case Conversion::TomlToGsi:
            scene = app::readScene(opt.dir, {});
            break;
    }
    try {
        text = how == Conversion::TomlToGsi
                   ? io::sceneToGsi(scene, fmt::format("converted from {} by granulab convert", opt.dir))
                   : io::sceneToToml(scene, opt.out,
                                     how == Conversion::CfddemToToml
                                         ? convertHeader(opt.dir)
                                         : std::vector<std::string>{fmt::format(
                                               "granulab scene converted from the gc2d gsi scene {} "
                                               "(`granulab convert`, docs/coming-from-gc2d.md). SI units.",
                                               opt.dir)});
    } catch (const std::invalid_argument& e) {
        throw SceneError(makeDiagnostic(opt.dir, 0, "", e.what()));
    }
    io::writeFileAtomically(opt.out, text);
    if (!opt.quiet) {
        std::size_t inlets = scene.machines.inlets.size();
        for (const auto& b : scene.machines.boundaries)
            for (const auto& e : b.edges) inlets += e.type == "inlet" ? 1 : 0;
        std::size_t grains = scene.particles.size();
        fmt::print(
            "wrote {}: {} particle(s), {} block(s), {} wall(s), {} source(s), {} inlet edge(s), end time "
            "{} s, dt {} s\n",
            opt.out, grains, scene.blocks.size(), scene.walls.size(), scene.machines.sources.size(), inlets,
            scene.run.endTime, scene.dem.dt);
        fmt::print("check it with: granulab info {}\n", opt.out);
    }
    return kExitOk;
}

}  // namespace granulab::app
