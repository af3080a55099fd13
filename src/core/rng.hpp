// SPDX-License-Identifier: MIT
// Counter-based random numbers (STYLE.md (d): all randomness from (seed, stream, counter), never
// from hidden state), so that a scene gives the same particles on every machine and every resume.
#pragma once
#include <cmath>
#include <cstdint>

#include "core/types.hpp"

namespace granulab {

/// SplitMix64 finaliser: a bijective 64-bit mixer (Steele, Lea, Flood 2014).
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// Deterministic stream of uniform and normal variates. The state is (key, counter); two
/// streams with different (seed, streamId) are independent for all practical purposes.
class CounterRng {
public:
    CounterRng(std::uint64_t seed, std::uint64_t streamId) noexcept
        : m_key(mix64(seed ^ mix64(streamId + 0x632be59bd9b4e019ULL))) {}

    std::uint64_t nextU64() noexcept { return mix64(m_key + mix64(m_counter++)); }

    /// Uniform in [0, 1) with 53 random bits.
    Real uniform() noexcept { return static_cast<Real>(nextU64() >> 11) * 0x1.0p-53; }
    Real uniform(Real lo, Real hi) noexcept { return lo + (hi - lo) * uniform(); }

    /// Standard normal variate (Box-Muller; both draws consumed, so the stream stays simple).
    Real normal() noexcept {
        Real u1 = uniform();
        Real u2 = uniform();
        if (u1 < 1e-300) u1 = 1e-300;
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
    }

    std::uint64_t counter() const noexcept { return m_counter; }

private:
    std::uint64_t m_key;
    std::uint64_t m_counter = 0;
};

}  // namespace granulab
