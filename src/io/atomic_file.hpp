// SPDX-License-Identifier: MIT
// The one way granulab writes an output file (DESIGN.md "Contract"): into a temporary name next
// to it, renamed into place when complete, so that an interrupted run never leaves a half-written
// file under a final name.
#pragma once
#include <fstream>
#include <string>

namespace granulab::io {

/// A file written under `path`.tmp and renamed to `path` by commit(). Destroyed uncommitted
/// (an exception on the way), it removes the temporary and leaves `path` as it was.
class AtomicFile {
public:
    /// Opens `path`.tmp for writing (binary, truncated); creates the parent folder. Throws
    /// std::runtime_error naming the file when it cannot.
    explicit AtomicFile(std::string path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// The open temporary file (binary; seekable, e.g. to patch a length written before).
    std::ostream& stream() noexcept { return m_out; }
    void write(const std::string& text) {
        m_out.write(text.data(), static_cast<std::streamsize>(text.size()));
    }
    /// Closes, checks for write errors and renames into place; throws std::runtime_error.
    void commit();

private:
    std::string m_path, m_tmp;
    std::ofstream m_out;
    bool m_committed = false;
};

/// Writes `text` to `path` through AtomicFile.
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace granulab::io
