// SPDX-License-Identifier: MIT
// The per-contact force evaluation, fixed order normal -> damping -> cap -> tangential
// (STYLE.md (b), LAMMPS GranularModel order). Template over one alternative per axis, so the
// hot loop has no dispatch; dem/forces_detail.hpp (forEachBucket) visits once per bucket of pairs.
#pragma once
#include <cmath>

#include "dem/contact/laws.hpp"

namespace granulab::dem {

/// Force magnitudes: fn > 0 is repulsive; ft is along t, acting on the first body.
struct ContactForce {
    Real fn;
    Real ft;
    Real rollingTorque;  ///< [N m] on the first body (the second gets the opposite)
};

template <class Normal, class Damping, class Tangential>
struct ResolvedLaw {
    Normal normal;
    Damping damping;
    Tangential tangential;
    bool clipAttraction;
    RollingSettings rolling;
};

/// Evaluates one contact; ioXi (tangential spring [m]) and ioZeta (rolling displacement [m]) are
/// the contact's history, updated in place.
/// kRolling = false compiles the rolling-resistance branch out (no rolling law in the scene).
template <class Normal, class Damping, class Tangential, bool kRolling = true>
[[gnu::always_inline]] inline ContactForce evaluateContact(
    const ResolvedLaw<Normal, Damping, Tangential>& law, const ContactKinematics& k, Real& ioXi,
    Real& ioZeta) noexcept {
    const Real kn = law.normal.stiffness(k.overlap, k.reff);
    const Real cn = law.damping.coefficient(k.meff, kn);
    Real fn = law.normal.force(k.overlap, k.reff) + cn * k.vn;
    if (law.clipAttraction && fn < 0) fn = 0;
    const Real ft = law.tangential.force(k, kn, fn, ioXi);
    Real rolling = 0;
    if (kRolling && law.rolling.enabled) {  // cfddem Eq. 3.56-3.59
        ioZeta += k.dxroll;
        const Real cr = 2.0 * law.rolling.ratio * std::sqrt(k.meff * kn) * k.reff;
        rolling = law.rolling.kr * ioZeta + cr * k.vroll;
    }
    return {fn, ft, rolling};
}

/// Elastic energy stored in one contact [J].
template <class Normal, class Damping, class Tangential>
inline Real contactEnergy(const ResolvedLaw<Normal, Damping, Tangential>& law, Real overlap, Real reff,
                          Real xi, Real zeta) noexcept {
    // Rolling spring: M = k_r Xi with relative rotation Xi / R_eff, so E = k_r Xi^2 / (2 R_eff).
    const Real rolling = law.rolling.enabled ? 0.5 * law.rolling.kr * zeta * zeta / reff : 0.0;
    return law.normal.energy(overlap, reff) +
           law.tangential.energy(overlap, reff, xi, law.normal.force(overlap, reff)) + rolling;
}

}  // namespace granulab::dem
