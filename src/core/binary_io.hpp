// SPDX-License-Identifier: MIT
// Raw little-endian binary (de)serialisation of scalars and vectors, for checkpoints that
// restore state bit for bit.
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

template <class T>
void writeVector(std::ostream& os, const std::vector<T>& v) {
    writePod<std::uint64_t>(os, v.size());
    os.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}

template <class T>
void readVector(std::istream& is, std::vector<T>& v) {
    const auto n = readPod<std::uint64_t>(is);
    if (n > (std::uint64_t{1} << 40)) throw std::runtime_error("checkpoint corrupt (vector size)");
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
    std::string s(n, '\0');
    is.read(s.data(), static_cast<std::streamsize>(n));
    if (!is) throw std::runtime_error("checkpoint truncated");
    return s;
}

}  // namespace granulab
