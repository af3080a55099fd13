// SPDX-License-Identifier: MIT
// Cores of the process for the default thread count (core/parallel.hpp).
#include "core/parallel.hpp"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>

namespace granulab {

int availableCores() noexcept {
    if (!kHaveThreads) return 1;
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) != 0) return 1;
    const int n = CPU_COUNT(&set);
    return n > 0 ? n : 1;
}

void splitByWeight(const double* weights, std::size_t count, int parts, std::uint32_t* cuts) noexcept {
    const int p = parts > 1 ? parts : 1;
    double total = 0;
    for (std::size_t k = 0; k < count; ++k) total += weights[k];
    cuts[0] = 0;
    std::size_t k = 0;
    double sum = 0;
    for (int r = 1; r < p; ++r) {
        // The r-th cut: the first item whose running weight passes r/p of the total, or the item
        // before it where that is closer.
        const double target = total * r / p;
        while (k < count && sum + weights[k] <= target) sum += weights[k++];
        if (k < count && target - sum > sum + weights[k] - target) sum += weights[k++];
        cuts[r] = static_cast<std::uint32_t>(k);
    }
    cuts[p] = static_cast<std::uint32_t>(count);
}

int defaultThreads() noexcept {
    const int cores = availableCores();
    const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
    if (!local) local = std::getenv("MPI_LOCALNRANKS");
    const long ranks = local ? std::strtol(local, nullptr, 10) : 1;
    if (ranks <= 1) return cores;
    // The machine's cores shared among its ranks, and no more than this rank's mask allows
    // (mpirun binds to a core or a socket, or not at all).
    const long online = std::max<long>(1, sysconf(_SC_NPROCESSORS_ONLN));
    return static_cast<int>(std::clamp<long>(online / ranks, 1, cores));
}

}  // namespace granulab
