// SPDX-License-Identifier: MIT
// Free surface of a pile and its angle of repose (gc2d spec section 7 item 5; the sandpile and
// draining-crater slopes of section 8.4-8.8): the surface profile h(x) in x-bins, the angle from
// straight-line fits to both flanks (top-centroid method, 5a) and from the area of a half-pile
// (integral method, 5b: tan phi = 2a/b^2).
#pragma once
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// What h(x) of a bin is.
enum class SurfaceHeight {
    Centroid,  ///< highest grain centre in the bin (spec 5a: 10-20 times faster, a constant offset)
    Top,  ///< highest grain point (disk: y + r, polygon: highest corner) of the grains centred in the bin
};

struct SurfaceParams {
    Real binWidth = 0;         ///< [m] (> 0); about one grain diameter
    std::optional<Real> xMin;  ///< [m] left end of the first bin; default the smallest grain centre x
    std::optional<Real> xMax;  ///< [m] right end of the last bin; default the largest grain centre x
    SurfaceHeight height = SurfaceHeight::Centroid;
};

/// h(x): a grain belongs to the bin of its centre x; empty bins have h = NaN.
struct SurfaceProfile {
    std::vector<Real> x;              ///< [m] bin centres
    std::vector<Real> h;              ///< [m] surface height per bin (NaN when empty)
    std::vector<std::size_t> grains;  ///< grains per bin
    Real binWidth = 0;                ///< [m]
    Real meanRadius = 0;              ///< [m] mean grain radius of the binned grains
    SurfaceHeight height = SurfaceHeight::Centroid;
};

/// Bins [xMin + i w, xMin + (i + 1) w), i < ceil((xMax - xMin)/w) (at least 1; a centre at xMax goes
/// into the last bin; grains outside [xMin, xMax] are ignored). Throws std::invalid_argument for
/// binWidth <= 0, xMin > xMax or more than 1e7 bins. No grains: one empty bin. Cost O(N).
SurfaceProfile surfaceProfile(const GrainFrame& grains, const SurfaceParams& params);

/// Least-squares line h = slope x + intercept over some bins.
struct LineFit {
    Real slope = 0;      ///< [1]
    Real intercept = 0;  ///< [m]
    Real xFrom = 0;      ///< [m] first and last bin centre used
    Real xTo = 0;
    std::size_t points = 0;  ///< bins used
    Real angle = 0;          ///< [rad] atan|slope|
    Real angleDeg = 0;       ///< [deg]
};

/// Integral method on one half-pile (spec 5b).
struct IntegralRepose {
    Real xFrom = 0, xTo = 0;  ///< [m] first and last non-empty bin centre used
    Real base = 0;            ///< [m] b = xTo - xFrom
    Real level = 0;           ///< [m] h0: the lowest h in the range (the foot as the profile sees it)
    Real rise = 0;            ///< [m] highest minus lowest h in the range
    Real area = 0;            ///< [m^2] a = integral of (h - h0) dx (trapezoids between bin centres)
    Real tanPhi = 0;          ///< [1] 2a/b^2
    Real angle = 0;           ///< [rad] atan(2a/b^2)
    Real angleDeg = 0;        ///< [deg]
};

/// tan phi = 2a/b^2 over the non-empty bins with centre in [xFrom, xTo] (the half-pile, e.g. the
/// draining-crater region A or B). a is measured above the profile's own lowest level in the range
/// and b is the extent of the bins used, so a constant offset of h (centroids instead of tops)
/// cancels exactly, as it does in the slope of a fit; a right-triangle profile rising by dh over b
/// gives tan phi = dh/b. Fewer than 2 bins: NaN fields (the data, not the parameters, fail).
/// Throws std::invalid_argument for xFrom >= xTo.
IntegralRepose integralRepose(const SurfaceProfile& profile, Real xFrom, Real xTo);

struct ReposeParams {
    Real bandLo = 0.2;  ///< fit the bins with lo <= (h - h0)/(h_apex - h0) <= hi (0 <= lo < hi <= 1)
    Real bandHi = 0.8;
    std::optional<Real> apexX;  ///< [m] split the flanks here instead of at the highest bin
    /// [m] a bin is the foot when h <= h0 + footTolerance, h0 the lowest h of the flank's side;
    /// NaN: the mean grain radius of the profile.
    Real footTolerance = std::numeric_limits<Real>::quiet_NaN();
};

/// Angle of repose of a heap with two flanks.
struct Repose {
    SurfaceProfile profile;
    std::size_t apexFirst = 0, apexLast = 0;  ///< bins of the highest h (a flat top spans several)
    Real apexX = 0, apexH = 0;                ///< [m]
    std::size_t footLeft = 0,
                footRight = 0;           ///< foot bins: flank = [footLeft, apexFirst], [apexLast, footRight]
    Real levelLeft = 0, levelRight = 0;  ///< [m] h0 of each side (lowest h)
    LineFit left, right;                 ///< top-centroid method (5a) per flank
    Real meanAngleDeg = 0;               ///< [deg] mean of the finite flank angles
    IntegralRepose integralLeft, integralRight;  ///< integral method (5b) over [foot, apex]
    std::vector<std::string> notes;
};

/// Both methods on both flanks: the apex is the highest bin (or apexX); each side's h0 is its lowest
/// h, its foot the first bin from the apex outward with h <= h0 + footTolerance; the fit uses the
/// flank's bins whose relative height lies in [bandLo, bandHi]; the integral method runs on
/// [foot, apex]. A flank with fewer than 2 usable bins gets NaN and a note. Throws
/// std::invalid_argument for a bad band, a negative tolerance or apexX outside the profile.
Repose angleOfRepose(const SurfaceProfile& profile, const ReposeParams& params = {});

/// Table "repose_profile": x [m], h [m], fit_left [m], fit_right [m] (each fit NaN outside its flank
/// [foot, apex]); notes: repose_left_deg, repose_right_deg, repose_mean_deg, the slopes and
/// intercepts, integral_left_deg, integral_right_deg, the surface definition.
Table toTable(const Repose& result);

}  // namespace granulab::analysis
