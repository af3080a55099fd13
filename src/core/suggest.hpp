// SPDX-License-Identifier: MIT
// "Did you mean" hints for unknown keys and names (edit distance).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace granulab {

/// Levenshtein distance, case-insensitive.
std::size_t editDistance(std::string_view a, std::string_view b);

/// " (did you mean 'x'?)" for the closest candidate within a small distance, else "".
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);

/// "a, b, c" for messages listing the allowed values (another separator when given).
std::string joinList(const std::vector<std::string>& items, std::string_view separator = ", ");

/// Reports `key` at `loc` unless `value` is one of `allowed`: "'x' is not allowed (did you mean
/// 'y'?); allowed: a, b".
void checkOneOf(Diagnostics& diags, const SourceLoc& loc, const std::string& key, const std::string& value,
                const std::vector<std::string>& allowed);

}  // namespace granulab
