// SPDX-License-Identifier: MIT
// The per-contact force evaluation, fixed order normal -> damping -> cap -> tangential
// (STYLE.md (b), LAMMPS GranularModel order). Template over one alternative per axis, so the
// hot loop has no dispatch; dem/forces.cpp visits once per bucket of pairs.
#pragma once
#include <cmath>

#include "dem/contact/laws.hpp"

namespace granulab::dem {

/// Force magnitudes: fn > 0 is repulsive; ft is along t, acting on the first body.
struct ContactForce {
    Real fn;
    Real ft;
};

template <class Normal, class Damping, class Tangential>
struct ResolvedLaw {
    Normal normal;
    Damping damping;
    Tangential tangential;
    bool clipAttraction;
};

/// Evaluates one contact; ioXi is the tangential spring history [m], updated in place.
template <class Normal, class Damping, class Tangential>
inline ContactForce evaluateContact(const ResolvedLaw<Normal, Damping, Tangential>& law,
                                    const ContactKinematics& k, Real& ioXi) noexcept {
    const Real kn = law.normal.stiffness(k.overlap, k.reff);
    const Real cn = law.damping.coefficient(k.meff, kn);
    Real fn = law.normal.force(k.overlap, k.reff) + cn * k.vn;
    if (law.clipAttraction && fn < 0) fn = 0;
    const Real ft = law.tangential.force(k, kn, fn, ioXi);
    return {fn, ft};
}

/// Elastic energy stored in one contact [J].
template <class Normal, class Damping, class Tangential>
inline Real contactEnergy(const ResolvedLaw<Normal, Damping, Tangential>& law, Real overlap, Real reff,
                          Real xi) noexcept {
    return law.normal.energy(overlap, reff) + law.tangential.energy(overlap, reff, xi);
}

}  // namespace granulab::dem
