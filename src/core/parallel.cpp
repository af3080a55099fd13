// SPDX-License-Identifier: MIT
// Cores of the process for the default thread count (core/parallel.hpp).
#include "core/parallel.hpp"

#include <sched.h>

namespace granulab {

int availableCores() noexcept {
    if (!kHaveThreads) return 1;
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) != 0) return 1;
    const int n = CPU_COUNT(&set);
    return n > 0 ? n : 1;
}

}  // namespace granulab
