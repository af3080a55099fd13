// SPDX-License-Identifier: MIT
// Exact round trips through a unit conversion (gc2d spec 9.4, restart files "bit for bit"): a
// file holds a value in the unit a reader expects (an acceleration [m/s^2], a spring force [N])
// while the engine keeps another (the Gear predictor's scaled r2 = dt^2/2 a [m], a spring length
// [m]). The writer picks, among the doubles next to value / factor, one that the reader's own
// arithmetic (x * factor, or x / divisor) turns back into exactly the engine's value.
#pragma once
#include <cmath>

namespace granulab {

/// x with x * factor == target in floating point, searched within 16 ulps of target / factor;
/// target / factor when none is found (or factor is 0 or not finite).
inline double preimageOfProduct(double target, double factor) noexcept {
    if (!(factor != 0) || !std::isfinite(factor)) return 0;
    const double guess = target / factor;
    double lo = guess, hi = guess;
    for (int k = 0; k <= 16; ++k) {
        if (lo * factor == target) return lo;
        if (hi * factor == target) return hi;
        lo = std::nextafter(lo, -HUGE_VAL);
        hi = std::nextafter(hi, HUGE_VAL);
    }
    return guess;
}

/// x with x / divisor == target in floating point, searched within 16 ulps of target * divisor;
/// target * divisor when none is found.
inline double preimageOfQuotient(double target, double divisor) noexcept {
    if (!(divisor != 0) || !std::isfinite(divisor)) return 0;
    const double guess = target * divisor;
    double lo = guess, hi = guess;
    for (int k = 0; k <= 16; ++k) {
        if (lo / divisor == target) return lo;
        if (hi / divisor == target) return hi;
        lo = std::nextafter(lo, -HUGE_VAL);
        hi = std::nextafter(hi, HUGE_VAL);
    }
    return guess;
}

}  // namespace granulab
