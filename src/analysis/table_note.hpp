// SPDX-License-Identifier: MIT
// The "key = value unit" note lines of an analysis table (analysis/table.hpp), for fitted values
// and scalar results (gc2d spec section 7).
#pragma once
#include <fmt/format.h>

#include <string>

#include "core/types.hpp"

namespace granulab::analysis {

/// "key = value unit" with value in %.6g (unit omitted when empty).
inline std::string noteLine(const std::string& key, Real value, const std::string& unit = "") {
    return unit.empty() ? fmt::format("{} = {:.6g}", key, value)
                        : fmt::format("{} = {:.6g} {}", key, value, unit);
}

}  // namespace granulab::analysis
