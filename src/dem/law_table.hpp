// SPDX-License-Identifier: MIT
// Contact laws per material pair and their grouping into "forms" (same alternative on every
// axis), so that the force loop dispatches once per bucket of pairs (DESIGN.md "Contact laws").
#pragma once
#include <cstdint>
#include <vector>

#include "dem/contact/laws.hpp"

namespace granulab::dem {

class LawTable {
public:
    LawTable() = default;
    explicit LawTable(std::uint32_t materialCount);

    void set(std::uint32_t a, std::uint32_t b, const ContactLaw& law);
    bool has(std::uint32_t a, std::uint32_t b) const noexcept { return m_defined[index(a, b)]; }
    const ContactLaw& law(std::uint32_t a, std::uint32_t b) const noexcept { return m_laws[index(a, b)]; }
    /// Groups material pairs by form; call after the last set().
    void finalize();

    std::uint32_t materialCount() const noexcept { return m_n; }
    std::uint32_t formCount() const noexcept { return static_cast<std::uint32_t>(m_formRep.size()); }
    std::uint32_t formOf(std::uint32_t a, std::uint32_t b) const noexcept { return m_formOf[index(a, b)]; }
    /// A law with the form's alternatives (parameters of some member pair).
    const ContactLaw& formRepresentative(std::uint32_t form) const noexcept { return m_formRep[form]; }
    const std::vector<ContactLaw>& laws() const noexcept { return m_laws; }
    /// True if some material pair has rolling resistance (contacts then keep a rolling history).
    bool hasRolling() const noexcept { return m_hasRolling; }
    /// True if some material pair uses the gc2d overlap-area law (contacts then keep the old
    /// overlap area and a feature cache).
    bool hasArea() const noexcept { return m_hasArea; }

private:
    std::size_t index(std::uint32_t a, std::uint32_t b) const noexcept {
        return static_cast<std::size_t>(a) * m_n + b;
    }
    std::uint32_t m_n = 0;
    std::vector<ContactLaw> m_laws;
    std::vector<char> m_defined;
    std::vector<std::uint32_t> m_formOf;
    std::vector<ContactLaw> m_formRep;
    bool m_hasRolling = false;
    bool m_hasArea = false;
};

}  // namespace granulab::dem
