// SPDX-License-Identifier: MIT
// Time schedules of the DEM scene: gravity magnitude (gc2d spec 6.6) CONSTANT, LINEAR, STEP and
// SMOOTH_STEP between g1 and g2 over [t1, t2] with the spec's recommended phase, a gravity
// direction turning linearly over a tilt window (tilting a box), and the global size scaling
// s(t) of thermal cycling (gc2d spec 2.4, Eq. B.2). Pure functions of time.
#pragma once
#include <algorithm>
#include <cmath>

#include "core/types.hpp"

namespace granulab::dem {

struct GravitySchedule {
    enum class Type { Constant, Linear, Step, SmoothStep };
    Type type = Type::Constant;
    Real g1 = 0, g2 = 0;                                ///< [m/s^2] magnitudes
    Real t1 = 0, t2 = 1;                                ///< [s]
    Real steps = 5;                                     ///< p1 (number of steps)
    Real ramp = 0.5;                                    ///< p2: fraction of each step period spent ramping
    Real direction1 = -kPi / 2, direction2 = -kPi / 2;  ///< [rad]
    Real tilt1 = 0, tilt2 = 0;                          ///< [s] tilt window
};

/// Gravity magnitude [m/s^2] at time t (gc2d 6.6; tau = (t - t1)/(t2 - t1) clamped to [0, 1],
/// k = floor(p1 tau), u = p1 tau - k; STEP g1 + (g2 - g1) k/p1; SMOOTH_STEP
/// g1 + (g2 - g1) (k + clamp((u - (1 - p2))/p2, 0, 1))/p1).
inline Real gravityMagnitude(const GravitySchedule& g, Real t) noexcept {
    if (g.type == GravitySchedule::Type::Constant) return g.g1;
    const Real span = g.t2 - g.t1;
    const Real tau = span > 0 ? std::clamp((t - g.t1) / span, Real(0), Real(1)) : (t >= g.t2 ? 1 : 0);
    switch (g.type) {
        case GravitySchedule::Type::Linear:
            return g.g1 + (g.g2 - g.g1) * tau;
        case GravitySchedule::Type::Step:
        case GravitySchedule::Type::SmoothStep: {
            const Real p1 = g.steps;
            const Real k = std::min(std::floor(p1 * tau), p1);
            const Real u = p1 * tau - k;
            Real frac = 0;
            if (g.type == GravitySchedule::Type::SmoothStep && k < p1)
                frac = g.ramp > 0 ? std::clamp((u - (1 - g.ramp)) / g.ramp, Real(0), Real(1)) : 0;
            return g.g1 + (g.g2 - g.g1) * (k + frac) / p1;
        }
        case GravitySchedule::Type::Constant:
            break;
    }
    return g.g1;
}

/// Gravity direction [rad] at time t: direction1 before the tilt window, direction2 after,
/// linear in between.
inline Real gravityDirection(const GravitySchedule& g, Real t) noexcept {
    if (g.direction1 == g.direction2) return g.direction1;
    const Real span = g.tilt2 - g.tilt1;
    const Real tau = span > 0 ? std::clamp((t - g.tilt1) / span, Real(0), Real(1)) : (t >= g.tilt2 ? 1 : 0);
    return g.direction1 + (g.direction2 - g.direction1) * tau;
}

/// Gravity vector [m/s^2] at time t.
inline Vec2 gravityAt(const GravitySchedule& g, Real t) noexcept {
    const Real m = gravityMagnitude(g, t), a = gravityDirection(g, t);
    return {m * std::cos(a), m * std::sin(a)};
}

/// Global size scaling of gc2d HEAT_* (spec 2.4): s(t) = 1 + a (1/2 - 1/2 tanh(S cos(2 pi f t_c))),
/// t_c = clamp(t, t1, t2): a smoothed square wave between about 1 and 1 + a.
struct SizeCycle {
    Real amplitude = 0.01;    ///< a (HEAT_AMPLITUDE)
    Real frequency = 1;       ///< f [1/s] (HEAT_FREQUENCE)
    Real slope = 10;          ///< S, steepness (HEAT_SLOPE)
    Real t1 = 0, t2 = 1e300;  ///< [s] HEAT_TIME
};

inline Real sizeScale(const SizeCycle& c, Real t) noexcept {
    const Real tc = std::clamp(t, c.t1, c.t2);
    return 1 + c.amplitude * (0.5 - 0.5 * std::tanh(c.slope * std::cos(2 * kPi * c.frequency * tc)));
}

}  // namespace granulab::dem
