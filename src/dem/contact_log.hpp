// SPDX-License-Identifier: MIT
// The contact records of one force evaluation (gc2d spec section 7, "per force: application
// point, vector and the bodies it acts on"), collected by the contact kernels only when the World
// is asked to (the steps that end at a snapshot), so the hot loop pays one predictable branch per
// touching contact. Body forces (gravity, damping, springs) are not contacts and are not recorded.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "geom/circle_contact.hpp"

namespace granulab::dem {

/// One contact as the law evaluated it. Ids are global particle ids (slots change when particles
/// are re-sorted or leave at the end of the step).
struct ContactRecord {
    ParticleId a = 0;   ///< first body (a grain)
    ParticleId b = 0;   ///< second grain; unused at a wall
    std::int32_t wall;  ///< wall index, -1 for a grain pair
    Vec2 point;         ///< [m] where the force acts (area law: middle of the contact line)
    Vec2 normal;        ///< unit normal from a toward b
    Vec2 force;         ///< [N] force on a (b gets the opposite at the same point)
    Real depth = 0;     ///< [m] overlap depth (area law: A / l)
    Real area = 0;      ///< [m^2] overlap area
    Real length = 0;    ///< [m] contact line length
};

struct ContactLog {
    std::vector<ContactRecord> records;
    std::int64_t step = -1;  ///< step whose force evaluation the records are (-1: none)

    void clear(std::int64_t atStep) {
        records.clear();
        step = atStep;
    }

    /// A disk-disk contact of the overlap-depth laws: centres ci, cj [m], radii [m], unit normal
    /// n from i to j, force on i [N]. Point: the middle of the overlap on the line of centres.
    void addDiskPair(ParticleId a, ParticleId b, Vec2 ci, Real ri, Vec2 cj, Real rj, Vec2 n, Vec2 force) {
        const geom::AreaContact lens = geom::circleCircleContact(ci, ri, cj, rj);
        const Real depth = ri + rj - norm(cj - ci);
        records.push_back(
            {a, b, -1, ci + n * (ri - 0.5 * depth), n, force, depth, lens.area, norm(lens.c2 - lens.c1)});
    }

    /// A disk-wall contact: centre c [m], radius r [m], overlap depth [m], unit normal n from the
    /// disk toward the wall, force on the disk [N]. Area: the circular segment cut off by the wall line.
    void addDiskWall(ParticleId a, std::int32_t wall, Vec2 c, Real r, Real depth, Vec2 n, Vec2 force) {
        const Real d = r - depth;  // [m] centre to wall line
        const Real half = std::sqrt(std::max<Real>(r * r - d * d, 0));
        const Real x = 2 * std::acos(std::clamp<Real>(d / r, -1, 1));  // central angle of the segment
        // r^2 (x - sin x) / 2; the series avoids cancellation for shallow segments.
        const Real xMinusSin =
            x < 0.1 ? x * x * x / 6 * (1 - x * x / 20 * (1 - x * x / 42)) : x - std::sin(x);
        records.push_back(
            {a, 0, wall, c + n * (r - 0.5 * depth), n, force, depth, 0.5 * r * r * xMinusSin, 2 * half});
    }

    /// An area-law contact (pair or wall): contact point, normal from a toward b, area [m^2],
    /// effective depth A / l [m], contact line length [m].
    void addArea(ParticleId a, ParticleId b, std::int32_t wall, Vec2 point, Vec2 n, Vec2 force, Real depth,
                 Real area, Real length) {
        records.push_back({a, b, wall, point, n, force, depth, area, length});
    }
};

}  // namespace granulab::dem
