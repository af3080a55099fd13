// SPDX-License-Identifier: MIT
// Checkpoint file (DESIGN.md "Contract": `granulab run --resume` continues bit for bit): a header
// that identifies the scene, the output schedule counters and the engine's complete state.
#pragma once
#include <cstdint>
#include <string>

#include "dem/world.hpp"

namespace granulab::io {

/// Output bookkeeping that must survive a resume.
struct OutputCounters {
    std::int64_t nextSnapshot = 0;  ///< index of the next VTK snapshot file
};

/// Identity of the scene a checkpoint belongs to (dt and particle count must match).
struct CheckpointHeader {
    double dt = 0;
    std::uint64_t particles = 0;
    std::uint64_t walls = 0;
    std::string integrator;  ///< its state is part of the checkpoint
};

/// Writes `dir`/checkpoint.bin atomically (temporary file + rename).
void writeCheckpoint(const std::string& dir, const CheckpointHeader& header, const OutputCounters& counters,
                     const dem::World& world);

/// Loads `dir`/checkpoint.bin into `world`; throws std::runtime_error with a clear message if
/// it is missing, corrupt or belongs to another scene.
OutputCounters readCheckpoint(const std::string& dir, const CheckpointHeader& expected, dem::World& world);

}  // namespace granulab::io
