// SPDX-License-Identifier: MIT
// Raw little-endian binary (de)serialisation of scalars and vectors, for checkpoints that
// restore state bit for bit. Readers throw std::runtime_error on a truncated stream or a length
// that does not fit the rest of it (never allocate for a damaged length).
#pragma once
#include <cstdint>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace granulab {

template <class T>
void writePod(std::ostream& os, const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    os.write(reinterpret_cast<const char*>(&v), sizeof(T));
}

template <class T>
T readPod(std::istream& is) {
    static_assert(std::is_trivially_copyable_v<T>);
    T v{};
    is.read(reinterpret_cast<char*>(&v), sizeof(T));
    if (!is) throw std::runtime_error("checkpoint truncated");
    return v;
}

/// Bytes left in `is` after the read position (the maximum when the stream cannot seek).
inline std::uint64_t bytesLeft(std::istream& is) {
    const auto here = is.tellg();
    if (here < 0) return ~std::uint64_t{0};
    is.seekg(0, std::ios::end);
    const auto end = is.tellg();
    is.seekg(here);
    return end >= here ? static_cast<std::uint64_t>(end - here) : ~std::uint64_t{0};
}

/// Throws when `n` elements of `size` bytes cannot follow in `is`: a damaged length is refused
/// before anything is allocated for it.
inline void checkElementsFit(std::istream& is, std::uint64_t n, std::size_t size) {
    if (n > (std::uint64_t{1} << 40) || n * size > bytesLeft(is))
        throw std::runtime_error("checkpoint corrupt or truncated (a length exceeds the file)");
}

template <class T>
void writeVector(std::ostream& os, const std::vector<T>& v) {
    writePod<std::uint64_t>(os, v.size());
    os.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}

template <class T>
void readVector(std::istream& is, std::vector<T>& v) {
    const auto n = readPod<std::uint64_t>(is);
    checkElementsFit(is, n, sizeof(T));
    v.resize(n);
    is.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
    if (!is) throw std::runtime_error("checkpoint truncated");
}

inline void writeString(std::ostream& os, const std::string& s) {
    writePod<std::uint64_t>(os, s.size());
    os.write(s.data(), static_cast<std::streamsize>(s.size()));
}

inline std::string readString(std::istream& is) {
    const auto n = readPod<std::uint64_t>(is);
    if (n > (1u << 20)) throw std::runtime_error("checkpoint corrupt (string size)");
    checkElementsFit(is, n, 1);
    std::string s(n, '\0');
    is.read(s.data(), static_cast<std::streamsize>(n));
    if (!is) throw std::runtime_error("checkpoint truncated");
    return s;
}

}  // namespace granulab
