// SPDX-License-Identifier: MIT
// Restitution of the Hertz spring with Lehr damping c_n = 2 D sqrt(meff k_Hz) delta^(1/4)
// (cfddem spec section 3.5): e depends on D only. e(D) is obtained by integrating the
// dimensionless collision once, and inverted by bisection, so that a user may give e.
#pragma once
#include "core/types.hpp"

namespace granulab::dem {

/// Restitution coefficient of a Hertz-Lehr collision with damping ratio D >= 0, unclipped
/// normal force (the "Hertz model" row of the spec's table), or clipped at zero.
Real hertzRestitution(Real dampingRatio, bool clipAttraction = false);

/// The damping ratio D that gives restitution e in (0, 1] (inverse of hertzRestitution).
Real hertzDampingRatio(Real restitution, bool clipAttraction = false);

/// Eq. 3.78 of the spec (exact for the linear spring): D = -ln e / sqrt(pi^2 + ln^2 e).
Real linearDampingRatio(Real restitution);

}  // namespace granulab::dem
