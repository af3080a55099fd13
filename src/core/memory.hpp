// SPDX-License-Identifier: MIT
// Memory of this process and of the machine: the peak for summary.json and the benchmarks
// (DESIGN.md "Contract": memory), the usable total for the validation's memory check (issue 11:
// a scene that cannot fit is an error before anything is allocated).
#pragma once
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
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

/// Memory this process may use [bytes]: the physical memory, or the cgroup (container) limit
/// when that is lower; 0 if unknown.
inline double usableMemoryBytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    double bytes = pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 0;
    for (const char* limitFile :
         {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
        std::ifstream in(limitFile);
        std::string text;
        if (!(in >> text) || text == "max") continue;
        try {
            const double limit = std::stod(text);
            if (limit > 0 && (bytes == 0 || limit < bytes)) bytes = limit;
        } catch (...) {  // unreadable limit: keep the physical memory
        }
    }
    return bytes;
}

}  // namespace granulab
