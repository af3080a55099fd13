// SPDX-License-Identifier: MIT
// The DEM clock: simulated time t = k dt (DESIGN.md "The DEM step"). The one place where a
// duration or an instant [s] becomes a step count, so that outputs, windows and the run end
// round the same way everywhere.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/types.hpp"

namespace granulab::dem {

/// A whole number of steps as an integer, saturated at +-2^62 ("never" for a period or a window
/// far beyond any run; validation keeps a run's own end below 2^53 steps). NaN counts as never.
inline std::int64_t saturatedSteps(Real steps) noexcept {
    constexpr Real kNever = 4611686018427387904.0;  // 2^62
    if (!(steps < kNever))
        return steps < 0 ? -static_cast<std::int64_t>(kNever) : static_cast<std::int64_t>(kNever);
    if (steps < -kNever) return -static_cast<std::int64_t>(kNever);
    return static_cast<std::int64_t>(steps);
}

/// Steps in a duration [s] at time step dt [s], rounded to the nearest step (an end time, an
/// output period).
inline std::int64_t stepsIn(Real duration, Real dt) noexcept {
    return saturatedSteps(std::round(duration / dt));
}

/// Steps of an output period [s]: rounded to the nearest step, at least one.
inline std::int64_t periodSteps(Real period, Real dt) noexcept {
    return std::max<std::int64_t>(1, stepsIn(period, dt));
}

/// First step k with k dt >= t [s] (a window opening at t); t/dt within 1e-9 of an integer counts
/// as that integer, so a window written as a multiple of dt opens on that step.
inline std::int64_t firstStepAtOrAfter(Real t, Real dt) noexcept {
    return saturatedSteps(std::ceil(t / dt - 1e-9));
}

}  // namespace granulab::dem
