// SPDX-License-Identifier: MIT
// The one table of contact-law keywords per axis (STYLE.md "Registration"): keyword, parameters
// with units, ranges and defaults, and the factory. Validation, `granulab help laws` and the
// docs all read this table.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/contact/laws.hpp"
#include "model/scene_def.hpp"

namespace granulab::dem {

enum class LawAxis { Normal, Damping, Tangential };

struct LawParamSpec {
    std::string key;
    std::string unit;
    Real min = 0;
    Real max = 1e300;
    bool minExclusive = false;
    std::optional<Real> defaultValue;  ///< nullopt: required (or derived, see defaultText)
    std::string defaultText;           ///< human-readable default, e.g. "2/7 kn"
    std::string doc;
    bool isBool = false;

    /// "(0, inf)" style description of the allowed range.
    std::string rangeText() const;
};

struct LawEntry {
    LawAxis axis;
    std::string keyword;
    std::string doc;
    std::vector<LawParamSpec> params;
};

/// All registered alternatives, in table order.
const std::vector<LawEntry>& lawRegistry();
/// Parameters valid for every law (e.g. clip_attraction).
const std::vector<LawParamSpec>& commonLawParams();
/// Keywords of one axis.
std::vector<std::string> lawKeywords(LawAxis axis);

/// Builds the law of one material pair; every problem goes to `diags` (the result is then
/// unusable but the scan continues so that all errors are reported together).
ContactLaw buildContactLaw(const model::ContactDef& def, const std::string& contextKey,
                           Diagnostics& diags);

}  // namespace granulab::dem
