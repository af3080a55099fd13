// SPDX-License-Identifier: MIT
// Kinematics of one contact in its frame (n, t = perp(n)), the input of every contact law.
#pragma once
#include "core/types.hpp"

namespace granulab::dem {

/// Kinematics of one contact, in the contact frame (n, t = perp(n)).
struct ContactKinematics {
    Real overlap;  ///< [m] > 0
    Real vn;       ///< [m/s] normal relative speed, > 0 when approaching
    Real vt;       ///< [m/s] tangential relative speed of the contact points (for damping)
    Real meff;     ///< [kg] effective mass
    Real dxt;      ///< [m] tangential displacement of the contact points during this step
    Real reff;     ///< [m] effective radius (R_i R_j / (R_i + R_j); the disk radius at a wall)
    Real vroll;    ///< [m/s] rolling velocity along t (cfddem Eq. 3.58), for rolling damping
    Real dxroll;   ///< [m] rolling displacement during this step (drift velocities)
};

}  // namespace granulab::dem
