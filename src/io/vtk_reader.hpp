// SPDX-License-Identifier: MIT
// Reader for the .vtp/.pvd files written by io/vtk_writer (render, analyze, resume). It reads
// only what our writer writes: raw appended binary, UInt64 headers, little endian.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace granulab::io {

/// Particle columns of one snapshot, in file cell order: the disks (vertex cells), then the
/// polygons (polygon cells; files written before polygons existed have none).
struct ParticleFrame {
    double time = 0;                                 ///< [s]
    std::vector<double> x, y, radius, speed, angle;  ///< [m], [m], [m] (polygons: circumradius), [m/s], [rad]
    std::vector<std::int64_t> id;
    /// Polygon outlines: the world corners (counter-clockwise) of particle i are
    /// corners[cornerStart[i] .. cornerStart[i + 1]); an empty range is a disk. size() + 1 entries.
    std::vector<std::size_t> cornerStart{0};
    std::vector<Vec2> corners;  ///< [m]

    std::size_t size() const noexcept { return x.size(); }
    std::size_t cornerCount(std::size_t i) const noexcept { return cornerStart[i + 1] - cornerStart[i]; }
    bool isPolygon(std::size_t i) const noexcept { return cornerCount(i) > 0; }
};

/// Wall segments of one snapshot.
struct WallFrame {
    std::vector<Vec2> a, b;  ///< [m] segment end points
};

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
