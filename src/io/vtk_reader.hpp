// SPDX-License-Identifier: MIT
// Reader for the .vtp/.pvd files written by io/vtk_writer (render, analyze, resume). It reads
// only what our writer writes: raw appended binary, UInt64 headers, little endian.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "core/types.hpp"

namespace granulab::io {

/// Particle columns of one snapshot, in file cell order: the disks (vertex cells), then the
/// polygons (polygon cells; files written before polygons existed have none). Arrays a file
/// lacks (edmd gas snapshots: angle, omega, mass, material) are filled with 0.
using ParticleFrame = analysis::GrainFrame;

/// Wall segments of one snapshot, with the wall index of each.
using WallFrame = analysis::WallSegments;

/// One DataSet line of a .pvd collection.
struct PvdEntry {
    double time = 0;   ///< [s]
    int part = 0;      ///< 0 = particles, 1 = walls
    std::string file;  ///< relative to the .pvd's folder
};

/// All three throw std::runtime_error naming the file on missing or malformed input.
ParticleFrame readParticlesVtp(const std::string& path);
WallFrame readWallsVtp(const std::string& path);
std::vector<PvdEntry> readPvd(const std::string& path);

}  // namespace granulab::io
