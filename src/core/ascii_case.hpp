// SPDX-License-Identifier: MIT
// ASCII case folding for case-insensitive scene keywords (gc2d spec 9.2: gsi, gci and file
// suffixes are read without regard to case). Bytes outside A-Z / a-z are kept as they are.
#pragma once
#include <cctype>
#include <string>
#include <string_view>

namespace granulab {

inline std::string asciiUpper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

inline std::string asciiLower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace granulab
