// SPDX-License-Identifier: MIT
// UTF-8 validity of text read from or written to files (TOML needs UTF-8; the cfddem seed's
// files may be Latin-1).
#pragma once
#include <cstddef>
#include <string_view>

namespace granulab {

/// True if `s` is well-formed UTF-8 (lead bytes of 1-4 byte sequences, continuation bytes 10xxxxxx).
inline bool isUtf8(std::string_view s) noexcept {
    for (std::size_t k = 0; k < s.size();) {
        const auto c = static_cast<unsigned char>(s[k]);
        const std::size_t n = c < 0x80           ? 1
                              : (c >> 5) == 0x6  ? 2
                              : (c >> 4) == 0xE  ? 3
                              : (c >> 3) == 0x1E ? 4
                                                 : 0;
        if (n == 0 || k + n > s.size()) return false;
        for (std::size_t j = 1; j < n; ++j)
            if ((static_cast<unsigned char>(s[k + j]) >> 6) != 0x2) return false;
        k += n;
    }
    return true;
}

}  // namespace granulab
