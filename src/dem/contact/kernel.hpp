// SPDX-License-Identifier: MIT
// The per-contact force evaluation, fixed order normal -> damping -> cap -> tangential
// (STYLE.md (b), LAMMPS GranularModel order). Template over one alternative per axis, so the
// hot loop has no dispatch; dem/forces.cpp visits once per bucket of pairs.
#pragma once
#include <cmath>
#include <type_traits>

#include "dem/contact/laws.hpp"

namespace granulab::dem {

/// Kinematics of one contact, in the contact frame (n, t = perp(n)).
struct ContactKinematics {
    Real overlap;  ///< [m] > 0
    Real vn;       ///< [m/s] normal relative speed, > 0 when approaching
    Real vt;       ///< [m/s] tangential relative speed of the contact points (for damping)
    Real meff;     ///< [kg] effective mass
    Real dxt;      ///< [m] tangential displacement of the contact points during this step
};

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
    const Real cn = law.damping.coefficient(k.meff, law.normal.stiffness(k.overlap));
    Real fn = law.normal.force(k.overlap) + cn * k.vn;
    if (law.clipAttraction && fn < 0) fn = 0;
    Real ft = 0;
    if constexpr (std::is_same_v<Tangential, CundallStrack>) {
        const CundallStrack& cs = law.tangential;
        const Real ct = cs.ct + k.meff * cs.gammaT;
        ioXi += k.dxt;
        ft = -(cs.kt * ioXi + ct * k.vt);
        const Real cap = cs.mu * std::abs(fn);
        const Real mag = std::abs(ft);
        if (mag > cap) {
            const Real scale = cap / mag;
            // Spring reset so that kt xi + ct vt equals the capped force (LAMMPS convention).
            ioXi = cs.kt > 0 ? scale * (ioXi + ct * k.vt / cs.kt) - ct * k.vt / cs.kt : 0;
            ft *= scale;
        }
    }
    return {fn, ft};
}

/// Elastic energy stored in one contact [J].
template <class Normal, class Damping, class Tangential>
inline Real contactEnergy(const ResolvedLaw<Normal, Damping, Tangential>& law, Real overlap,
                          Real xi) noexcept {
    Real e = law.normal.energy(overlap);
    if constexpr (std::is_same_v<Tangential, CundallStrack>) e += 0.5 * law.tangential.kt * xi * xi;
    return e;
}

}  // namespace granulab::dem
