// SPDX-License-Identifier: MIT
// The contact files of a DEM snapshot (gc2d spec section 7): the World's contact records turned
// into an analysis::ContactFrame (global ids, fn and ft) and written as vtk/contacts_NNNNNN.npy
// and the force-network line set vtk/contacts_NNNNNN.vtp (part 2 of snapshots.pvd).
#pragma once
#include <string>

#include "analysis/dem_frame.hpp"
#include "dem/world.hpp"
#include "io/vtk_writer.hpp"

namespace granulab::app {

/// The records of `log` with fn = -F.n and ft = F.perp(n) (analysis/dem_frame.hpp conventions).
analysis::ContactFrame contactFrameOf(const dem::ContactLog& log, double time);

/// Writes both contact files of snapshot `index` and registers the line set in `pvd`.
void writeContactSnapshot(const std::string& dir, int index, const dem::World& world, io::PvdWriter& pvd);

}  // namespace granulab::app
