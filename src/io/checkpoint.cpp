// SPDX-License-Identifier: MIT
// Checkpoint container (io/checkpoint.hpp): header, identity check, engine blob with its length.
#include "io/checkpoint.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "core/binary_io.hpp"
#include "io/atomic_file.hpp"

namespace granulab::io {

namespace {
constexpr std::uint64_t kMagic = 0x544b434c42414e47ULL;         // "GNABLCKT"
constexpr std::uint64_t kOldEdmdMagic = 0x31444d4445424c47ULL;  // "GLBEDMD1": edmd files before version 5

std::string describe(const SceneIdentity& id) {
    std::string s;
    for (const auto& e : id) s += fmt::format("{}{} {}", s.empty() ? "" : ", ", e.key, e.value);
    return s;
}
}  // namespace

std::uint64_t fingerprint(const SceneIdentity& identity) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    const auto mix = [&](const std::string& s) {
        for (const unsigned char c : s) h = (h ^ c) * 0x100000001b3ULL;
        h = (h ^ 0xffu) * 0x100000001b3ULL;  // separator
    };
    for (const auto& e : identity) {
        mix(e.key);
        mix(e.value);
    }
    return h;
}

void writeCheckpoint(const std::string& dir, const CheckpointHeader& header,
                     const std::function<void(std::ostream&)>& saveEngine) {
    AtomicFile file(dir + "/checkpoint.bin");
    std::ostream& out = file.stream();
    writePod(out, kMagic);
    writePod(out, kCheckpointVersion);
    writeString(out, header.engine);
    writePod<std::uint64_t>(out, header.identity.size());
    for (const auto& e : header.identity) {
        writeString(out, e.key);
        writeString(out, e.value);
    }
    writePod(out, fingerprint(header.identity));
    writePod(out, header.bookkeeping.nextSnapshot);
    const auto lengthAt = out.tellp();
    writePod<std::uint64_t>(out, 0);  // blob length, patched below
    const auto blobStart = out.tellp();
    saveEngine(out);
    const auto blobEnd = out.tellp();
    out.seekp(lengthAt);
    writePod<std::uint64_t>(out, static_cast<std::uint64_t>(blobEnd - blobStart));
    out.seekp(blobEnd);
    file.commit();
}

RunBookkeeping readCheckpoint(const std::string& dir, const CheckpointHeader& expected,
                              const std::function<void(std::istream&)>& loadEngine) {
    const std::string path = dir + "/checkpoint.bin";
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(fmt::format("no checkpoint at {} (run without --resume first)", path));
    const auto magic = readPod<std::uint64_t>(in);
    if (magic == kOldEdmdMagic)
        throw std::runtime_error(
            fmt::format("{} is an edmd checkpoint of format version 1 (unversioned, before granulab "
                        "checkpoints had one container); this build reads version {}: rerun the scene "
                        "without --resume",
                        path, kCheckpointVersion));
    if (!in || magic != kMagic) throw std::runtime_error(path + " is not a granulab checkpoint");
    if (const auto v = readPod<std::uint32_t>(in); v != kCheckpointVersion)
        throw std::runtime_error(
            fmt::format("{} has format version {}, this build reads version {}: rerun the scene "
                        "without --resume (or with the granulab version that wrote it)",
                        path, v, kCheckpointVersion));
    CheckpointHeader h;
    h.engine = readString(in);
    if (h.engine != expected.engine)
        throw std::runtime_error(
            fmt::format("{} was written by the {} engine; this scene runs run.engine = \"{}\"", path,
                        h.engine, expected.engine));
    const auto entries = readPod<std::uint64_t>(in);
    if (!in || entries > 1000) throw std::runtime_error(path + " is corrupt (identity)");
    for (std::uint64_t k = 0; k < entries; ++k) {
        IdentityEntry e;
        e.key = readString(in);
        e.value = readString(in);
        h.identity.push_back(e);
    }
    const auto print = readPod<std::uint64_t>(in);
    if (!in || print != fingerprint(h.identity))
        throw std::runtime_error(path + " is corrupt (scene fingerprint)");
    if (print != fingerprint(expected.identity)) {
        // Name the first user-settable entry that differs, with the setting that resumes.
        for (const auto& want : expected.identity)
            for (const auto& got : h.identity)
                if (got.key == want.key && got.value != want.value && want.key.find('.') != std::string::npos)
                    throw std::runtime_error(
                        fmt::format("{} was written with {} '{}' (this scene: '{}'); resume with --set {}={}",
                                    path, got.key, got.value, want.value, got.key, got.value));
        throw std::runtime_error(fmt::format("{} belongs to another scene ({}; this scene: {})", path,
                                             describe(h.identity), describe(expected.identity)));
    }
    RunBookkeeping book;
    book.nextSnapshot = readPod<std::int64_t>(in);
    const auto length = readPod<std::uint64_t>(in);
    if (!in) throw std::runtime_error(path + " is truncated");
    const auto blobStart = in.tellg();
    loadEngine(in);
    if (!in || static_cast<std::uint64_t>(in.tellg() - blobStart) != length)
        throw std::runtime_error(
            fmt::format("{} is corrupt or truncated (the engine state is not {} bytes)", path, length));
    return book;
}

}  // namespace granulab::io
