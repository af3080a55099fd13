// SPDX-License-Identifier: MIT
// cos and sin of a body's angle for its world corners (gc2d spec section 5.4, step 3; Eq. 2.35),
// without a call of the library's sin and cos for every polygon and step. The angle is split
// exactly into a whole multiple of h = 1/64 rad and a rest |delta| <= 1/128 rad:
//   phi = k h + delta,  R(phi) = R(k h) R(delta),
// with cos(k h), sin(k h) from std::cos/std::sin (a function of k only, so that a cache of it
// is valid for any particle: RotationCache), and cos(delta), sin(delta) from their Taylor series
// to the term delta^6 and delta^7 (truncation below 4e-22, far below one unit in the last
// place). A grain turns by omega dt per step (1e-5 rad at 10 rad/s and dt = 1e-6 s), so k changes
// every few hundred steps and the step costs a few multiplications. The result is a pure
// function of the angle: the same on any thread count, after a resume and in every writer that
// places corners (ShapeContext, the gc2d and VTK files, scene set-up).
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/types.hpp"

namespace granulab::geom {

struct CosSin {
    Real c = 1, s = 0;
};

namespace rotation {

inline constexpr Real kStepsPerRadian = 64;  ///< 1/h [1/rad]; h = 1/64 rad is a power of two
/// |angle| below this has an exact split (k fits 2^52; larger angles use std::cos, std::sin).
inline constexpr Real kLargestSplit = 0x1p46;  // [rad]
inline constexpr std::int64_t kNoStep = std::numeric_limits<std::int64_t>::min();

/// cos and sin of |delta| <= 1/128 rad (Taylor to delta^6, delta^7; Horner form).
inline CosSin small(Real delta) noexcept {
    constexpr Real k6 = 1.0 / 6, k20 = 1.0 / 20, k42 = 1.0 / 42, k12 = 1.0 / 12, k30 = 1.0 / 30;
    const Real d2 = delta * delta;
    const Real s = delta * (1 - d2 * k6 * (1 - d2 * k20 * (1 - d2 * k42)));
    const Real c = 1 - d2 * 0.5 * (1 - d2 * k12 * (1 - d2 * k30));
    return {c, s};
}

/// R(base) R(delta) as cos, sin.
inline CosSin compose(CosSin base, CosSin delta) noexcept {
    return {base.c * delta.c - base.s * delta.s, base.s * delta.c + base.c * delta.s};
}

/// cos and sin of k h (the library's; a function of k only).
inline CosSin ofStep(std::int64_t k) noexcept {
    const Real a = static_cast<Real>(k) / kStepsPerRadian;  // exact: k < 2^53, h a power of two
    return {std::cos(a), std::sin(a)};
}

/// Whole steps of h nearest to angle (|angle| < kLargestSplit), and the exact rest.
inline std::int64_t stepOf(Real angle, Real& delta) noexcept {
    const Real k = std::nearbyint(angle * kStepsPerRadian);  // angle * 64 is exact
    delta = angle - k / kStepsPerRadian;                     // exact: both lie within 1/128
    return static_cast<std::int64_t>(k);
}

}  // namespace rotation

/// cos and sin of angle [rad] (see the file comment); the library's for non-finite or huge angles.
inline CosSin rotationOf(Real angle) noexcept {
    if (!(std::abs(angle) < rotation::kLargestSplit)) return {std::cos(angle), std::sin(angle)};
    Real delta;
    const std::int64_t k = rotation::stepOf(angle, delta);
    return rotation::compose(rotation::ofStep(k), rotation::small(delta));
}

/// rotationOf for many bodies, keeping cos and sin of each slot's last k h: the same results as
/// rotationOf bit for bit. An entry holds (k, R(k h)) of whichever body last used the slot, which
/// is valid for any body, so the cache needs no invalidation when slots are reordered.
class RotationCache {
public:
    void resize(std::size_t n) {
        m_step.resize(n, rotation::kNoStep);
        m_base.resize(n);
    }
    /// cos and sin of angle for slot i (i < size given to resize).
    CosSin operator()(std::size_t i, Real angle) noexcept {
        if (!(std::abs(angle) < rotation::kLargestSplit)) return {std::cos(angle), std::sin(angle)};
        Real delta;
        const std::int64_t k = rotation::stepOf(angle, delta);
        if (k != m_step[i]) {
            m_step[i] = k;
            m_base[i] = rotation::ofStep(k);
        }
        return rotation::compose(m_base[i], rotation::small(delta));
    }

private:
    std::vector<std::int64_t> m_step;
    std::vector<CosSin> m_base;
};

}  // namespace granulab::geom
