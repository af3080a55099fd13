// SPDX-License-Identifier: MIT
// gc2d's legacy data files (gc2d spec 9.1 "File types", naming and lock file; 9.5 "Data outputs";
// 2.1 the clockwise angle convention; docs/coming-from-gc2d.md "Legacy outputs"): pure writers
// that turn plain data (analysis::GrainFrame, analysis::ContactFrame, wall states, one-body
// forces) into the lines of
//   <basename>.ggf        body-frame outlines, one line per body, appended as bodies appear
//   <basename>.NNNN.gff   every force at one dump, one line per (force, body)
//   <basename>.NNNN.gpf   every body's state at one dump
//   <basename>.gtf        one line per dump: file number, time, g, 0.0, size scale
//   <basename>.gpl        one line every STEPS_DUMPLINE: t, g, then id type x y vx vy per body
//   <basename>.glk        the empty lock file
// Ids follow io/gc2d_ids.hpp (walls 0 .. W - 1, then grain W + granulab id). Angles, angular
// velocities and accelerations are written CLOCKWISE (gc2d's convention; granulab's are
// counter-clockwise, so their sign is turned here, as io/gsi_scene.cpp turns ANGLE and OMEGA on
// input). Every number is written in its shortest round-trip form (fmt "{}"), so reading a file
// gives back the same doubles. Units: SI (m, s, kg, N, rad).
#pragma once
#include <cstdint>
#include <cstdio>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "core/types.hpp"
#include "io/gc2d_ids.hpp"

namespace granulab::io {

/// gc2d's MAX_NUM_CORNERS (spec 9.7): the ggf holds 3 + 2 N_max fields per line. granulab's
/// polygons have no corner limit; a scene with wider outlines widens every line of its ggf
/// (gc2dOutlineWidth), as gc2d compiled with a larger MAX_NUM_CORNERS would.
inline constexpr std::size_t kGc2dMaxCorners = 64;

/// gc2d's type codes (spec 2.1): 0 free particle, 2 wall.
inline constexpr int kGc2dParticle = 0;
inline constexpr int kGc2dWall = 2;

/// "<basename>.<ext>" (ggf, gtf, gpl, glk, ps).
std::string gc2dFileName(const std::string& basename, std::string_view ext);
/// "<basename>.<NNNN>.<ext>" (gff, gpf): `number` zero-padded to 4 digits (more above 9999).
std::string gc2dFileName(const std::string& basename, std::int64_t number, std::string_view ext);

/// The N_max of a ggf whose widest outline has `widest` corners: max(64, widest).
std::size_t gc2dOutlineWidth(std::size_t widest) noexcept;

/// One ggf line (with '\n'): id, type, N, x_1..x_N, zeros up to `width`, y_1..y_N, zeros up to
/// `width` (3 + 2 width fields). `bodyCorners` [m]: the outline in the body frame (centroid at
/// the origin, angle 0). Throws std::invalid_argument when it has more than `width` corners.
std::string ggfLine(std::int64_t id, int type, std::span<const Vec2> bodyCorners,
                    std::size_t width = kGc2dMaxCorners);

/// The walls as gc2d bodies of type 2, in wall-index order (gc2d ids 0 .. W - 1).
struct Gc2dWalls {
    std::vector<Vec2> centroid;  ///< [m] now
    std::vector<double> angle;   ///< [rad] counter-clockwise, rotation since the reference placement
    std::vector<Vec2> velocity;  ///< [m/s] of the centroid
    std::vector<double> omega;   ///< [rad/s] counter-clockwise
    std::size_t size() const noexcept { return centroid.size(); }
};

/// The centroid [m] of an outline: the area centroid of a closed polygon with non-zero area,
/// otherwise (an open polyline, a degenerate ring) the mean of the corners.
Vec2 outlineCentroid(std::span<const Vec2> corners, bool closed) noexcept;

/// Accelerations of the grains of a GrainFrame, in its order: the total force and torque of the
/// last force evaluation divided by the mass and the moment of inertia.
struct GrainAccelerations {
    std::vector<double> ax, ay;  ///< [m/s^2]
    std::vector<double> alpha;   ///< [rad/s^2] counter-clockwise
};

/// A force on one grain that no other body feels (gff id2 = -1): gravity m g at the centroid, a
/// pull spring at its attachment point.
struct OneBodyForce {
    std::int64_t grain = 0;  ///< granulab id
    Vec2 point;              ///< [m] application point
    Vec2 force;              ///< [N]
};

/// The gpf of one dump: the walls (id, centroid, angle, velocities, accelerations 0: walls move
/// as prescribed), then the grains in frame order: `id x y phi vx vy omega ax ay alpha`, phi,
/// omega and alpha clockwise.
std::string gpfText(const Gc2dIds& ids, const Gc2dWalls& walls, const analysis::GrainFrame& grains,
                    const GrainAccelerations& acc);

/// The gff of one dump: `id1 id2 x_s y_s x_f y_f f_x f_y` with (x_s, y_s) the centroid of id1,
/// (x_f, y_f) the application point and f the force on id1. Every contact of `contacts` gives
/// two lines, a -> b with F and b -> a with -F (a wall contact: grain -> wall and wall ->
/// grain); then one line per `oneBody` force with id2 = -1. A contact whose grain is not in
/// `grains` throws std::invalid_argument.
std::string gffText(const Gc2dIds& ids, const Gc2dWalls& walls, const analysis::GrainFrame& grains,
                    const analysis::ContactFrame& contacts, const std::vector<OneBodyForce>& oneBody);

/// One gtf line: file number, time [s], g [m/s^2], 0.0 (reserved), size scale factor s.
std::string gtfLine(std::int64_t fileNumber, double time, double g, double scale);

/// One gpl line: t [s], g [m/s^2], then `id type x y vx vy` for the walls and the grains.
std::string gplLine(const Gc2dIds& ids, double time, double g, const Gc2dWalls& walls,
                    const analysis::GrainFrame& grains);

/// The fields of a whitespace-separated line as numbers (a field that is no number: NaN).
std::vector<double> gc2dFields(std::string_view line);

/// Keeps the complete lines of the file at `path` for which keep(line) holds (a last line
/// without '\n', left by a run that was killed mid-write, is dropped). No file: nothing. Used by
/// a resumed run before it appends.
void keepGc2dLines(const std::string& path, const std::function<bool(std::string_view line)>& keep);

/// What a ggf already holds (a resumed run appends to it).
struct GgfContents {
    bool exists = false;
    std::size_t width = 0;         ///< N_max of its lines (0: no line)
    bool walls = false;            ///< it has the wall lines
    std::int64_t nextGrainId = 0;  ///< granulab id after the highest grain it holds
};
GgfContents readGgfContents(const std::string& path, const Gc2dIds& ids);

/// A file appended to line by line (ggf, gtf, gpl), flushed after every write.
class Gc2dAppender {
public:
    Gc2dAppender() = default;
    /// Opens `path`: truncated, or kept and appended to when `append`. Throws std::runtime_error.
    Gc2dAppender(const std::string& path, bool append);
    ~Gc2dAppender();
    Gc2dAppender(Gc2dAppender&& o) noexcept;
    Gc2dAppender& operator=(Gc2dAppender&& o) noexcept;
    Gc2dAppender(const Gc2dAppender&) = delete;
    Gc2dAppender& operator=(const Gc2dAppender&) = delete;

    bool isOpen() const noexcept { return m_file != nullptr; }
    void write(std::string_view text);

private:
    std::FILE* m_file = nullptr;
    std::string m_path;
};

}  // namespace granulab::io
