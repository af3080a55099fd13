// SPDX-License-Identifier: MIT
// LawTable: symmetric material-pair table and form grouping.
#include "dem/law_table.hpp"

#include <array>

namespace granulab::dem {

LawTable::LawTable(std::uint32_t materialCount)
    : m_n(materialCount),
      m_laws(static_cast<std::size_t>(materialCount) * materialCount),
      m_defined(m_laws.size(), 0),
      m_formOf(m_laws.size(), 0) {}

void LawTable::set(std::uint32_t a, std::uint32_t b, const ContactLaw& law) {
    m_laws[index(a, b)] = law;
    m_laws[index(b, a)] = law;
    m_defined[index(a, b)] = 1;
    m_defined[index(b, a)] = 1;
}

void LawTable::finalize() {
    m_formRep.clear();
    m_hasRolling = false;
    m_hasArea = false;
    for (const auto& l : m_laws) {
        m_hasRolling = m_hasRolling || rollingSettings(l.rolling).enabled;
        m_hasArea = m_hasArea || areaModulus(l.normal) != nullptr;
    }
    std::vector<std::array<std::size_t, 3>> signatures;
    for (std::size_t k = 0; k < m_laws.size(); ++k) {
        const auto& l = m_laws[k];
        const std::array<std::size_t, 3> sig{l.normal.index(), l.damping.index(), l.tangential.index()};
        std::size_t form = signatures.size();
        for (std::size_t f = 0; f < signatures.size(); ++f)
            if (signatures[f] == sig) form = f;
        if (form == signatures.size()) {
            signatures.push_back(sig);
            m_formRep.push_back(l);
        }
        m_formOf[k] = static_cast<std::uint32_t>(form);
    }
}

}  // namespace granulab::dem
