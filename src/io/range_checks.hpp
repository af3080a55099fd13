// SPDX-License-Identifier: MIT
// The range checks every Def-level validation uses (docs/scene-format.md "Errors"): the message
// names the key, the unit, the value and the allowed range.
#pragma once
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace granulab::io {

inline void checkPositive(Diagnostics& d, const SourceLoc& loc, const std::string& key, Real v,
                          const std::string& unit) {
    if (!(v > 0) || !std::isfinite(v))
        d.error(loc, key, fmt::format("must be > 0 [{}], got {}; allowed (0, inf)", unit, v));
}

inline void checkNonNegative(Diagnostics& d, const SourceLoc& loc, const std::string& key, Real v,
                             const std::string& unit) {
    if (!(v >= 0) || !std::isfinite(v))
        d.error(loc, key, fmt::format("must be >= 0 [{}], got {}; allowed [0, inf)", unit, v));
}

}  // namespace granulab::io
