// SPDX-License-Identifier: MIT
// The table of contact-law keywords per axis (STYLE.md "Registration"), generated from the axis
// variants of dem/contact/laws.hpp: keyword, parameters with units, ranges and defaults, and the
// factory. Validation, `granulab help laws` and the docs all read this table.
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/contact/law_params.hpp"
#include "dem/contact/laws.hpp"
#include "model/scene_def.hpp"

namespace granulab::dem {

struct LawEntry {
    LawAxis axis;
    std::string keyword;
    std::string doc;
    std::vector<LawParamSpec> params;
};

/// All registered alternatives, in variant order (normal, damping, tangential, rolling).
const std::vector<LawEntry>& lawRegistry();
/// Parameters valid for every law (e.g. clip_attraction).
const std::vector<LawParamSpec>& commonLawParams();
/// Keywords of one axis.
std::vector<std::string> lawKeywords(LawAxis axis);
/// "normal", "damping", "tangential" or "rolling" (the [[contact]] key that selects the axis law).
const char* axisKey(LawAxis axis) noexcept;

/// Builds the law of one material pair; every problem goes to `diags` (the result is then
/// unusable but the scan continues so that all errors are reported together).
ContactLaw buildContactLaw(const model::ContactDef& def, const std::string& contextKey, Diagnostics& diags,
                           const PairMaterials& materials);

}  // namespace granulab::dem
