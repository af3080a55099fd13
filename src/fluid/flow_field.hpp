// SPDX-License-Identifier: MIT
// A flow field imported from a CFD program, reduced to the DEM plane (cfddem spec 5.4-5.5): the
// distinct (x, y) nodes with the fluid velocity (and optionally pressure) at each, and the 2D
// cells over them when the file had cells. Filled by io/flow_field_reader (VTK files) or by a test;
// fluid/field_interpolator turns it into a lookup structure. SI units.
#pragma once
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace granulab::fluid {

struct FlowField {
    std::string source;  ///< file it was read from (for messages), or "uniform"/"test"
    /// [s] the time the file carries (FieldData TimeValue, .pvd/.series entry); NaN if none
    Real time = std::numeric_limits<Real>::quiet_NaN();
    std::vector<Real> x, y;    ///< [m] node coordinates, each (x, y) once (z layers collapsed)
    std::vector<Real> ux, uy;  ///< [m/s] fluid velocity at the nodes
    std::vector<Real> p;       ///< pressure at the nodes as the file gives it; empty when not read
    /// 2D cells (convex polygons, counter-clockwise or clockwise) over node indices: cell c has the
    /// nodes cellNodes[cellOffsets[c] .. cellOffsets[c + 1]); both empty when the file had no cells.
    std::vector<std::uint32_t> cellOffsets, cellNodes;
    Real depth = 0;  ///< [m] z extent of the CFD mesh (a 2D OpenFOAM case has two z layers); 0: one layer

    std::size_t size() const noexcept { return x.size(); }
    bool hasCells() const noexcept { return cellOffsets.size() > 1; }
    bool hasPressure() const noexcept { return !p.empty(); }
};

/// A field with one node per corner of the box [lo, hi] and the same velocity everywhere (a
/// still or uniform stream when the scene names no file).
FlowField uniformField(Vec2 lo, Vec2 hi, Vec2 velocity);

}  // namespace granulab::fluid
