// SPDX-License-Identifier: MIT
// Contact laws, decomposed by axis (DESIGN.md "Contact laws", STYLE.md (b)): each alternative is
// a small stateless struct with its parameters, one noexcept function, and its registration
// (keyword, documentation, parameter table with units, ranges and defaults, factory).
//
// TO ADD A LAW, EDIT ONLY THIS FILE: write its struct with the static members below and append
// it to the variant of its axis. The registry (registry.cpp), validation, `granulab help laws`
// and the force kernels pick it up from the variant.
#pragma once
#include <cmath>
#include <variant>
#include <vector>

#include "core/types.hpp"
#include "dem/contact/law_params.hpp"

namespace granulab::dem {

// ---------------------------------------------------------------- normal spring
/// Linear (Hooke) spring: F = kn * delta. kn [N/m].
struct HookeNormal {
    static constexpr LawAxis kAxis = LawAxis::Normal;
    static constexpr const char* kKeyword = "hooke";
    static constexpr const char* kDoc = "linear spring F_n = kn * delta";
    static std::vector<LawParamSpec> params() {
        return {lawParam("kn", "N/m", 0, kUnbounded, true, "required", "normal spring stiffness")};
    }
    static HookeNormal make(const LawParams& p) { return {p.require("kn")}; }

    Real kn = 0;
    Real force(Real overlap) const noexcept { return kn * overlap; }
    /// Secant stiffness F/delta [N/m], used by damping laws scaled with stiffness.
    Real stiffness(Real /*overlap*/) const noexcept { return kn; }
    /// Stored elastic energy [J].
    Real energy(Real overlap) const noexcept { return 0.5 * kn * overlap * overlap; }
};

using NormalLaw = std::variant<HookeNormal>;

// ---------------------------------------------------------------- normal damping
// Each returns the normal damping coefficient c [N s/m]; the damping force is c * v_n.

struct NoDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "none";
    static constexpr const char* kDoc = "no normal damping (elastic)";
    static std::vector<LawParamSpec> params() { return {}; }
    static NoDamping make(const LawParams&) { return {}; }

    Real coefficient(Real /*meff*/, Real /*stiffness*/) const noexcept { return 0; }
};

/// Constant coefficient: c = cn [N s/m].
struct ViscousDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "coefficient";
    static constexpr const char* kDoc = "viscous normal damping F = cn * v_n";
    static std::vector<LawParamSpec> params() {
        return {lawParam("cn", "N s/m", 0, kUnbounded, false, "required", "damping coefficient")};
    }
    static ViscousDamping make(const LawParams& p) { return {p.require("cn")}; }

    Real cn = 0;
    Real coefficient(Real /*meff*/, Real /*stiffness*/) const noexcept { return cn; }
};

/// From a restitution coefficient e: c = 2 beta sqrt(meff kn), beta = -ln e / sqrt(pi^2 + ln^2 e).
/// Exact for the linear spring without attraction clipping (docs/physics/contact-laws.md).
struct RestitutionDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "restitution";
    static constexpr const char* kDoc =
        "damping from the normal restitution coefficient e (exact for hooke without clipping)";
    static std::vector<LawParamSpec> params() {
        return {lawParam("e", "-", 0, 1, false, "required", "normal restitution coefficient")};
    }
    static RestitutionDamping make(const LawParams& p) { return {betaFromRestitution(p.require("e"))}; }

    Real beta = 0;  ///< damping ratio derived from e, in [0, 1]
    Real coefficient(Real meff, Real stiffness) const noexcept {
        return 2.0 * beta * std::sqrt(meff * stiffness);
    }
    static Real betaFromRestitution(Real e) noexcept {
        if (e <= 0) return 1.0;
        const Real l = std::log(e);
        return -l / std::sqrt(kPi * kPi + l * l);
    }
};

/// LAMMPS gran/hooke/history convention: c = meff * gamma_n, gamma_n [1/s].
struct MassScaledDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "lammps";
    static constexpr const char* kDoc = "mass-scaled damping F = meff * gamma_n * v_n (LAMMPS gran/hooke/history)";
    static std::vector<LawParamSpec> params() {
        return {lawParam("gamma_n", "1/s", 0, kUnbounded, false, "required", "normal damping rate")};
    }
    static MassScaledDamping make(const LawParams& p) { return {p.require("gamma_n")}; }

    Real gammaN = 0;
    Real coefficient(Real meff, Real /*stiffness*/) const noexcept { return meff * gammaN; }
};

using DampingLaw = std::variant<NoDamping, ViscousDamping, RestitutionDamping, MassScaledDamping>;

// ---------------------------------------------------------------- tangential
/// Frictionless contact.
struct NoFriction {
    static constexpr LawAxis kAxis = LawAxis::Tangential;
    static constexpr const char* kKeyword = "none";
    static constexpr const char* kDoc = "frictionless";
    static std::vector<LawParamSpec> params() { return {}; }
    static NoFriction make(const LawParams&) { return {}; }
};

/// Cundall-Strack spring with Coulomb cap (Cundall & Strack 1979): the tangential displacement
/// xi [m] is kept in the current tangent direction (a scalar in 2D, so rotation of the contact
/// keeps its magnitude). F_t = -(kt xi + c_t v_t), |F_t| <= mu |F_n|; when capped, xi is reset
/// to the value that gives exactly the capped force (LAMMPS convention).
/// c_t = ct + meff * gammaT.
struct CundallStrack {
    static constexpr LawAxis kAxis = LawAxis::Tangential;
    static constexpr const char* kKeyword = "cundall_strack";
    static constexpr const char* kDoc = "tangential spring with history, viscous term and Coulomb cap mu * |F_n|";
    static std::vector<LawParamSpec> params() {
        return {lawParam("mu", "-", 0, kUnbounded, false, "required", "friction coefficient"),
                lawParam("kt", "N/m", 0, kUnbounded, false, "2/7 kn", "tangential stiffness"),
                lawParam("ct", "N s/m", 0, kUnbounded, false, "0", "constant tangential damping"),
                lawParam("gamma_t", "1/s", 0, kUnbounded, false, "gamma_n/2 with damping = \"lammps\", else 0",
                         "mass-scaled tangential damping (c_t += meff * gamma_t)")};
    }
    static CundallStrack make(const LawParams& p) {
        CundallStrack cs;
        cs.mu = p.require("mu");
        cs.kt = p.getOr("kt", 2.0 / 7.0 * p.getOr("kn", 0.0));
        cs.ct = p.getOr("ct", 0.0);
        cs.gammaT = p.getOr("gamma_t", p.uses(MassScaledDamping::kKeyword) ? 0.5 * p.getOr("gamma_n", 0.0) : 0.0);
        return cs;
    }

    Real kt = 0;      ///< [N/m]
    Real ct = 0;      ///< [N s/m] constant tangential damping
    Real gammaT = 0;  ///< [1/s] mass-scaled tangential damping
    Real mu = 0;      ///< Coulomb friction coefficient
};

using TangentialLaw = std::variant<NoFriction, CundallStrack>;

/// One resolved contact law for a pair of materials.
struct ContactLaw {
    NormalLaw normal;
    DampingLaw damping;
    TangentialLaw tangential;
    bool clipAttraction = false;  ///< clip the normal force at zero (never attractive)
};

/// Parameters valid for every law.
inline std::vector<LawParamSpec> commonLawParamSpecs() {
    LawParamSpec clip = lawParam("clip_attraction", "-", 0, 1, false, "false",
                                 "clip the normal force at zero so the contact never attracts");
    clip.isBool = true;
    return {clip};
}

}  // namespace granulab::dem
