// SPDX-License-Identifier: MIT
// The contact file of a DEM snapshot (gc2d spec section 7; docs/output-format.md "Contacts"):
// vtk/contacts_NNNNNN.npy, a NumPy structured array (format version 1.0, little endian, packed
// fields, one record of 108 bytes per contact) that `numpy.load` reads directly:
//   a <i8, b <i8 (particle ids; b = -1 at a wall), wall <i4 (wall index, -1 for grain pairs),
//   px, py [m] contact point, nx, ny unit normal from a toward b, fx, fy [N] force on a (b gets
//   the opposite, at the same point), fn [N] normal force (repulsive > 0), ft [N] tangential
//   force along perp(n), depth [m] overlap depth (area law: A / l), area [m^2] overlap area,
//   length [m] contact line length; all <f8.
// Beside it the same contacts as a VTK line set for ParaView (io/vtk_writer.hpp writeContactsVtp).
#pragma once
#include <string>

#include "analysis/dem_frame.hpp"

namespace granulab::io {

/// Writes `c` as a .npy structured array through AtomicFile; throws std::runtime_error.
void writeContactsNpy(const std::string& path, const analysis::ContactFrame& c);

/// Reads a file written by writeContactsNpy (the time is not in the file: 0). Throws
/// std::runtime_error naming the file when it is missing, not a .npy of this layout, or truncated.
analysis::ContactFrame readContactsNpy(const std::string& path);

/// "vtk/contacts_NNNNNN.npy" of snapshot `index`, relative to the output folder.
std::string contactFileName(int index);

}  // namespace granulab::io
