// SPDX-License-Identifier: MIT
// The edmd engine's section [edmd] (io/edmd_sections.hpp; docs/scene-format.md "[edmd]").
// Syntax, type and unknown-key errors only; io/validate_edmd.hpp checks ranges and consistency.
#include "io/edmd_sections.hpp"

#include "io/toml_table_reader.hpp"

namespace granulab::io {

namespace {

/// A per-axis array of 2 or 3 numbers (2D or 3D; the dimension is checked in validation).
void readAxisNumbers(TableReader& r, const std::string& key, std::vector<Real>& out,
                     const std::string& what) {
    const toml::node* n = r.node(key);
    if (!n) return;
    const auto* a = n->as_array();
    const std::size_t count = a ? a->size() : 0;
    if (count != 2 && count != 3)
        r.diags().error(locOf(*n, r.file()), r.keyPath(key), "expected an array of 2 or 3 " + what);
    else
        r.numbers(key, out, count);
}

void readEdmd(TableReader& r, model::EdmdDef& e) {
    e.loc = r.loc();
    readAxisNumbers(r, "box", e.box, "edge lengths [m]");
    if (const toml::node* n = r.node("periodic")) {
        const auto* a = n->as_array();
        bool ok = a && (a->size() == 2 || a->size() == 3);
        if (ok)
            for (const auto& v : *a) {
                if (!v.is_boolean())
                    ok = false;
                else
                    e.periodic.push_back(v.value<bool>().value_or(true));
            }
        if (!ok)
            r.diags().error(locOf(*n, r.file()), r.keyPath("periodic"),
                            "expected an array of 2 or 3 booleans, one per axis");
    }
    r.integer("count", e.count);
    r.number("volume_fraction", e.volumeFraction);
    r.number("radius", e.radius);
    r.number("radius_max", e.radiusMax);
    r.number("mass", e.mass);
    r.choice("placement", e.placement, {"lattice", "random"});
    r.number("temperature", e.temperature);
    r.number("equilibrate", e.equilibrate);
    r.number("restitution", e.restitution);
    r.choice("restitution_model", e.restitutionModel, {"constant", "mcnamara_falcon", "viscoelastic"});
    r.number("restitution_speed", e.restitutionSpeed);
    r.number("wall_restitution", e.wallRestitution);
    r.number("tangential_restitution", e.tangentialRestitution);
    r.number("inertia_factor", e.inertiaFactor);
    r.number("tc", e.tc);
    readAxisNumbers(r, "gravity", e.gravity, "components [m/s^2]");
    r.number("growth_rate", e.growthRate);
    r.number("cell_size", e.cellSize);
    r.number("cells_per_particle", e.cellsPerParticle);
    r.choice("cell_grid", e.cellGrid, {"auto", "morton", "free"});
    r.choice("queue", e.queue, {"calendar", "heap", "tree"});
    r.number("end_tau", e.endTau);
    r.number("end_collisions", e.endCollisions);
    r.choice("series", e.series, {"linear", "log"});
    r.integer("series_points", e.seriesPoints);
    r.number("series_first", e.seriesFirst);
    r.boolean("clusters", e.clusters);
    r.number("cluster_delta", e.clusterDelta);
    r.boolean("analysis_files", e.analysisFiles);
}

void readEdmdSections(TableReader& root, model::SceneDef& scene) {
    withTable(root, "edmd", [&](TableReader& t) { readEdmd(t, scene.edmd); });
}

}  // namespace

SceneSections edmdSceneSections() {
    SceneSections s;
    s.engine = "edmd";
    s.sections = {"edmd"};
    s.required = "edmd";
    s.requiredHint = "the event-driven gas: count or volume_fraction, radius";
    s.needsEndTime = false;  // or edmd.end_tau / edmd.end_collisions (checked by validateEdmd)
    s.read = &readEdmdSections;
    return s;
}

}  // namespace granulab::io
