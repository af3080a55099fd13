// SPDX-License-Identifier: MIT
// VTK XML output for ParaView (DESIGN.md "io/ writers"): particles and walls as PolyData (.vtp,
// raw binary appended data) and a .pvd collection that strings the snapshots into a time series.
//
// Particle file layout (one piece, part 0 of snapshots.pvd, so ParaView shows disks and polygons
// together when it opens the .pvd; a disk-only scene has no Polys and no CellData):
// - Points, in slot order: a disk contributes its centre, a polygon its world corners
//   (x, y) + R(angle) * body corner, counter-clockwise.
// - Verts: one vertex cell per disk (its centre point). Polys: one polygon cell per polygon
//   particle (its corners), present only when the scene has polygons. VTK numbers the cells
//   verts first, then polys: cell data index = disk rank, or disk count + polygon rank.
// - PointData (always): id, radius, velocity, speed, omega, angle, mass, material,
//   acceleration (3 components, z = 0), angular_acceleration, diameter; with a flow field also
//   fluid_velocity (3 components) and fluid_pressure (FluidAtParticles). At a disk
//   centre these are the disk's values; at a polygon corner they repeat the polygon's values
//   except radius = 0, so that the Glyph filter (scale array `radius`) draws nothing there and
//   colouring by a point array (e.g. `speed`) paints each polygon in one colour.
// - CellData (only when the scene has polygons): id, radius [m] (disk radius / polygon
//   circumradius), velocity, speed, omega, angle, mass, material, acceleration,
//   angular_acceleration, diameter (2 radius), [fluid_velocity, fluid_pressure], shape_kind (0 = disk or
//   sphere, 1 = polygon), corners (corner count, 0 for disks), position (centre of mass, 3
//   components, z = 0), for every cell, disks included.
// In ParaView the polygons show as filled outlines as soon as the .pvd is opened; for the disks
// add the Glyph filter as described at writeParticlesVtp.
#pragma once
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/point_set.hpp"
#include "io/vtk_reader.hpp"
#include "model/particle_store.hpp"
#include "model/shape_pool.hpp"
#include "model/walls.hpp"

namespace granulab::io {

/// The flow field at each particle's centre (slot order), written beside the particle arrays
/// when the scene has one (cfddem spec 5): velocity [m/s] (2 per slot), pressure (1 per slot,
/// in the field file's units: OpenFOAM's incompressible p is kinematic, [m^2/s^2]); NaN where a
/// particle lies outside the field's mesh.
struct FluidAtParticles {
    std::vector<double> velocity;
    std::vector<double> pressure;
};

/// Writes one vertex per disk and one polygon cell per polygon particle (layout: top of this
/// file). Point data: id, radius [m], velocity [m/s] (3 components, z = 0), speed [m/s], omega
/// [rad/s], angle [rad], mass [kg], material, acceleration [m/s^2] (3 components: the force and
/// torque of the last force evaluation over the mass and inertia, gravity and fluid forces
/// included), angular_acceleration [rad/s^2], diameter [m] (2 radius: the seed cfddem's set),
/// and with `fluid` fluid_velocity [m/s] and fluid_pressure; field data TimeValue [s].
/// In ParaView show the disks with the Glyph filter: glyph type Sphere (or 2D Glyph Circle),
/// scale array `radius`, scale factor 2 (the glyph sources have radius 0.5, so 2 r = diameter).
/// `shapes` is the pool the store's `shape` column refers to; a shape index outside it throws
/// std::invalid_argument. Creates the parent folder if needed; throws std::runtime_error when
/// the file cannot be written.
void writeParticlesVtp(const std::string& path, const model::ParticleStore& s, const model::ShapePool& shapes,
                       double time, const FluidAtParticles* fluid = nullptr);
/// Without a shape pool: every particle is written as a vertex with its radius (a polygon
/// particle with its circumradius, like a disk).
void writeParticlesVtp(const std::string& path, const model::ParticleStore& s, double time);

/// Writes wall segments as Lines cells (points = segment end points a, b of each segment) with
/// the cell data `wall` (index of the wall the segment belongs to) and field data TimeValue [s].
void writeWallsVtp(const std::string& path, const model::WallSet& w, double time);

/// The force network of a DEM snapshot (gc2d spec 7 item 12): one polyline cell per contact
/// from the centre of a through the contact point to the centre of b (at a wall: centre of a to
/// the contact point), so that a line ends where the force acts, also for polygons. Cell data:
/// a, b, wall (Int64/Int32), force [N] (on a, 3 components), force_magnitude [N], fn, ft [N],
/// normal (3 components), depth [m], area [m^2], length [m]; field data TimeValue [s]. In
/// ParaView: Tube filter, vary the radius by `force_magnitude`. `centreA`/`centreB` [m]: the
/// centres of a and b (centreB unused at walls), one per contact.
void writeContactsVtp(const std::string& path, const analysis::ContactFrame& c,
                      const std::vector<Vec2>& centreA, const std::vector<Vec2>& centreB, double time);

/// Hard-sphere gas snapshot (edmd engine): points in 3D (z = 0 for disks), point data id,
/// radius [m], velocity [m/s], speed [m/s] and collisions (per particle, for colouring as in the
/// thesis' Figs. 1.1, 4.4, 5.1).
void writeGasVtp(const std::string& path, const analysis::PointSet& gas,
                 const std::vector<std::uint64_t>& ids, const std::vector<double>& collisions, double time);

/// "vtk/<stem>_NNNNNN.vtp" (6-digit snapshot index), relative to the output folder.
std::string snapshotFileName(const std::string& stem, int index);

/// ParaView .pvd collection: one DataSet per (time, part). write() rewrites the whole file
/// (atomically, via a temporary file and rename), so a killed run still leaves a valid file.
class PvdWriter {
public:
    explicit PvdWriter(std::string path);

    /// Registers a file (path relative to the .pvd's folder) for time [s] and part.
    void add(double time, int part, const std::string& relativeFile);
    void write() const;
    /// Replaces the entry list by the file's content (on --resume); a missing file gives an
    /// empty list, a malformed one throws std::runtime_error.
    void load();
    /// Drops every entry with time > `time` [s] (snapshots newer than the checkpoint resumed).
    void truncateAfter(double time);

    const std::vector<PvdEntry>& entries() const noexcept { return m_entries; }
    const std::string& path() const noexcept { return m_path; }

private:
    std::string m_path;
    std::vector<PvdEntry> m_entries;
};

/// Convenience for the run command: writes OUTDIR/vtk/particles_NNNNNN.vtp (part 0, disks and
/// polygons) and OUTDIR/vtk/walls_NNNNNN.vtp (part 1), adds both to `pvd` and rewrites it.
void writeSnapshot(const std::string& outDir, int index, const model::ParticleStore& s,
                   const model::ShapePool& shapes, const model::WallSet& w, double time, PvdWriter& pvd,
                   const FluidAtParticles* fluid = nullptr);

}  // namespace granulab::io
