// SPDX-License-Identifier: MIT
// The analyses of a dem run by name (gc2d spec section 7; docs/analysis.md): the one list that
// `granulab analyze DIR [what...]` (app/dem/dem_analyze.cpp) runs and that the scene key
// `output.analyses` (in-run, at every snapshot; io/scene_reader.cpp) is checked against.
#pragma once
#include <string_view>

namespace granulab::analysis {

struct DemAnalysisInfo {
    const char* name;
    const char* what;
    bool defaultSet;        ///< run by `granulab analyze` when no analysis is named
    bool needsContacts;     ///< reads the snapshot's contact file (output.contacts = true)
    const char* needsFlag;  ///< a command-line option it cannot run without (nullptr: none), so
                            ///< not available in-run
};

/// In the order they run.
inline constexpr DemAnalysisInfo kDemAnalyses[] = {
    {"pressure", "mean pressure on every wall and the floor's profile p(x) (Eq. 2.36-2.40)", true, true,
     nullptr},
    {"forces", "force directions P(alpha) and magnitudes P(F/<F>) (spec 7.3)", true, true, nullptr},
    {"coordination", "contacts per grain, P(K), rattlers (spec 7.4)", true, true, nullptr},
    {"repose", "angle of repose: top-centroid fit and integral 2a/b^2 (spec 7.5)", true, false, nullptr},
    {"packing", "local packing fraction with the hull correction (Eq. 2.44/2.45)", true, false, nullptr},
    {"stress", "stress tensors on test areas, principal axes, Psi (Eq. 2.52)", true, true, nullptr},
    {"coarse", "kernel coarse-grained density, velocity and stress fields", false, true, nullptr},
    {"janssen", "silo depth profiles and the Janssen fit of k and mu_j (spec 8.3; needs --silo)", false, true,
     "--silo"},
    {"strain", "displacement, strain, nu, E, K against --reference (Eq. 4.2-4.5, 4.11)", false, false,
     "--reference"},
    {"persistence", "contacts of --reference still present (spec 7.11)", false, true, "--reference"},
    {"roughness", "surface-roughness power spectrum of the flanks or --range (spec 7.11)", false, false,
     nullptr},
};

/// The entry of `name`, or nullptr.
constexpr const DemAnalysisInfo* findDemAnalysis(std::string_view name) {
    for (const auto& a : kDemAnalyses)
        if (name == a.name) return &a;
    return nullptr;
}

}  // namespace granulab::analysis
