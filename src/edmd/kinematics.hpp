// SPDX-License-Identifier: MIT
// Event times and collision rules of hard disks and spheres (edmd spec sections 2.5 and 2.8,
// errata collected in section 9): pure functions on D-dimensional vectors (D = 2 or 3), so one
// code serves disks and spheres. Times in [s], positions [m], velocities [m/s].
#pragma once
#include <cmath>
#include <limits>
#include <utility>

#include "core/types.hpp"

namespace granulab::edmd {

template <int D>
struct VecD {
    Real c[D] = {};
    Real& operator[](int k) noexcept { return c[k]; }
    Real operator[](int k) const noexcept { return c[k]; }
    friend VecD operator+(VecD a, const VecD& b) noexcept {
        for (int k = 0; k < D; ++k) a.c[k] += b.c[k];
        return a;
    }
    friend VecD operator-(VecD a, const VecD& b) noexcept {
        for (int k = 0; k < D; ++k) a.c[k] -= b.c[k];
        return a;
    }
    friend VecD operator*(VecD a, Real s) noexcept {
        for (int k = 0; k < D; ++k) a.c[k] *= s;
        return a;
    }
    friend VecD operator*(Real s, VecD a) noexcept { return a * s; }
    friend Real dot(const VecD& a, const VecD& b) noexcept {
        Real s = 0;
        for (int k = 0; k < D; ++k) s += a.c[k] * b.c[k];
        return s;
    }
};
using Vec3 = VecD<3>;

inline constexpr Real kNoEvent = std::numeric_limits<Real>::infinity();

/// Free flight over dt [s] (edmd spec 2.5.1, Eq. 2.2-2.4): the position [m] of a particle at x
/// with velocity v [m/s] after dt, on a straight line.
[[gnu::always_inline]] inline Real flightPosition(Real x, Real v, Real dt) noexcept {
    return x + v * dt;
}

/// Same under uniform gravity g [m/s^2] (a parabola): x + v dt + g dt^2/2, evaluated in exactly
/// this order, (x + v dt) + ((g/2) dt) dt; the engine's checkpoints and regression runs depend on
/// the rounding, so keep the expression as it is.
[[gnu::always_inline]] inline Real flightPosition(Real x, Real v, Real g, Real dt) noexcept {
    return x + v * dt + 0.5 * g * dt * dt;
}

/// Velocity [m/s] after a free flight of dt [s] under gravity g [m/s^2]: v + g dt.
[[gnu::always_inline]] inline Real flightVelocity(Real v, Real g, Real dt) noexcept {
    return v + g * dt;
}

/// The free flight of a whole particle over dt [s], componentwise as above: x [m] and v [m/s]
/// are replaced by their values after dt. Without Gravity (g ignored) the velocity is unchanged
/// and the position moves on a straight line.
template <bool Gravity, int D>
[[gnu::always_inline]] inline void freeFlight(VecD<D>& x, VecD<D>& v, const VecD<D>& g, Real dt) noexcept {
    for (int k = 0; k < D; ++k) {
        if constexpr (Gravity) {
            x[k] = flightPosition(x[k], v[k], g[k], dt);
            v[k] = flightVelocity(v[k], g[k], dt);
        } else {
            x[k] = flightPosition(x[k], v[k], dt);
        }
    }
}

/// Time until two spheres at relative position r12 = r1 - r2 with relative velocity v12 touch at
/// contact distance s = a1 + a2 (edmd Eq. 2.18-2.19, robust form of spec 2.8): +inf if they
/// separate or miss; 0 if they already overlap by round-off while approaching.
template <int D>
[[gnu::always_inline]] inline Real pairCollisionTime(const VecD<D>& r12, const VecD<D>& v12,
                                                     Real s) noexcept {
    const Real b = dot(r12, v12);
    if (!(b < 0)) return kNoEvent;  // separating (also the pair that has just collided)
    const Real v2 = dot(v12, v12);
    const Real c = dot(r12, r12) - s * s;
    if (c <= 0) return 0;  // touching or overlapping by round-off, approaching: now
    const Real disc = b * b - v2 * c;
    if (!(disc >= 0)) return kNoEvent;
    return c / (-b + std::sqrt(disc));  // the smaller root without cancellation
}

/// Same for spheres whose contact distance grows as s(t) = s + us t (growing spheres, edmd
/// Eq. 2.20-2.21; us = u_a1 + u_a2): smallest non-negative root of (r12 + t v12)^2 = (s + us t)^2.
template <int D>
Real growingPairCollisionTime(const VecD<D>& r12, const VecD<D>& v12, Real s, Real us) noexcept {
    const Real A = dot(v12, v12) - us * us;
    const Real B = dot(r12, v12) - s * us;  // half the linear coefficient
    const Real C = dot(r12, r12) - s * s;
    if (C <= 0) return B < 0 ? 0 : kNoEvent;  // in contact: collide now if the gap closes
    if (A == 0) return B < 0 ? -C / (2 * B) : kNoEvent;
    const Real disc = B * B - A * C;
    if (!(disc >= 0)) return kNoEvent;
    const Real q = -(B + std::copysign(std::sqrt(disc), B));  // stable pair of roots: q/A, C/q
    Real t1 = q / A, t2 = q != 0 ? C / q : kNoEvent;
    if (t1 > t2) std::swap(t1, t2);
    // A root is a contact only while the contact distance is positive: (r + v t)^2 = s(t)^2
    // also holds where the distance equals -s(t) (a shrinking pair "meeting" past zero size).
    for (const Real t : {t1, t2})
        if (t >= 0 && s + us * t > 0) return t;
    return kNoEvent;
}

/// Time until a particle moving with x(t) = x + v t + g t^2 / 2 along a wall normal reaches the
/// plane coordinate `target` from below (x < target, edmd Eq. 2.22-2.25 projected on the
/// normal): the smallest positive root; +inf if never. For the cell crossings and for plane
/// walls (target = wall - a).
inline Real firstPassage(Real x, Real v, Real g, Real target) noexcept {
    const Real d = target - x;  // >= 0
    if (g == 0) return v > 0 ? d / v : (d <= 0 && v >= 0 ? 0 : kNoEvent);
    // g t^2/2 + v t - d = 0
    const Real disc = v * v + 2 * g * d;
    if (!(disc >= 0)) return kNoEvent;  // decelerates and turns back before the plane
    const Real sq = std::sqrt(disc);
    const Real q = -0.5 * (v + std::copysign(sq, v));  // roots q/(g/2) and -d/q
    Real t1 = q / (0.5 * g), t2 = q != 0 ? -d / q : kNoEvent;
    if (t1 > t2) std::swap(t1, t2);
    if (t1 > 0) return t1;
    return t2 > 0 ? t2 : (d <= 0 && v >= 0 ? 0 : kNoEvent);
}

/// Time until a gap s [m] closes when it shrinks with speed u [m/s] (u > 0: closing) and
/// acceleration gw [m/s^2] (gw > 0: towards closing): the smallest t > 0 with
/// s = u t + gw t^2 / 2 (edmd Eq. 2.22-2.25 along the plane normal), +inf if never. A gap that
/// is already closed by round-off (s <= 0) closes now if it is still closing, else when gravity
/// brings it back. Every positive root has the cancellation-free form 2 s / (u + sqrt(u^2 +
/// 2 gw s)). Used for cell faces (s = distance to the face) and walls (s = distance - a).
[[gnu::always_inline]] inline Real closingTime(Real s, Real u, Real gw) noexcept {
    if (!(s > 0)) {
        if (u > 0 || (u == 0 && gw > 0)) return 0;
        return gw > 0 ? -2 * u / gw : kNoEvent;
    }
    if (gw == 0) return u > 0 ? s / u : kNoEvent;
    const Real disc = u * u + 2 * gw * s;
    if (!(disc >= 0) || (gw < 0 && u <= 0)) return kNoEvent;  // turns back before the plane
    return 2 * s / (u + std::sqrt(disc));
}

/// Smooth inelastic collision with normal restitution eps (edmd Eq. 4.6, with masses for
/// polydisperse systems): unit normal k = (r1 - r2)/|r1 - r2|; only the normal relative
/// velocity changes, momentum is conserved, energy loss m_red/2 (1 - eps^2) v_n^2.
template <int D>
void smoothCollision(VecD<D>& v1, VecD<D>& v2, Real m1, Real m2, const VecD<D>& k, Real eps) noexcept {
    const Real vn = dot(v1 - v2, k);                        // < 0 when approaching
    const Real j = (1 + eps) * vn * (m1 * m2 / (m1 + m2));  // impulse magnitude along -k on 1
    v1 = v1 - k * (j / m1);
    v2 = v2 + k * (j / m2);
}

inline Vec3 crossProduct(const Vec3& a, const Vec3& b) noexcept {
    return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

/// Rough inelastic collision of two equal spheres (or disks), edmd Eq. 2.6-2.8 with the
/// errata of spec 2.5.2: k = (r1 - r2)/|r1 - r2| points from particle 2 to particle 1,
/// z = I/(m a^2) (0.4 solid sphere, 0.5 solid disk), phi tangential restitution (-1 smooth,
/// +1 perfectly rough). Disks: z-components only (w = (0, 0, omega)).
inline void roughCollision(Vec3& v1, Vec3& v2, Vec3& w1, Vec3& w2, const Vec3& k, Real a, Real eps, Real phi,
                           Real z) noexcept {
    const Vec3 v12 = v1 - v2;
    const Vec3 vn = k * dot(v12, k);
    const Vec3 vt = v12 - vn;
    const Vec3 vr = crossProduct(k, w1 + w2) * a;
    const Vec3 u = vt + vr;  // tangential velocity of the contact points (eq. 2.7 with k from 2 to 1)
    const Real ct = z * (1 + phi) / (2 * z + 2);
    const Vec3 dv = vn * ((1 + eps) / 2) + u * ct;
    v1 = v1 - dv;
    v2 = v2 + dv;
    const Vec3 dw = crossProduct(k, u) * ((1 + phi) / (a * (2 * z + 2)));
    w1 = w1 + dw;  // same sign for both (spec 2.5.2)
    w2 = w2 + dw;
}

/// Rough inelastic collision of two spheres of any radii a1, a2, masses m1, m2 and moments of
/// inertia I = z m a^2 (edmd Eq. 2.6-2.8 generalised; reduces to roughCollision for equal
/// spheres). k = (r1 - r2)/|r1 - r2|; the contact-point relative velocity
/// g = v12 + k x (a1 w1 + a2 w2) has its normal part reversed with eps and its tangential part
/// with phi: the tangential impulse is -(1 + phi) m_t g_t with 1/m_t = 1/m1 + 1/m2 +
/// a1^2/I1 + a2^2/I2. normalImpulse [kg m/s] is the normal impulse on particle 1 along k
/// (computed by the caller, so that speed-dependent restitution and growing spheres enter
/// there). Disks: vectors in the plane (z = 0), spins along z.
inline void roughCollisionGeneral(Vec3& v1, Vec3& v2, Vec3& w1, Vec3& w2, const Vec3& k, Real a1, Real a2,
                                  Real m1, Real m2, Real z, Real normalImpulse, Real phi) noexcept {
    const Vec3 v12 = v1 - v2;
    const Vec3 g = v12 + crossProduct(k, w1 * a1 + w2 * a2);
    const Vec3 gt = g - k * dot(g, k);
    const Real invMt = 1 / m1 + 1 / m2 + 1 / (z * m1) + 1 / (z * m2);
    const Vec3 jt = gt * (-(1 + phi) / invMt);
    const Vec3 j = k * normalImpulse + jt;
    v1 = v1 + j * (1 / m1);
    v2 = v2 - j * (1 / m2);
    const Vec3 kxj = crossProduct(k, jt);
    w1 = w1 - kxj * (1 / (z * m1 * a1));  // torque (-a1 k) x J over I1 = z m1 a1^2
    w2 = w2 - kxj * (1 / (z * m2 * a2));
}

}  // namespace granulab::edmd
