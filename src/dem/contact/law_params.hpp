// SPDX-License-Identifier: MIT
// Parameter descriptions and values of contact laws: each law in dem/contact/laws.hpp declares
// its parameters (unit, range, default) with these types, and reads its values from LawParams.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace granulab::dem {

enum class LawAxis { Normal, Damping, Tangential, Rolling };

inline constexpr Real kUnbounded = 1e300;

/// One parameter of a law: documentation and allowed range.
struct LawParamSpec {
    std::string key;
    std::string unit;
    Real min = 0;
    Real max = kUnbounded;
    bool minExclusive = false;
    bool maxExclusive = false;
    std::string defaultText;  ///< "required", a number, or how it is derived ("2/7 kn")
    std::string doc;
    bool isBool = false;

    bool required() const { return defaultText == "required"; }
    /// "(0, inf)" style description of the allowed range.
    std::string rangeText() const;
};

/// Elastic constants of the two materials of a contact (0 where a material does not set them).
struct PairMaterials {
    std::string nameA, nameB;
    Real youngsA = 0, youngsB = 0;  ///< [Pa]
    Real poissonA = 0, poissonB = 0;
};

/// The values a user gave for one [[contact]] entry (all axes together, so a law may derive a
/// default from another axis, e.g. kt = 2/7 kn), and the materials of the pair it is built for.
/// Required values that are missing are recorded.
class LawParams {
public:
    LawParams(std::map<std::string, Real> values, std::vector<std::string> axisKeywords,
              PairMaterials materials = {})
        : m_values(std::move(values)),
          m_keywords(std::move(axisKeywords)),
          m_materials(std::move(materials)) {}

    const PairMaterials& materials() const noexcept { return m_materials; }
    /// Effective modulus E* = ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b)^-1 [Pa] (cfddem Eq. 3.32); records
    /// which material lacks youngs_modulus.
    Real effectiveModulus() const {
        const auto& m = m_materials;
        if (!(m.youngsA > 0)) m_missingMaterial.push_back(m.nameA);
        if (!(m.youngsB > 0)) m_missingMaterial.push_back(m.nameB);
        if (!(m.youngsA > 0) || !(m.youngsB > 0)) return 0;
        return 1.0 / ((1 - m.poissonA * m.poissonA) / m.youngsA + (1 - m.poissonB * m.poissonB) / m.youngsB);
    }
    /// Materials that a law needed youngs_modulus from but that do not set it.
    const std::vector<std::string>& materialsMissingModulus() const noexcept { return m_missingMaterial; }

    std::optional<Real> get(const std::string& key) const {
        const auto it = m_values.find(key);
        if (it == m_values.end()) return std::nullopt;
        return it->second;
    }
    Real getOr(const std::string& key, Real fallback) const { return get(key).value_or(fallback); }
    /// The value, or 0 with the key recorded as missing.
    Real require(const std::string& key) const {
        if (auto v = get(key)) return *v;
        m_missing.push_back(key);
        return 0;
    }
    /// True if the law of some axis has this keyword (e.g. damping "lammps").
    bool uses(const std::string& keyword) const {
        for (const auto& k : m_keywords)
            if (k == keyword) return true;
        return false;
    }
    const std::vector<std::string>& missing() const noexcept { return m_missing; }
    /// A law reports a value it cannot realise (key, message).
    void fail(std::string key, std::string message) const {
        m_failures.push_back({std::move(key), std::move(message)});
    }
    const std::vector<std::pair<std::string, std::string>>& failures() const noexcept { return m_failures; }

private:
    std::map<std::string, Real> m_values;
    std::vector<std::string> m_keywords;
    PairMaterials m_materials;
    mutable std::vector<std::string> m_missing;
    mutable std::vector<std::string> m_missingMaterial;
    mutable std::vector<std::pair<std::string, std::string>> m_failures;
};

/// Shorthand used by the law tables.
inline LawParamSpec lawParam(std::string key, std::string unit, Real min, Real max, bool minExclusive,
                             std::string defaultText, std::string doc) {
    LawParamSpec p;
    p.key = std::move(key);
    p.unit = std::move(unit);
    p.min = min;
    p.max = max;
    p.minExclusive = minExclusive;
    p.defaultText = std::move(defaultText);
    p.doc = std::move(doc);
    return p;
}

}  // namespace granulab::dem
