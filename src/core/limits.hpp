// SPDX-License-Identifier: MIT
// Representable-range limits shared by the validation of every engine (issue 11: every numeric
// input and derived quantity is checked for finiteness and range before a run starts).
#pragma once
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace granulab {

/// Integers above 2^53 in magnitude have no exact double: counts of steps, collisions and
/// particles derived in double must stay below it.
inline constexpr double kExactIntegerLimit = 9007199254740992.0;

/// Largest particle count of one scene: ids are 32-bit, and pair keys pack two ids.
inline constexpr double kMaxParticleCount = 2147483647.0;

/// Reports (at `loc`, `key`) a scene whose engine would need more memory than this machine has:
/// `bytes` estimated [bytes] for `what` (e.g. "2.1e9 particles").
inline void checkMemoryFits(Diagnostics& diags, const SourceLoc& loc, const std::string& key, double bytes,
                            const std::string& what) {
    const double usable = usableMemoryBytes();
    if (!std::isfinite(bytes) || (usable > 0 && bytes > usable))
        diags.error(loc, key,
                    fmt::format("{} need about {:.3g} GB of memory; this machine has {:.3g} GB", what,
                                bytes / 1e9, usable / 1e9));
}

/// Smallest coordinate step [m] that double precision resolves at |x| (its unit in the last place).
inline double resolutionAt(double x) {
    return std::nextafter(std::abs(x), INFINITY) - std::abs(x);
}

}  // namespace granulab
