// SPDX-License-Identifier: MIT
// Edit distance and "did you mean" hints.
#include "core/suggest.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace granulab {

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                              std::tolower(static_cast<unsigned char>(b[j - 1]));
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates) {
    std::size_t best = std::string::npos;
    const std::string* bestName = nullptr;
    for (const auto& c : candidates) {
        const std::size_t d = editDistance(word, c);
        if (d < best) {
            best = d;
            bestName = &c;
        }
    }
    const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
    if (bestName && best <= limit) return " (did you mean '" + *bestName + "'?)";
    return "";
}

std::string joinList(const std::vector<std::string>& items, std::string_view separator) {
    std::string s;
    for (std::size_t k = 0; k < items.size(); ++k) {
        if (k) s += separator;
        s += items[k];
    }
    return s;
}

void checkOneOf(Diagnostics& diags, const SourceLoc& loc, const std::string& key, const std::string& value,
                const std::vector<std::string>& allowed) {
    if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
        diags.error(loc, key,
                    fmt::format("'{}' is not allowed{}; allowed: {}", value, didYouMean(value, allowed),
                                joinList(allowed)));
}

}  // namespace granulab
