// SPDX-License-Identifier: MIT
// Memory of this process, for summary.json and the benchmarks (DESIGN.md "Contract": memory).
#pragma once
#include <cstddef>
#include <fstream>
#include <string>

namespace granulab {

/// Peak resident memory of this process [bytes] (VmHWM of /proc/self/status; 0 if unknown).
inline std::size_t peakRssBytes() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmHWM:", 0) == 0) return static_cast<std::size_t>(std::stoull(line.substr(6))) * 1024;
    return 0;
}

}  // namespace granulab
