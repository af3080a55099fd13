// SPDX-License-Identifier: MIT
// Contact-law registry: generic machinery over the four axis variants of laws.hpp (adding an
// overlap-depth law does not touch this file; the pairing rule of the gc2d area family in
// buildContactLaw names the area laws).
#include "dem/contact/registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/suggest.hpp"

namespace granulab::dem {

std::string LawParamSpec::rangeText() const {
    if (isBool) return "true or false";
    const std::string lo = fmt::format("{}{}", minExclusive ? "(" : "[", min);
    const std::string hi = max >= kUnbounded ? "inf)" : fmt::format("{}{}", max, maxExclusive ? ")" : "]");
    return lo + ", " + hi;
}

namespace {

template <class Variant, std::size_t... I>
void appendEntries(std::vector<LawEntry>& out, std::index_sequence<I...>) {
    (out.push_back(
         {std::variant_alternative_t<I, Variant>::kAxis, std::variant_alternative_t<I, Variant>::kKeyword,
          std::variant_alternative_t<I, Variant>::kDoc, std::variant_alternative_t<I, Variant>::params()}),
     ...);
}

template <class Variant>
void appendEntries(std::vector<LawEntry>& out) {
    appendEntries<Variant>(out, std::make_index_sequence<std::variant_size_v<Variant>>{});
}

/// Constructs the alternative of `Variant` whose keyword matches; false if none does.
template <class Variant, std::size_t... I>
bool makeByKeyword(const std::string& keyword, const LawParams& p, Variant& out, std::index_sequence<I...>) {
    return ((keyword == std::variant_alternative_t<I, Variant>::kKeyword
                 ? (out = std::variant_alternative_t<I, Variant>::make(p), true)
                 : false) ||
            ...);
}

template <class Variant>
bool makeByKeyword(const std::string& keyword, const LawParams& p, Variant& out) {
    return makeByKeyword(keyword, p, out, std::make_index_sequence<std::variant_size_v<Variant>>{});
}

const LawEntry* findEntry(LawAxis axis, const std::string& keyword) {
    for (const auto& e : lawRegistry())
        if (e.axis == axis && e.keyword == keyword) return &e;
    return nullptr;
}

}  // namespace

const std::vector<LawEntry>& lawRegistry() {
    static const std::vector<LawEntry> table = [] {
        std::vector<LawEntry> t;
        appendEntries<NormalLaw>(t);
        appendEntries<DampingLaw>(t);
        appendEntries<TangentialLaw>(t);
        appendEntries<RollingLaw>(t);
        return t;
    }();
    return table;
}

const std::vector<LawParamSpec>& commonLawParams() {
    static const std::vector<LawParamSpec> common = commonLawParamSpecs();
    return common;
}

std::vector<std::string> lawKeywords(LawAxis axis) {
    std::vector<std::string> out;
    for (const auto& e : lawRegistry())
        if (e.axis == axis) out.push_back(e.keyword);
    return out;
}

const char* axisKey(LawAxis axis) noexcept {
    switch (axis) {
        case LawAxis::Normal:
            return "normal";
        case LawAxis::Damping:
            return "damping";
        case LawAxis::Tangential:
            return "tangential";
        case LawAxis::Rolling:
            return "rolling";
    }
    return "";
}

ContactLaw buildContactLaw(const model::ContactDef& def, const std::string& ctx, Diagnostics& diags,
                           const PairMaterials& materials) {
    const std::string* names[4] = {&def.normal, &def.damping, &def.tangential, &def.rolling};
    const LawAxis axes[4] = {LawAxis::Normal, LawAxis::Damping, LawAxis::Tangential, LawAxis::Rolling};
    std::vector<const LawParamSpec*> allowed;
    bool allKnown = true;
    for (int a = 0; a < 4; ++a) {
        const LawEntry* entry = findEntry(axes[a], *names[a]);
        if (!entry) {
            allKnown = false;
            const auto kws = lawKeywords(axes[a]);
            diags.error(def.loc, ctx + "." + axisKey(axes[a]),
                        fmt::format("unknown {} law '{}'{}; allowed: {}", axisKey(axes[a]), *names[a],
                                    didYouMean(*names[a], kws), joinList(kws)));
            continue;
        }
        for (const auto& p : entry->params) allowed.push_back(&p);
    }
    for (const auto& p : commonLawParams()) allowed.push_back(&p);

    // Unknown keys and range checks.
    std::vector<std::string> allowedNames;
    for (const auto* p : allowed) allowedNames.push_back(p->key);
    std::map<std::string, Real> values;
    for (const auto& [key, value] : def.params) {
        values[key] = value.value;
        const LawParamSpec* spec = nullptr;
        for (const auto* p : allowed)
            if (p->key == key) spec = p;
        if (!spec) {
            if (allKnown)
                diags.error(value.loc, ctx + "." + key,
                            fmt::format("key not used by laws {}/{}/{}/{}{}; allowed here: {}", def.normal,
                                        def.damping, def.tangential, def.rolling,
                                        didYouMean(key, allowedNames), joinList(allowedNames)));
            continue;
        }
        if (spec->isBool != value.isBool) {
            diags.error(value.loc, ctx + "." + key,
                        fmt::format("{} expects {}", key,
                                    spec->isBool ? "true or false" : "a number [" + spec->unit + "]"));
            continue;
        }
        const Real v = value.value;
        const bool below = spec->minExclusive ? !(v > spec->min) : !(v >= spec->min);
        const bool above = spec->maxExclusive ? !(v < spec->max) : v > spec->max;
        if (!std::isfinite(v) || below || above)
            diags.error(value.loc, ctx + "." + key,
                        fmt::format("{} = {} is out of range; allowed {} [{}]", key, v, spec->rangeText(),
                                    spec->unit));
    }

    // The gc2d area family (normal "area" or "area_potential", damping "gamma", tangential "gc2d")
    // has its own kernel and is not combined with the overlap-depth laws.
    if (allKnown) {
        const bool area = def.normal == AreaNormal::kKeyword || def.normal == AreaPotentialNormal::kKeyword;
        const bool dampingOk =
            area ? (def.damping == NoDamping::kKeyword || def.damping == AreaDamping::kKeyword)
                 : def.damping != AreaDamping::kKeyword;
        const bool tangentialOk =
            area ? (def.tangential == NoFriction::kKeyword || def.tangential == AreaFriction::kKeyword)
                 : def.tangential != AreaFriction::kKeyword;
        constexpr const char* kFamily = "normal = \"area\" or \"area_potential\" (overlap-area laws)";
        if (!dampingOk)
            diags.error(def.loc, ctx + ".damping",
                        area ? fmt::format("normal = \"{}\" takes damping \"none\" or \"gamma\", got '{}'",
                                           def.normal, def.damping)
                             : fmt::format("damping = \"gamma\" belongs to {}", kFamily));
        if (!tangentialOk)
            diags.error(def.loc, ctx + ".tangential",
                        area ? fmt::format("normal = \"{}\" takes tangential \"none\" or \"gc2d\", got '{}'",
                                           def.normal, def.tangential)
                             : fmt::format("tangential = \"gc2d\" belongs to {}", kFamily));
        if (area && def.rolling != NoRolling::kKeyword)
            diags.error(def.loc, ctx + ".rolling",
                        fmt::format("normal = \"{}\" has no rolling resistance law (polygons roll on their "
                                    "corners)",
                                    def.normal));
    }

    ContactLaw law;
    const LawParams params(values, {def.normal, def.damping, def.tangential, def.rolling}, materials);
    makeByKeyword(def.normal, params, law.normal);
    makeByKeyword(def.damping, params, law.damping);
    makeByKeyword(def.tangential, params, law.tangential);
    makeByKeyword(def.rolling, params, law.rolling);
    law.clipAttraction = params.getOr("clip_attraction", 0.0) != 0.0;
    for (const auto& key : params.missing())
        for (const auto* p : allowed)
            if (p->key == key)
                diags.error(def.loc, ctx + "." + key,
                            fmt::format("missing required parameter '{}' ({}), allowed {} [{}]", key, p->doc,
                                        p->rangeText(), p->unit));
    for (const auto& [key, message] : params.failures()) diags.error(def.loc, ctx + "." + key, message);
    std::vector<std::string> seen;
    for (const auto& name : params.materialsMissingModulus()) {
        if (std::find(seen.begin(), seen.end(), name) != seen.end()) continue;
        seen.push_back(name);
        diags.error(
            def.loc, ctx,
            fmt::format("laws {}/{}/{} need the elastic constants of material '{}': set its youngs_modulus "
                        "[Pa] in (0, inf) and poisson in [0, 0.5)",
                        def.normal, def.damping, def.tangential, name));
    }
    return law;
}

}  // namespace granulab::dem
