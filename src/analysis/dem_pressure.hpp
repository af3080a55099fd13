// SPDX-License-Identifier: MIT
// Wall and floor pressure of a DEM snapshot (gc2d spec section 7 items 1-2, Eqs. 2.36-2.40; used
// for the sandpile floor profiles of section 8.4-8.5): the mean pressure on a wall, the local
// pressure profile along a straight wall with windows of width 2b, and the pile scale (height,
// foot) that normalises the profile. 2D: forces are [N] per metre of depth, pressures [N/m].
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// Which walls form "the wall" (several indices are summed as one wall, e.g. a floor built of
/// several [[wall]] entries).
struct WallPressureParams {
    std::vector<std::int32_t> walls;  ///< wall indices of the scene (ContactFrame::wall)
    /// Unit normal pointing toward the grains; zero = from the contact normals (dem_geometry.hpp).
    Vec2 inwardNormal{};
};

/// Mean pressure on a wall (gc2d Eq. 2.36/2.37).
struct WallPressure {
    Vec2 force{};           ///< [N] force the grains exert on the wall: -sum of the forces on the grains
    Real length = 0;        ///< [m] total length of the wall's segments
    Vec2 forcePerLength{};  ///< [N/m] force / length, per component (the only answer for a bent wall)
    bool straight = false;  ///< all segments parallel
    Vec2 normal{};          ///< unit inward normal (toward the grains); NaN for a bent wall
    /// [N/m] (1/l) sum_i n_in . F_i, F_i the force on the grain (Eq. 2.36 with n_in = (0, 1) for a
    /// floor, Eq. 2.37 with n_in = (+-1, 0) for a side wall): > 0 when the grains push; NaN if bent.
    Real pressure = 0;
    /// [N/m] (1/l) sum_i fn_i: the normal force of every contact along its own contact normal;
    /// defined for any wall shape and equal to `pressure` on a straight wall for disks on its face.
    Real normalPressure = 0;
    std::size_t contacts = 0;  ///< contacts with the wall
};

/// Sums the contacts whose wall index is in params.walls. Throws std::invalid_argument for an
/// empty selection, a wall without segments, or zero length. Cost O(contacts * walls + segments).
WallPressure wallPressure(const ContactFrame& contacts, const WallSegments& segments,
                          const WallPressureParams& params);

/// One-row table (default name "wall_mean_pressure"): Fx, Fy [N] on the wall, l [m], Fx/l, Fy/l,
/// p, p_n [N/m], contacts [1].
Table toTable(const WallPressure& result, std::string name = "wall_mean_pressure");

/// Scale of a pile for the thesis' normalised plots (x/d, p/(rho g h)).
struct PileScale {
    Real rho = 0;  ///< [kg/m^2] areal bulk density
    Real g = 0;    ///< [m/s^2] gravitational acceleration (magnitude)
    Real h = 0;    ///< [m] pile height above the wall
    Real x0 = 0;   ///< [m] foot of the pile, start (wall coordinate, see PressureProfile::x)
    Real x1 = 0;   ///< [m] foot of the pile, end; d = x1 - x0
};

/// Local pressure profile settings (Eqs. 2.38-2.40).
struct PressureProfileParams {
    std::vector<std::int32_t> walls;  ///< the (straight) wall: wall indices with parallel segments
    Real halfWidth = 0;               ///< [m] b: a window is [x - b, x + b] (> 0)
    Real step = 0;                    ///< [m] distance of window centres (> 0; < 2b overlaps)
    /// [m] first and last window centre along the wall coordinate; default the wall's extent.
    std::optional<Real> from, to;
    std::size_t movingAverage = 5;   ///< M, odd >= 1: the moving average spans M windows centred on each
    std::size_t minContacts = 10;    ///< windows holding fewer contacts are counted in the warning
    Vec2 inwardNormal{};             ///< as WallPressureParams::inwardNormal
    std::optional<PileScale> scale;  ///< adds x/d and p/(rho g h) when set
};

/// p(x) along a wall.
struct PressureProfile {
    /// [m] window centres along the wall coordinate x = dot(point, t), t the wall direction with its
    /// largest component positive: x for a floor, y for a side wall.
    std::vector<Real> x;
    std::vector<Real> p;                  ///< [N/m] (1/2b) sum n_in . F_i over the window (Eq. 2.38)
    std::vector<Real> pAverage;           ///< [N/m] moving average of p over M windows (fewer at the ends)
    std::vector<std::size_t> contacts;    ///< contacts per window
    std::vector<Real> xOverD;             ///< (x - x0)/d, empty without scale
    std::vector<Real> pOverRhoGH;         ///< p/(rho g h), empty without scale
    std::vector<Real> pAverageOverRhoGH;  ///< p_avg/(rho g h), empty without scale
    Vec2 tangent{}, normal{};             ///< wall direction and inward normal (unit)
    Real halfWidth = 0, step = 0;         ///< [m]
    std::size_t movingAverage = 1;        ///< M
    std::size_t sparseWindows = 0;        ///< windows with fewer than minContacts contacts
    std::optional<PileScale> scale;
    std::vector<std::string> notes;  ///< warnings (sparse windows, no contacts)
};

/// Eq. 2.38: windows of width 2b at from, from + step, ... <= to; a contact counts in a window
/// when x - b <= x_contact <= x + b. Throws std::invalid_argument for bad parameters (b, step <= 0,
/// even or zero M, from > to, more than 1e7 windows, a bent wall, a scale with rho, g, h or d
/// <= 0). Cost O(C log C + windows).
PressureProfile pressureProfile(const ContactFrame& contacts, const WallSegments& segments,
                                const PressureProfileParams& params);

/// Table with columns x [m], p [N/m], p_avg [N/m], contacts [1] and, with a scale, x/d [1] and
/// p/(rho g h) [1]; notes: the window settings, the scale and the warnings. Name: "floor_pressure"
/// for the floor, "wall_pressure" otherwise (the caller chooses).
Table toTable(const PressureProfile& profile, std::string name = "floor_pressure");

/// Measures h and the foot [x0, x1] of a pile standing on the straight wall `walls`: h = the
/// largest reach of a grain along the inward normal (highest grain top over a floor) minus the
/// wall's level; the foot = the extent along the wall coordinate of the grains (their outlines,
/// not their centres) that touch the wall, or of all grains when allGrains. Contacts naming an id
/// missing from `grains` are skipped. Where the data has no answer the fields are NaN (h without
/// grains; x0 and x1 when no grain touches the wall). Throws std::invalid_argument for a bent wall
/// or rho, g <= 0.
PileScale measurePileScale(const GrainFrame& grains, const ContactFrame& contacts,
                           const WallSegments& segments, const std::vector<std::int32_t>& walls, Real rho,
                           Real g, bool allGrains = false);

}  // namespace granulab::analysis
