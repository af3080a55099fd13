// SPDX-License-Identifier: MIT
// Idle cores of this process's CPU set from Linux's /proc/stat (core/idle_cores.hpp).
#include "core/idle_cores.hpp"

#include <sched.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

namespace granulab {

IdleCores::IdleCores() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) != 0) return;
    for (int c = 0; c < CPU_SETSIZE; ++c)
        if (CPU_ISSET(c, &set)) m_cpus.push_back(c);
}

std::vector<IdleCores::Ticks> IdleCores::read() const {
    if (m_cpus.empty()) return {};
    std::FILE* f = std::fopen("/proc/stat", "r");
    if (!f) return {};
    std::vector<Ticks> out = parseStat(f, m_cpus);
    std::fclose(f);
    return out;
}

std::vector<IdleCores::Ticks> IdleCores::parseStat(std::FILE* f, const std::vector<int>& cpus) {
    std::vector<Ticks> out;
    std::vector<Ticks> all;  // index: CPU number
    char line[512];
    while (std::fgets(line, sizeof line, f)) {
        // "cpuN user nice system idle iowait irq softirq steal guest guest_nice" (guest time is
        // already counted in user and nice)
        if (std::strncmp(line, "cpu", 3) != 0) break;  // the cpu lines come first
        // The first line sums all CPUs ("cpu  user nice ..."): no CPU number follows "cpu" (and
        // "%d" would skip the blanks and take the user ticks for one).
        if (!std::isdigit(static_cast<unsigned char>(line[3]))) continue;
        int cpu = -1;
        unsigned long long v[8] = {};
        if (std::sscanf(line, "cpu%d %llu %llu %llu %llu %llu %llu %llu %llu", &cpu, &v[0], &v[1], &v[2],
                        &v[3], &v[4], &v[5], &v[6], &v[7]) < 5 ||
            cpu < 0 || cpu >= kMaxCpu)
            continue;
        if (static_cast<std::size_t>(cpu) >= all.size()) all.resize(static_cast<std::size_t>(cpu) + 1);
        Ticks& t = all[static_cast<std::size_t>(cpu)];
        t.idle = v[3] + v[4];
        for (const unsigned long long x : v) t.total += x;
    }
    for (const int c : cpus) {
        if (static_cast<std::size_t>(c) >= all.size()) return {};  // a CPU of the mask not listed
        out.push_back(all[static_cast<std::size_t>(c)]);
    }
    return out;
}

void IdleCores::start() {
    m_start = read();
}

double IdleCores::idleSinceStart() {
    if (m_start.empty()) return -1;
    return idleBetween(m_start, read());
}

double IdleCores::idleBetween(const std::vector<Ticks>& before, const std::vector<Ticks>& after,
                              std::uint64_t minTicks) {
    if (before.empty() || before.size() != after.size()) return -1;
    double idle = 0;
    bool enough = false;
    for (std::size_t k = 0; k < before.size(); ++k) {
        if (after[k].total < before[k].total || after[k].idle < before[k].idle)
            return -1;  // a CPU went offline
        const std::uint64_t total = after[k].total - before[k].total;
        if (total == 0) continue;
        enough = enough || total >= minTicks;
        idle +=
            static_cast<double>(std::min(after[k].idle - before[k].idle, total)) / static_cast<double>(total);
    }
    return enough ? idle : -1;
}

}  // namespace granulab
