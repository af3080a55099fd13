// SPDX-License-Identifier: MIT
// Convex polygon grain shapes (gc2d spec section 2.3, App. B.1.6 and the Perl macros of App.
// D.3-D.5): regular polygons, (chamfered) rectangles, polygons inscribed in ellipses, and the
// random gc2d grains with their size, corner-count, corner-angle and rotation modes. Pure
// functions: every random draw comes from the CounterRng passed in. Lengths in m, angles in
// rad (counter-clockwise); corner lists are counter-clockwise in the shape's own frame (the
// ellipse or rectangle centred at the origin; the ShapePool re-centres them at the centroid).
#pragma once
#include <optional>
#include <vector>

#include "core/rng.hpp"
#include "core/types.hpp"
#include "model/scene_def.hpp"

namespace granulab::model {

/// Chamfer of the SPECIAL_RECTANGLE grains (gc2d does not print its value): 10 % of each edge
/// is cut at each corner.
inline constexpr Real kSpecialRectangleChamfer = 0.1;

/// Largest number of corners a generated shape may have (guards against absurd input).
inline constexpr std::int64_t kMaxShapeCorners = 10000;

/// Regular N-gon inscribed in the circle of radius r [m], a corner on +x (gc2d_sphere).
std::vector<Vec2> regularPolygon(int n, Real r);

/// Rectangle with edges a (along x) and b (along y) [m]. A chamfer c in (0, 0.5) cuts every
/// corner so that the edges shrink to a (1 - 2c) and b (1 - 2c): an octagon of area
/// a b (1 - 2 c^2) (gc2d_rectangle_cut); c = 0 is the plain rectangle (gc2d_rectangle).
std::vector<Vec2> rectangle(Real a, Real b, Real chamfer);

/// N corners at the regular angles i 2 pi / N on the ellipse with semi-axes a, b [m]
/// (gc2d_ellipse).
std::vector<Vec2> ellipsePolygon(Real a, Real b, int n);

/// Unit variate of gc2d's "special truncated Gaussian" (App. B.1.6, footnote 3): N(0.5, 0.1)
/// with draws outside [0, 1] rejected.
Real specialGaussianUnit(CounterRng& rng);

/// One random gc2d grain (App. B.1.6, spec section 2.3).
struct Grain {
    std::vector<Vec2> corners;  ///< [m] counter-clockwise, ellipse centre at the origin
    Vec2 semiAxes;              ///< [m] drawn semi-axes (a, b); SPECIAL_RECTANGLE: half edges
    int drawnCorners = 0;       ///< corner count N drawn (0 for SPECIAL_RECTANGLE)
    std::vector<Real> angles;   ///< [rad] corner angles in [0, 2 pi), ascending (empty for SPECIAL_RECTANGLE)
    int redraws = 0;            ///< angle sets redrawn because corners nearly coincided
};

/// Draws one grain of a `kind = "grain"` shape: semi-axes by size_mode, corner count by
/// corner_count_mode, angles by corner_angles, sorted ascending after reduction to [0, 2 pi),
/// corners (a cos phi, b sin phi). Corners closer than 1e-9 max(a, b) to their predecessor are
/// dropped; when fewer than 3 remain or the polygon fails geom::checkConvexPolygon, the angles
/// are drawn again from the same stream (deterministic). After 1000 failed draws the regular
/// angles are used.
Grain randomGrain(const ShapeDef& def, CounterRng& rng);

/// Initial angle [rad] of one particle by rotation_mode: CONST phi_0, EQUAL uniform in
/// [0, 2 pi), GAUSS special truncated Gaussian on (phi_0 - pi/2, phi_0 + pi/2).
Real drawRotation(const ShapeDef& def, CounterRng& rng);

/// Corners of a deterministic shape (polygon, regular, rectangle, ellipse), counter-clockwise:
/// a clockwise `polygon` list is reversed (validate() warns about it). nullopt for a grain or
/// for parameters that give no polygon (they are reported by validate()).
std::optional<std::vector<Vec2>> deterministicCorners(const ShapeDef& def);

/// Largest distance [m] of a corner from the shape's placement point that any particle of this
/// shape can have: the circumradius about the centroid for deterministic shapes, and for grains
/// the largest semi-axis that can be drawn (the grain lies inside its ellipse, whose centre is
/// put on the lattice site). 0 if the parameters are invalid.
Real maxPlacementRadius(const ShapeDef& def);

}  // namespace granulab::model
