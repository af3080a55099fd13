// SPDX-License-Identifier: MIT
// Opening the flow fields of [fluid] (io/flow_fields.hpp; cfddem spec 5.5, Eq. 4.2).
#include "io/flow_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include "io/flow_field_reader.hpp"

namespace granulab::io {

fluid::InterpolatorOptions interpolatorOptions(const model::FluidDef& def) {
    fluid::InterpolatorOptions o;
    o.method = def.interpolation;
    o.outside = def.outside == "nearest" ? fluid::Outside::Nearest : fluid::Outside::Zero;
    o.shepardNodes = def.shepardNodes;
    o.shepardPower = def.shepardPower;
    o.keepPressure = def.pressureGradient;
    return o;
}

OpenedFields openFlowFields(const model::SceneDef& scene, Diagnostics& diags) {
    OpenedFields out;
    const model::FluidDef& def = scene.fluid;
    out.source.options = interpolatorOptions(def);
    out.source.interpolateInTime = def.timeInterpolation;
    out.source.uniformVelocity = def.velocity;
    out.timing = "uniform";
    if (!def.present || def.fields.empty()) return out;

    const std::filesystem::path sceneDir = std::filesystem::path(scene.path).parent_path();
    FieldReadOptions read;
    read.velocityArray = def.velocityArray;
    read.pressureArray = def.pressureArray;
    read.readPressure = def.pressureGradient;
    read.data = def.data;

    struct Entry {
        std::string path;
        Real time;
        SourceLoc loc;
    };
    std::vector<Entry> entries;
    const std::size_t errorsBefore = diags.list().size();
    for (std::size_t k = 0; k < def.fields.size(); ++k) {
        const SourceLoc& loc = k < def.fieldLocs.size() ? def.fieldLocs[k] : def.loc;
        std::filesystem::path p(def.fields[k]);
        if (p.is_relative()) p = sceneDir / p;
        try {
            for (const FieldFile& f : listFieldFiles(p.lexically_normal().string()))
                entries.push_back({f.path, f.time, loc});
        } catch (const std::exception& e) {
            diags.error(loc, "fluid.fields", e.what());
        }
    }
    if (diags.list().size() > errorsBefore) return out;
    if (entries.empty()) {
        diags.error(def.loc, "fluid.fields", "lists no field file");
        return out;
    }
    // Every file once: readable, the arrays there and finite, usable by the interpolation. Only one
    // field is in memory at a time; the run loads them again when they are due.
    for (std::size_t k = 0; k < entries.size(); ++k) {
        Entry& e = entries[k];
        if (k > 0 && def.check == "first" && !std::isnan(e.time)) {  // read when due (fluid.check)
            if (!std::filesystem::is_regular_file(e.path))
                diags.error(e.loc, "fluid.fields", fmt::format("{}: no such file", e.path));
            continue;
        }
        try {
            fluid::FlowField f = readFlowField(e.path, read);
            if (std::isnan(e.time)) e.time = f.time;
            auto check = std::make_shared<const fluid::FieldInterpolator>(std::move(f), out.source.options);
            if (k == 0) {
                out.nodes = check->nodes();
                out.method = check->methodName();
                out.first = check;
            }
        } catch (const std::invalid_argument& ex) {
            diags.error(e.loc, "fluid.fields", fmt::format("{}: {}", e.path, ex.what()));
        } catch (const std::exception& ex) {
            diags.error(e.loc, "fluid.fields", ex.what());
        }
    }
    if (diags.list().size() > errorsBefore) return out;

    const std::string paths0 = entries.front().path;
    const bool allTimed =
        std::none_of(entries.begin(), entries.end(), [](const Entry& e) { return std::isnan(e.time); });
    const bool even = def.timing == "even" || (def.timing == "auto" && !allTimed);
    if (def.timing == "file" && !allTimed) {
        const auto it =
            std::find_if(entries.begin(), entries.end(), [](const Entry& e) { return std::isnan(e.time); });
        diags.error(
            it->loc, "fluid.fields",
            fmt::format(
                "{} carries no time (no TimeValue, not in a .pvd or .series); fluid.timing = \"file\" "
                "needs one per file (or use timing = \"even\")",
                it->path));
        return out;
    }
    if (even) {  // cfddem Eq. 4.2: n files spread evenly over the run, file k once t > k t_end / n
        const Real n = static_cast<Real>(entries.size());
        for (std::size_t k = 0; k < entries.size(); ++k)
            entries[k].time = static_cast<Real>(k) * scene.run.endTime / n;
        out.source.afterTime = true;
        out.timing = "even";
    } else {
        std::stable_sort(entries.begin(), entries.end(),
                         [](const Entry& a, const Entry& b) { return a.time < b.time; });
        for (std::size_t k = 1; k < entries.size(); ++k)
            if (entries[k].time == entries[k - 1].time) {
                diags.error(entries[k].loc, "fluid.fields",
                            fmt::format("{} and {} carry the same time {} s", entries[k - 1].path,
                                        entries[k].path, entries[k].time));
                return out;
            }
        out.timing = "file";
    }
    if (paths0 != entries.front().path) {  // sorted by time: the field of t = 0 is another one
        try {
            out.first = std::make_shared<const fluid::FieldInterpolator>(
                readFlowField(entries.front().path, read), out.source.options);
        } catch (const std::exception& ex) {  // it was read without error a moment ago
            diags.error(entries.front().loc, "fluid.fields", ex.what());
        }
    }
    std::vector<std::string> paths;
    for (const Entry& e : entries) {
        out.source.times.push_back(e.time);
        paths.push_back(e.path);
    }
    out.files = paths;
    out.source.load = [paths, read](std::size_t k) { return readFlowField(paths.at(k), read); };
    return out;
}

}  // namespace granulab::io
