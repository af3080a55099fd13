// SPDX-License-Identifier: MIT
// Contact-law axes as small stateless structs (DESIGN.md "Contact laws", STYLE.md (b)).
// Each axis alternative holds its parameters and one noexcept function; the kernel in
// dem/contact/kernel.hpp combines one alternative per axis. To add a law: add its struct here,
// its alternative to the axis variant, and its row in dem/contact/registry.cpp.
#pragma once
#include <cmath>
#include <variant>

#include "core/types.hpp"

namespace granulab::dem {

// ---------------------------------------------------------------- normal spring
/// Linear (Hooke) spring: F = kn * delta. kn [N/m].
struct HookeNormal {
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
    Real coefficient(Real /*meff*/, Real /*stiffness*/) const noexcept { return 0; }
};

/// Constant coefficient: c = cn [N s/m].
struct ViscousDamping {
    Real cn = 0;
    Real coefficient(Real /*meff*/, Real /*stiffness*/) const noexcept { return cn; }
};

/// From a restitution coefficient e: c = 2 beta sqrt(meff kn), beta = -ln e / sqrt(pi^2 + ln^2 e).
/// Exact for the linear spring without attraction clipping (docs/physics/contact-laws.md).
struct RestitutionDamping {
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
    Real gammaN = 0;
    Real coefficient(Real meff, Real /*stiffness*/) const noexcept { return meff * gammaN; }
};

using DampingLaw = std::variant<NoDamping, ViscousDamping, RestitutionDamping, MassScaledDamping>;

// ---------------------------------------------------------------- tangential
/// Frictionless contact.
struct NoFriction {};

/// Cundall-Strack spring with Coulomb cap (Cundall & Strack 1979): the tangential displacement
/// xi [m] is kept in the current tangent direction (a scalar in 2D, so rotation of the contact
/// keeps its magnitude). F_t = -(kt xi + c_t v_t), |F_t| <= mu |F_n|; when capped, xi is reset
/// to the value that gives exactly the capped force (LAMMPS convention).
/// c_t = ct + meff * gammaT.
struct CundallStrack {
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

}  // namespace granulab::dem
