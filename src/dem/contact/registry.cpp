// SPDX-License-Identifier: MIT
// Contact-law registry: to add a law, edit only this file (plus its struct in laws.hpp).
#include "dem/contact/registry.hpp"

#include <cmath>
#include <fmt/format.h>
#include <set>

#include "core/suggest.hpp"

namespace granulab::dem {

namespace {
constexpr Real kInf = 1e300;

LawParamSpec param(std::string key, std::string unit, Real min, Real max, bool minExclusive,
                   std::optional<Real> def, std::string defText, std::string doc) {
    LawParamSpec p;
    p.key = std::move(key);
    p.unit = std::move(unit);
    p.min = min;
    p.max = max;
    p.minExclusive = minExclusive;
    p.defaultValue = def;
    p.defaultText = std::move(defText);
    p.doc = std::move(doc);
    return p;
}
}  // namespace

std::string LawParamSpec::rangeText() const {
    if (isBool) return "true or false";
    const std::string lo = fmt::format("{}{}", minExclusive ? "(" : "[", min);
    const std::string hi = max >= kInf ? "inf)" : fmt::format("{}]", max);
    return lo + ", " + hi;
}

const std::vector<LawEntry>& lawRegistry() {
    static const std::vector<LawEntry> table = {
        {LawAxis::Normal, "hooke", "linear spring F_n = kn * delta",
         {param("kn", "N/m", 0, kInf, true, std::nullopt, "required", "normal spring stiffness")}},
        {LawAxis::Damping, "none", "no normal damping (elastic)", {}},
        {LawAxis::Damping, "coefficient", "viscous normal damping F = cn * v_n",
         {param("cn", "N s/m", 0, kInf, false, std::nullopt, "required", "damping coefficient")}},
        {LawAxis::Damping, "restitution",
         "damping from the normal restitution coefficient e (exact for hooke without clipping)",
         {param("e", "-", 0, 1, false, std::nullopt, "required", "normal restitution coefficient")}},
        {LawAxis::Damping, "lammps",
         "mass-scaled damping F = meff * gamma_n * v_n (LAMMPS gran/hooke/history)",
         {param("gamma_n", "1/s", 0, kInf, false, std::nullopt, "required",
                "normal damping rate")}},
        {LawAxis::Tangential, "none", "frictionless", {}},
        {LawAxis::Tangential, "cundall_strack",
         "tangential spring with history, viscous term and Coulomb cap mu * |F_n|",
         {param("mu", "-", 0, kInf, false, std::nullopt, "required", "friction coefficient"),
          param("kt", "N/m", 0, kInf, false, std::nullopt, "2/7 kn", "tangential stiffness"),
          param("ct", "N s/m", 0, kInf, false, 0.0, "0", "constant tangential damping"),
          param("gamma_t", "1/s", 0, kInf, false, std::nullopt,
                "gamma_n/2 with damping = \"lammps\", else 0",
                "mass-scaled tangential damping (c_t += meff * gamma_t)")}},
    };
    return table;
}

const std::vector<LawParamSpec>& commonLawParams() {
    static const std::vector<LawParamSpec> common = [] {
        LawParamSpec clip = param("clip_attraction", "-", 0, 1, false, 0.0, "false",
                                  "clip the normal force at zero so the contact never attracts");
        clip.isBool = true;
        return std::vector<LawParamSpec>{clip};
    }();
    return common;
}

std::vector<std::string> lawKeywords(LawAxis axis) {
    std::vector<std::string> out;
    for (const auto& e : lawRegistry())
        if (e.axis == axis) out.push_back(e.keyword);
    return out;
}

namespace {
const char* axisKey(LawAxis axis) {
    switch (axis) {
        case LawAxis::Normal: return "normal";
        case LawAxis::Damping: return "damping";
        case LawAxis::Tangential: return "tangential";
    }
    return "";
}

const LawEntry* findEntry(LawAxis axis, const std::string& keyword) {
    for (const auto& e : lawRegistry())
        if (e.axis == axis && e.keyword == keyword) return &e;
    return nullptr;
}
}  // namespace

ContactLaw buildContactLaw(const model::ContactDef& def, const std::string& ctx, Diagnostics& diags) {
    ContactLaw law;
    const std::string* names[3] = {&def.normal, &def.damping, &def.tangential};
    const LawAxis axes[3] = {LawAxis::Normal, LawAxis::Damping, LawAxis::Tangential};
    std::vector<const LawParamSpec*> allowed;
    const LawEntry* entries[3] = {nullptr, nullptr, nullptr};
    for (int a = 0; a < 3; ++a) {
        entries[a] = findEntry(axes[a], *names[a]);
        if (!entries[a]) {
            const auto kws = lawKeywords(axes[a]);
            diags.error(def.loc, ctx + "." + axisKey(axes[a]),
                        fmt::format("unknown {} law '{}'{}; allowed: {}", axisKey(axes[a]), *names[a],
                                    didYouMean(*names[a], kws), joinList(kws)));
            continue;
        }
        for (const auto& p : entries[a]->params) allowed.push_back(&p);
    }
    for (const auto& p : commonLawParams()) allowed.push_back(&p);

    // Unknown keys and range checks.
    std::vector<std::string> allowedNames;
    for (const auto* p : allowed) allowedNames.push_back(p->key);
    for (const auto& [key, value] : def.params) {
        const LawParamSpec* spec = nullptr;
        for (const auto* p : allowed)
            if (p->key == key) spec = p;
        if (!spec) {
            diags.error(value.loc, ctx + "." + key,
                        fmt::format("key not used by laws {}/{}/{}{}; allowed here: {}", def.normal,
                                    def.damping, def.tangential, didYouMean(key, allowedNames),
                                    joinList(allowedNames)));
            continue;
        }
        const Real v = value.value;
        const bool below = spec->minExclusive ? !(v > spec->min) : !(v >= spec->min);
        if (!std::isfinite(v) || below || v > spec->max) {
            diags.error(value.loc, ctx + "." + key,
                        fmt::format("{} = {} is out of range; allowed {} [{}]", key, v,
                                    spec->rangeText(), spec->unit));
        }
    }
    auto get = [&](const std::string& key) -> std::optional<Real> {
        auto it = def.params.find(key);
        if (it == def.params.end()) return std::nullopt;
        return it->second.value;
    };
    auto require = [&](const std::string& key) -> Real {
        auto v = get(key);
        if (!v) {
            for (const auto* p : allowed)
                if (p->key == key)
                    diags.error(def.loc, ctx + "." + key,
                                fmt::format("missing required parameter '{}' ({}), allowed {} [{}]",
                                            key, p->doc, p->rangeText(), p->unit));
            return 0;
        }
        return *v;
    };

    Real kn = 0;
    if (entries[0] && entries[0]->keyword == "hooke") {
        kn = require("kn");
        law.normal = HookeNormal{kn};
    }
    Real gammaN = 0;
    if (entries[1]) {
        const auto& kw = entries[1]->keyword;
        if (kw == "none") law.damping = NoDamping{};
        else if (kw == "coefficient") law.damping = ViscousDamping{require("cn")};
        else if (kw == "restitution")
            law.damping = RestitutionDamping{RestitutionDamping::betaFromRestitution(require("e"))};
        else if (kw == "lammps") {
            gammaN = require("gamma_n");
            law.damping = MassScaledDamping{gammaN};
        }
    }
    if (entries[2]) {
        const auto& kw = entries[2]->keyword;
        if (kw == "none") law.tangential = NoFriction{};
        else if (kw == "cundall_strack") {
            CundallStrack cs;
            cs.mu = require("mu");
            cs.kt = get("kt").value_or(2.0 / 7.0 * kn);
            cs.ct = get("ct").value_or(0.0);
            const bool lammpsDamping = entries[1] && entries[1]->keyword == "lammps";
            cs.gammaT = get("gamma_t").value_or(lammpsDamping ? 0.5 * gammaN : 0.0);
            law.tangential = cs;
        }
    }
    law.clipAttraction = get("clip_attraction").value_or(0.0) != 0.0;
    return law;
}

}  // namespace granulab::dem
