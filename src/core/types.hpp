// SPDX-License-Identifier: MIT
// Basic numeric types and the 2D vector used by every layer (DESIGN.md "core").
#pragma once
#include <cmath>
#include <cstdint>

namespace granulab {

/// Floating-point type of all physical quantities (SI units unless a comment says otherwise).
using Real = double;

/// Stable particle identifier; survives slot reordering, checkpoints and resumes.
using ParticleId = std::uint32_t;

inline constexpr Real kPi = 3.141592653589793238462643383279502884;

/// 2D vector [m], [m/s], [N] ... (units follow the quantity it holds).
struct Vec2 {
    Real x = 0;
    Real y = 0;

    constexpr Vec2 operator+(Vec2 o) const noexcept { return {x + o.x, y + o.y}; }
    constexpr Vec2 operator-(Vec2 o) const noexcept { return {x - o.x, y - o.y}; }
    constexpr Vec2 operator-() const noexcept { return {-x, -y}; }
    constexpr Vec2 operator*(Real s) const noexcept { return {x * s, y * s}; }
    constexpr Vec2 operator/(Real s) const noexcept { return {x / s, y / s}; }
    constexpr Vec2& operator+=(Vec2 o) noexcept {
        x += o.x;
        y += o.y;
        return *this;
    }
    constexpr Vec2& operator-=(Vec2 o) noexcept {
        x -= o.x;
        y -= o.y;
        return *this;
    }
    constexpr bool operator==(const Vec2&) const = default;
};

constexpr Vec2 operator*(Real s, Vec2 v) noexcept {
    return v * s;
}
constexpr Real dot(Vec2 a, Vec2 b) noexcept {
    return a.x * b.x + a.y * b.y;
}
/// z-component of the 3D cross product (a,0) x (b,0).
constexpr Real cross(Vec2 a, Vec2 b) noexcept {
    return a.x * b.y - a.y * b.x;
}
/// Perpendicular rotated +90 degrees: z x a.
constexpr Vec2 perp(Vec2 a) noexcept {
    return {-a.y, a.x};
}
inline Real norm(Vec2 a) noexcept {
    return std::sqrt(dot(a, a));
}
constexpr Real norm2(Vec2 a) noexcept {
    return dot(a, a);
}

}  // namespace granulab
