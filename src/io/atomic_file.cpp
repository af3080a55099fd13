// SPDX-License-Identifier: MIT
// Temporary file + rename (io/atomic_file.hpp).
#include "io/atomic_file.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace granulab::io {

AtomicFile::AtomicFile(std::string path) : m_path(std::move(path)), m_tmp(m_path + ".tmp") {
    const std::filesystem::path parent = std::filesystem::path(m_path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    m_out.open(m_tmp, std::ios::binary | std::ios::trunc);
    if (!m_out) throw std::runtime_error("cannot write " + m_tmp);
}

AtomicFile::~AtomicFile() {
    if (m_committed) return;
    m_out.close();
    std::error_code ignored;
    std::filesystem::remove(m_tmp, ignored);
}

void AtomicFile::commit() {
    m_out.close();
    if (!m_out) throw std::runtime_error("write failed: " + m_tmp);
    std::error_code ec;
    std::filesystem::rename(m_tmp, m_path, ec);
    if (ec) throw std::runtime_error("cannot write " + m_path + ": " + ec.message());
    m_committed = true;
}

void writeFileAtomically(const std::string& path, const std::string& text) {
    AtomicFile file(path);
    file.write(text);
    file.commit();
}

}  // namespace granulab::io
