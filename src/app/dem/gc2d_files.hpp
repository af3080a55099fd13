// SPDX-License-Identifier: MIT
// gc2d's legacy files of a DEM run (gc2d spec 9.1 and 9.5; docs/coming-from-gc2d.md "Legacy
// outputs"), written when output.gc2d is on (a gsi scene turns it on): the World's state turned
// into the plain data of io/gc2d_outputs.hpp. The dem adapter (app/dem/dem_simulation.cpp) owns
// one on the root rank and calls it at its output stops:
//   open     once before the first output: ggf, gtf and gpl opened (a resumed run keeps their
//            lines up to the checkpoint and appends)
//   dump     at every snapshot: the ggf lines of the bodies new since the last dump, the gff and
//            gpf numbered output.gc2d_next_data_number + snapshot index, one gtf line
//   line     every output.gc2d_line_interval: one gpl line
//   picture  at the end: <basename>.ps of the final state (cairo's PostScript surface, drawn by
//            the helpers of `granulab render`)
#pragma once
#include <cstdint>
#include <string>

#include "analysis/dem_frame.hpp"
#include "dem/world.hpp"
#include "io/gc2d_ids.hpp"
#include "io/gc2d_outputs.hpp"
#include "model/scene_def.hpp"

namespace granulab::app {

/// The grains of `world` in id order, as the analyses read a snapshot: world corners of the
/// polygons at the current size scale, angles and angular velocities counter-clockwise.
analysis::GrainFrame grainFrameOf(const dem::World& world);
/// Their accelerations (same order): total force and torque of the last force evaluation over
/// mass and moment of inertia.
io::GrainAccelerations accelerationsOf(const dem::World& world, const analysis::GrainFrame& grains);
/// The walls as gc2d bodies (centroid, rotation, velocities), in wall-index order.
io::Gc2dWalls gc2dWallsOf(const model::WallSet& walls);
/// The outline of wall w in its reference placement relative to its centroid (the ggf's body
/// frame): a body's or closed polyline's corners, an open polyline's points.
std::vector<Vec2> wallBodyOutline(const model::WallSet& walls, std::size_t w);

class Gc2dFiles {
public:
    /// `scene`: output.gc2d and the shapes sources may insert (the ggf width); `world`: the run
    /// (its walls fix the ids). Both must outlive this object.
    Gc2dFiles(const model::SceneDef& scene, const dem::World& world);

    /// Opens the appended files in `dir` (resumeTime >= 0: a resumed run, see the top comment).
    void open(const std::string& dir, double resumeTime);
    /// The files of snapshot `index` (the state of the world now). Returns false when the World's
    /// contact records are not of this step (the gff then holds the one-body forces only).
    bool dump(const std::string& dir, int index);
    /// One gpl line (output.gc2d_line_interval).
    void line();
    /// <basename>.ps of the world now; false if cairo could not write it.
    bool picture(const std::string& dir) const;

private:
    std::size_t ggfWidth() const;

    const model::SceneDef& m_scene;
    const dem::World& m_world;
    io::Gc2dIds m_ids;
    io::Gc2dAppender m_ggf, m_gtf, m_gpl;
    std::size_t m_width = 0;       ///< N_max of the ggf (0: fixed at the first dump)
    bool m_wallsWritten = false;   ///< the ggf holds the wall lines
    std::int64_t m_nextGrain = 0;  ///< granulab ids below it are in the ggf (or left before a dump)
};

}  // namespace granulab::app
