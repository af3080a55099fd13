// SPDX-License-Identifier: MIT
// Checkpoint container (io/checkpoint.hpp): header, identity check, engine blob with its length,
// checksum. Writing streams every byte through a hashing buffer (no second copy of the state in
// memory); reading checks the checksum in a first pass over the file, then parses it.
#include "io/checkpoint.hpp"

#include <fmt/format.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>
#include <streambuf>

#include "core/binary_io.hpp"
#include "io/atomic_file.hpp"

namespace granulab::io {

namespace {
constexpr std::uint64_t kMagic = 0x544b434c42414e47ULL;         // "GNABLCKT"
constexpr std::uint64_t kOldEdmdMagic = 0x31444d4445424c47ULL;  // "GLBEDMD1": edmd files before version 5
constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ULL;     // 64-bit FNV-1a (Fowler, Noll, Vo)
constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;
constexpr std::uint64_t kTrailerBytes = 16;  // blob length + checksum

std::uint64_t fnv1a(std::uint64_t h, const char* bytes, std::size_t n) noexcept {
    for (std::size_t k = 0; k < n; ++k) h = (h ^ static_cast<unsigned char>(bytes[k])) * kFnvPrime;
    return h;
}

/// Passes every byte on to `target`, hashing and counting it.
class HashingBuf final : public std::streambuf {
public:
    explicit HashingBuf(std::streambuf* target) : m_target(target) {}
    std::uint64_t hash() const noexcept { return m_hash; }
    std::uint64_t bytes() const noexcept { return m_bytes; }

protected:
    int_type overflow(int_type c) override {
        if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
        const char ch = traits_type::to_char_type(c);
        return xsputn(&ch, 1) == 1 ? c : traits_type::eof();
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        m_hash = fnv1a(m_hash, s, static_cast<std::size_t>(n));
        m_bytes += static_cast<std::uint64_t>(n);
        return m_target->sputn(s, n);
    }

private:
    std::streambuf* m_target;
    std::uint64_t m_hash = kFnvOffset;
    std::uint64_t m_bytes = 0;
};

/// Checks the checksum of the `size`-byte file open in `in`: 64-bit FNV-1a over all bytes but
/// the last 8, which hold it.
void checkChecksum(std::istream& in, std::uint64_t size, const std::string& path) {
    in.seekg(0);
    std::uint64_t h = kFnvOffset;
    std::array<char, 1 << 16> chunk{};
    for (std::uint64_t left = size - 8; left > 0;) {
        const auto n = static_cast<std::streamsize>(std::min<std::uint64_t>(left, chunk.size()));
        in.read(chunk.data(), n);
        if (!in) throw std::runtime_error(path + " cannot be read");
        h = fnv1a(h, chunk.data(), static_cast<std::size_t>(n));
        left -= static_cast<std::uint64_t>(n);
    }
    const auto stored = readPod<std::uint64_t>(in);
    if (stored != h)
        throw std::runtime_error(fmt::format(
            "{} is damaged: checksum mismatch (stored {:016x}, computed {:016x}; the file was changed "
            "or cut after it was written); rerun the scene without --resume, or resume from a good copy",
            path, stored, h));
}

std::string describe(const SceneIdentity& id) {
    std::string s;
    for (const auto& e : id) s += fmt::format("{}{} {}", s.empty() ? "" : ", ", e.key, e.value);
    return s;
}
}  // namespace

std::uint64_t fingerprint(const SceneIdentity& identity) {
    std::uint64_t h = kFnvOffset;
    const auto mix = [&](const std::string& s) {
        h = fnv1a(h, s.data(), s.size());
        h = (h ^ 0xffu) * kFnvPrime;  // separator
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
    HashingBuf hashing(file.stream().rdbuf());
    std::ostream out(&hashing);
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
    const std::uint64_t blobStart = hashing.bytes();
    saveEngine(out);
    writePod<std::uint64_t>(out, hashing.bytes() - blobStart);
    out.flush();
    if (!out) throw std::runtime_error("write failed: " + dir + "/checkpoint.bin");
    writePod(file.stream(), hashing.hash());  // the checksum itself is not hashed
    file.commit();
}

RunBookkeeping readCheckpoint(const std::string& dir, const CheckpointHeader& expected,
                              const std::function<void(std::istream&)>& loadEngine) {
    const std::string path = dir + "/checkpoint.bin";
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(fmt::format("no checkpoint at {} (run without --resume first)", path));
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    constexpr std::uint64_t kHeaderBytes = 12;  // magic + version
    if (ec || size < 8) throw std::runtime_error(path + " is not a granulab checkpoint (too short)");
    const auto magic = readPod<std::uint64_t>(in);
    if (magic == kOldEdmdMagic)
        throw std::runtime_error(
            fmt::format("{} is an edmd checkpoint of format version 1 (unversioned, before granulab "
                        "checkpoints had one container); this build reads version {}: rerun the scene "
                        "without --resume",
                        path, kCheckpointVersion));
    if (magic != kMagic) throw std::runtime_error(path + " is not a granulab checkpoint");
    if (size < kHeaderBytes + kTrailerBytes)
        throw std::runtime_error(fmt::format("{} is damaged: truncated ({} bytes)", path, size));
    if (const auto v = readPod<std::uint32_t>(in); v != kCheckpointVersion)
        throw std::runtime_error(
            fmt::format("{} has format version {}, this build reads version {}: rerun the scene "
                        "without --resume (or with the granulab version that wrote it)",
                        path, v, kCheckpointVersion));
    checkChecksum(in, size, path);
    in.seekg(static_cast<std::streamoff>(kHeaderBytes));
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
    const auto blobStart = static_cast<std::uint64_t>(in.tellg());
    if (!in || blobStart + kTrailerBytes > size) throw std::runtime_error(path + " is truncated");
    const std::uint64_t length = size - kTrailerBytes - blobStart;
    in.seekg(static_cast<std::streamoff>(size - kTrailerBytes));
    if (readPod<std::uint64_t>(in) != length)
        throw std::runtime_error(fmt::format("{} is corrupt (blob length)", path));
    in.seekg(static_cast<std::streamoff>(blobStart));
    try {
        loadEngine(in);
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(path + " is corrupt (the engine state does not fit in memory)");
    } catch (const std::exception& e) {
        throw std::runtime_error(fmt::format("{} cannot be resumed: {}", path, e.what()));
    }
    if (!in || static_cast<std::uint64_t>(in.tellg()) - blobStart != length)
        throw std::runtime_error(
            fmt::format("{} is corrupt or truncated (the engine state is not {} bytes)", path, length));
    return book;
}

}  // namespace granulab::io
