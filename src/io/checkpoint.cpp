// SPDX-License-Identifier: MIT
// Binary checkpoint: magic, version, header, counters, engine state.
#include "io/checkpoint.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <stdexcept>

#include "core/binary_io.hpp"

namespace granulab::io {

namespace {
constexpr std::uint64_t kMagic = 0x544b434c42414e47ULL;  // "GNABLCKT"
constexpr std::uint32_t kVersion = 4;  // 3: + integrator name; 4: + polygon shapes, area-contact state
}  // namespace

void writeCheckpoint(const std::string& dir, const CheckpointHeader& header, const OutputCounters& counters,
                     const dem::World& world) {
    const std::string path = dir + "/checkpoint.bin";
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw std::runtime_error("cannot write " + tmp);
        writePod(out, kMagic);
        writePod(out, kVersion);
        writePod(out, header.dt);
        writePod(out, header.particles);
        writePod(out, header.walls);
        writeString(out, header.integrator);
        writePod(out, counters.nextSnapshot);
        world.saveState(out);
        if (!out) throw std::runtime_error("write failed: " + tmp);
    }
    std::filesystem::rename(tmp, path);
}

OutputCounters readCheckpoint(const std::string& dir, const CheckpointHeader& expected, dem::World& world) {
    const std::string path = dir + "/checkpoint.bin";
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(fmt::format("no checkpoint at {} (run without --resume first)", path));
    if (readPod<std::uint64_t>(in) != kMagic) throw std::runtime_error(path + " is not a granulab checkpoint");
    if (const auto v = readPod<std::uint32_t>(in); v != kVersion)
        throw std::runtime_error(fmt::format("{} has format version {}, this build reads {}", path, v, kVersion));
    CheckpointHeader h;
    h.dt = readPod<double>(in);
    h.particles = readPod<std::uint64_t>(in);
    h.walls = readPod<std::uint64_t>(in);
    h.integrator = readString(in);
    if (h.integrator != expected.integrator)
        throw std::runtime_error(fmt::format("{} was written with integrator '{}'; resume with --set dem.integrator={}",
                                             path, h.integrator, h.integrator));
    if (h.dt != expected.dt || h.particles != expected.particles || h.walls != expected.walls)
        throw std::runtime_error(fmt::format(
            "{} belongs to another scene (dt {} s, {} particles, {} walls; this scene: dt {} s, {} particles, {} walls)",
            path, h.dt, h.particles, h.walls, expected.dt, expected.particles, expected.walls));
    OutputCounters c;
    c.nextSnapshot = readPod<std::int64_t>(in);
    world.loadState(in);
    return c;
}

}  // namespace granulab::io
