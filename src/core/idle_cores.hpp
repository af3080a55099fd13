// SPDX-License-Identifier: MIT
// How many of this process's cores were idle over an interval: the sum, over the CPUs of its
// affinity mask, of each CPU's idle share of its time (idle and iowait ticks over all ticks, from
// Linux's /proc/stat). The automatic thread count (core/thread_governor.hpp; docs/physics/
// dem-threads.md, "How the default is chosen") asks it before it tries a larger team: on cores that
// other programs keep busy a trial costs time slices of the operating system and cannot win.
// Read rarely (once per planned trial, a few times a second at most), never in a step's loops.
#pragma once
#include <cstdint>
#include <cstdio>
#include <vector>

namespace granulab {

class IdleCores {
public:
    /// Reads the affinity mask of the calling thread's process.
    IdleCores();
    /// Starts an interval now.
    void start();
    /// [cores] idle on average since start(), summed over the mask's CPUs; < 0 when unknown (no
    /// /proc/stat, no start(), or too few clock ticks since start() to tell).
    double idleSinceStart();

    /// Per-CPU tick counters of one reading (exposed for tests of the arithmetic).
    struct Ticks {
        std::uint64_t idle = 0, total = 0;
    };
    /// Idle cores between two readings of the same CPUs; < 0 when fewer than `minTicks` ticks
    /// passed on every CPU (an interval too short to tell). Two ticks (20 ms) resolve what the
    /// thread count asks: whether the other cores were busy throughout or idle.
    static double idleBetween(const std::vector<Ticks>& before, const std::vector<Ticks>& after,
                              std::uint64_t minTicks = 2);

    /// The ticks of `cpus` from the text of /proc/stat (empty when one of them is not listed).
    static std::vector<Ticks> parseStat(std::FILE* stat, const std::vector<int>& cpus);
    static constexpr int kMaxCpu = 1 << 16;

private:
    /// Ticks of the mask's CPUs now (empty when /proc/stat cannot be read).
    std::vector<Ticks> read() const;

    std::vector<int> m_cpus;  ///< CPU numbers of the affinity mask
    std::vector<Ticks> m_start;
};

}  // namespace granulab
