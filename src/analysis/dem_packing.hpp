// SPDX-License-Identifier: MIT
// Local packing fraction of a DEM snapshot on a grid of rectangular test areas (gc2d spec
// section 7 item 6, Sec. 2.3.3): the simple estimate rho' = sum alpha_i a_i / A (Eq. 2.44) and
// the estimate corrected for free surfaces and edges rho = sum alpha_i a_i / A_k (Eq. 2.45).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/dem_grid.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

struct PackingParams {
    /// "Corners" of a disk for E1 (Eq. 2.45): the points at angles 2 pi m / diskHullPoints
    /// (m = 0 .. n - 1, so the four extreme points are among them when n is a multiple of 4),
    /// i.e. the corners of the inscribed regular n-gon. At n = 16 the hull of a free surface of
    /// disks lies at most r (1 - cos(pi/16)) = 0.019 r inside the true outline. >= 4.
    std::size_t diskHullPoints = 16;
};

struct PackingGrid {
    TestAreaGrid grid;
    std::vector<Real> covered;        ///< [m^2] sum alpha_i a_i: exact area of the grains inside the area
    std::vector<Real> simple;         ///< rho' = covered / (w h) (Eq. 2.44)
    std::vector<Real> hullArea;       ///< [m^2] A_k: convex hull of E1 u E2 (Eq. 2.45)
    std::vector<Real> improved;       ///< rho = covered / A_k (Eq. 2.45); NaN where A_k = 0
    std::vector<std::size_t> grains;  ///< grains with alpha_i > 0
    std::vector<std::string> notes;
};

/// Area [m^2] of the disk (centre c, radius r [m]) inside the rectangle [lo, hi], exact (Green's
/// theorem over the arcs inside the rectangle and the rectangle edges inside the disk). Appends to
/// `points` (if not null) the boundary points of the clipped region that enter A_k: the
/// rectangle-edge pieces' end points (crossings of the circle with the rectangle, or rectangle
/// corners covered by the disk) and the disk "corners" (PackingParams) inside the rectangle.
Real diskInRectangle(Vec2 c, Real r, Vec2 lo, Vec2 hi, std::size_t diskCorners, std::vector<Vec2>* points);

/// Area [m^2] of the polygon `poly` (counter-clockwise corners [m]) inside [lo, hi]
/// (Sutherland-Hodgman, exact for convex grains). Appends to `points` (if not null) the corners of
/// the clipped polygon: the grain's corners inside A (E1), the crossings of its edges with the
/// rectangle (E2), and rectangle corners covered by the grain.
Real polygonInRectangle(const std::vector<Vec2>& poly, Vec2 lo, Vec2 hi, std::vector<Vec2>* points);

/// Packing fractions of `grains` on every area of `grid`. E1 u E2 is taken as the vertices of every
/// clipped piece (grain n A), which adds the rectangle corners covered by a grain to the spec's
/// E1 (corners inside A) and E2 (boundary crossings): without them a bulk area whose corners lie
/// inside grains would get A_k < A, and rho != rho' in the bulk. Cost O(N x areas per grain), with
/// membership by the grain's bounding box. Throws std::invalid_argument for a bad grid or
/// diskHullPoints < 4. Areas without grains get rho' = 0 and rho = NaN (noted).
PackingGrid packingGrid(const GrainFrame& grains, const TestAreaGrid& grid, const PackingParams& params = {});

/// Table "packing_fraction": x, z [m] (area centre, z = vertical y), rho_simple, rho_improved [1],
/// A_k [m^2], grains [1]; notes: grid geometry and the packing notes.
Table packingTable(const PackingGrid& packing);

}  // namespace granulab::analysis
