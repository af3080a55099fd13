// SPDX-License-Identifier: MIT
// NumPy .npy writer and reader of the contact records (io/contact_file.hpp). The format is
// NumPy's own (numpy.org "NEP 1: A simple file format for NumPy arrays"): magic "\x93NUMPY",
// version 1.0, a little-endian uint16 header length, a Python dict literal padded with spaces to
// a multiple of 64 bytes ending in '\n', then the packed records.
#include "io/contact_file.hpp"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace granulab::io {

namespace {
static_assert(std::endian::native == std::endian::little, "the .npy writer assumes a little-endian host");

constexpr char kMagic[] = "\x93NUMPY";
constexpr std::size_t kMagicSize = 6;
constexpr std::size_t kRecordBytes = 8 + 8 + 4 + 11 * 8;
constexpr std::array<const char*, 11> kDoubleFields{"px", "py", "nx",    "ny",   "fx",    "fy",
                                                    "fn", "ft", "depth", "area", "length"};

std::string descr() {
    std::string d = "[('a', '<i8'), ('b', '<i8'), ('wall', '<i4')";
    for (const char* f : kDoubleFields) d += fmt::format(", ('{}', '<f8')", f);
    return d + "]";
}

/// The double columns of a frame (const or not) in kDoubleFields order.
template <class Frame>
auto doubleColumns(Frame& c) {
    return std::array{&c.px, &c.py, &c.nx, &c.ny, &c.fx, &c.fy, &c.fn, &c.ft, &c.depth, &c.area, &c.length};
}

template <class T>
void put(std::string& out, T v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}
}  // namespace

std::string contactFileName(int index) {
    return fmt::format("vtk/contacts_{:06d}.npy", index);
}

void writeContactsNpy(const std::string& path, const analysis::ContactFrame& frame) {
    const std::size_t n = frame.size();
    std::string header = fmt::format("{{'descr': {}, 'fortran_order': False, 'shape': ({},), }}", descr(), n);
    const std::size_t unpadded = kMagicSize + 2 + 2 + header.size() + 1;
    header.append((64 - unpadded % 64) % 64, ' ');
    header += '\n';
    std::string out(kMagic, kMagicSize);
    out += '\x01';
    out += '\x00';
    put(out, static_cast<std::uint16_t>(header.size()));
    out += header;
    out.reserve(out.size() + n * kRecordBytes);
    const auto cols = doubleColumns(frame);
    for (std::size_t k = 0; k < n; ++k) {
        put(out, frame.a[k]);
        put(out, frame.b[k]);
        put(out, frame.wall[k]);
        for (const auto* col : cols) put(out, (*col)[k]);
    }
    AtomicFile file(path);
    file.write(out);
    file.commit();
}

analysis::ContactFrame readContactsNpy(const std::string& path) {
    std::ifstream is(path, std::ios::binary);
    if (!is) throw std::runtime_error("cannot open " + path);
    std::ostringstream ss;
    ss << is.rdbuf();
    const std::string text = ss.str();
    const auto fail = [&](const std::string& what) -> void { throw std::runtime_error(path + ": " + what); };
    if (text.size() < kMagicSize + 4 || text.compare(0, kMagicSize, kMagic, kMagicSize) != 0)
        fail("not a NumPy .npy file");
    if (text[kMagicSize] != 1) fail("unsupported .npy format version");
    std::uint16_t headerLen = 0;
    std::memcpy(&headerLen, text.data() + kMagicSize + 2, 2);
    const std::size_t dataStart = kMagicSize + 4 + headerLen;
    if (dataStart > text.size()) fail("truncated header");
    const std::string header = text.substr(kMagicSize + 4, headerLen);
    if (header.find("'descr': " + descr()) == std::string::npos ||
        header.find("'fortran_order': False") == std::string::npos)
        fail("not a granulab contact file (fields differ from " + descr() + ")");
    const auto shape = header.find("'shape': (");
    if (shape == std::string::npos) fail("no shape in the header");
    std::size_t n = 0;
    try {
        n = std::stoull(header.substr(shape + 10));
    } catch (const std::exception&) {
        fail("malformed shape in the header");
    }
    if ((text.size() - dataStart) / kRecordBytes < n || (text.size() - dataStart) != n * kRecordBytes)
        fail(fmt::format("holds {} bytes of records, {} contacts need {}", text.size() - dataStart, n,
                         n * kRecordBytes));
    analysis::ContactFrame c;
    c.a.resize(n);
    c.b.resize(n);
    c.wall.resize(n);
    const auto cols = doubleColumns(c);
    for (auto* col : cols) col->resize(n);
    const char* p = text.data() + dataStart;
    for (std::size_t k = 0; k < n; ++k) {
        std::memcpy(&c.a[k], p, 8);
        std::memcpy(&c.b[k], p + 8, 8);
        std::memcpy(&c.wall[k], p + 16, 4);
        p += 20;
        for (auto* col : cols) {
            std::memcpy(&(*col)[k], p, 8);
            p += 8;
        }
    }
    return c;
}

}  // namespace granulab::io
