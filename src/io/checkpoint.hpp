// SPDX-License-Identifier: MIT
// The one checkpoint container of every engine (DESIGN.md "Contract": `granulab run --resume`
// continues bit for bit). Layout (format version 6), little-endian as the machine writes it:
//   magic "GNABLCKT" (u64) | format version (u32) | engine name | scene identity (key, value
//   pairs and their 64-bit fingerprint) | run bookkeeping | blob | blob length (u64) |
//   checksum (u64: 64-bit FNV-1a over every byte before it)
// The blob is the engine's own state (dem::World::saveState, edmd::Engine::saveState, ...).
// A file whose checksum does not match (a flipped bit, a block overwritten, a cut file) is
// refused naming the file, before the engine reads anything. Files of an older format version,
// and the unversioned edmd files of version 1, are refused with a message naming their version.
#pragma once
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace granulab::io {

/// What a checkpoint must share with the scene that resumes it: entries such as the integrator
/// or the particle count. `key` names the scene key when the user can change it (dem.integrator).
struct IdentityEntry {
    std::string key;
    std::string value;
    bool operator==(const IdentityEntry&) const = default;
};
using SceneIdentity = std::vector<IdentityEntry>;

/// 64-bit FNV-1a over the identity entries (stored, and compared before the entries).
std::uint64_t fingerprint(const SceneIdentity& identity);

/// Run bookkeeping that a resume restores (the output schedules are re-derived from the scene).
struct RunBookkeeping {
    std::int64_t nextSnapshot = 0;  ///< index of the next snapshot file
};

struct CheckpointHeader {
    std::string engine;
    SceneIdentity identity;
    RunBookkeeping bookkeeping;
};

/// The format version this build writes and reads.
inline constexpr std::uint32_t kCheckpointVersion = 6;

/// Writes `dir`/checkpoint.bin atomically; `saveEngine` writes the blob.
void writeCheckpoint(const std::string& dir, const CheckpointHeader& header,
                     const std::function<void(std::ostream&)>& saveEngine);

/// Reads `dir`/checkpoint.bin: checks magic, version, checksum, engine and identity against
/// `expected` (throws std::runtime_error with a message naming the file, what differs and how to
/// resume), then calls `loadEngine` on the blob and checks that it consumed exactly the blob (an
/// exception of `loadEngine`, std::bad_alloc included, becomes a std::runtime_error naming the
/// file). Returns the bookkeeping.
RunBookkeeping readCheckpoint(const std::string& dir, const CheckpointHeader& expected,
                              const std::function<void(std::istream&)>& loadEngine);

}  // namespace granulab::io
