// SPDX-License-Identifier: MIT
// CFD flow-field import (cfddem spec 5.5): reads a CFD output file (OpenFOAM foamToVTK legacy .vtk or
// .vtm multiblock, VTK XML .vtu/.vtr/.vts/.vti) with VTK's own readers and reduces it to the DEM
// plane as a fluid::FlowField (z layers collapsed, duplicate (x, y) nodes merged, cells made 2D);
// and expands a scene's field entry (file, .pvd, .series, folder) into the list of files to read.
#pragma once
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/flow_field.hpp"

namespace granulab::io {

/// Which arrays readFlowField takes from the file, and from where.
struct FieldReadOptions {
    std::string velocityArray = "U";  ///< [m/s] 2 or 3 components; x and y are used
    std::string pressureArray = "p";  ///< 1 component, stored as the file gives it
    bool readPressure = false;        // fill FlowField::p (error if the array is missing)
    /// "auto" (point data if the array is there, else cell data) | "point" | "cell"
    std::string data = "auto";
};

/// Error in a field file: the message names the file (and the array where one is concerned).
struct FieldFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Reads one field file into a FlowField (cfddem spec 5.5):
/// - format by extension: .vtk (legacy, ASCII or binary, any dataset type), .vtu .vtr .vts .vti .vtp
///   (VTK XML) and .vtm (multiblock: the block named "internal", else the first non-empty dataset
///   that has the velocity array);
/// - velocity (and pressure) from point data, or from cell data averaged to the points
///   (vtkCellDataToPointData), as options.data says;
/// - z collapse: one z level keeps every point (depth 0); two levels (a 2D OpenFOAM case extruded
///   one cell) keep the z_min points, depth = z_max - z_min [m]; more levels is an error. Points
///   with the same (x, y) then become one node (the first one's values are kept). Tolerance:
///   1e-9 x the bounding-box extent, at least 1e-12 [m];
/// - cells: every VTK cell with >= 3 distinct surviving nodes, counter-clockwise about its centroid;
/// - time: FieldData "TimeValue" [s] (first tuple) if present, else NaN; source = path.
/// Throws FieldFileError (message starts with the path) for a missing, unreadable, truncated or
/// garbage file, a missing array, a wrong component or tuple count, a NaN or infinite value, a 3D
/// field or an empty dataset. VTK's messages are captured, not printed. Not thread-safe with other
/// VTK use in the process while it runs (it silences VTK's global output window); calls are
/// serialised.
fluid::FlowField readFlowField(const std::string& path, const FieldReadOptions& options);

/// One file of a field time series.
struct FieldFile {
    std::string path;                                        ///< ready to pass to readFlowField
    double time = std::numeric_limits<double>::quiet_NaN();  ///< [s] from the collection; NaN if none
};

/// Expands one entry of a scene's field list: a data file (one entry, its time from FieldData TimeValue if
/// any is NOT read here, NaN); a .pvd collection (DataSet file/timestep attributes, paths relative to the
/// .pvd); a .series JSON file ({"file-series-version": "1.0", "files": [{"name": ..., "time": ...}]}, paths
/// relative); a folder: its single *.series or *.pvd if it has one, else every data file in it
/// (.vtk .vtu .vtr .vts .vti .vtm) sorted by the last integer in the file name (case_2 before case_10), times
/// NaN. Collections keep the order of their entries; a folder with several collections is an error. Throws
/// FieldFileError for a missing path, an empty folder, a malformed collection, or a listed file that does not
/// exist.
std::vector<FieldFile> listFieldFiles(const std::string& entry);

}  // namespace granulab::io
