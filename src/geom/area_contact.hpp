// SPDX-License-Identifier: MIT
// Result of an overlap-area contact (gc2d spec section 3.1, Fig. 2.4), shared by every shape
// pair: polygon-polygon (geom/convex_contact), circle-polygon and circle-circle
// (geom/circle_contact). The force law (gc2d Eq. 2.20-2.29) needs only these quantities; the
// energy-conserving law (Feng, Han & Owen 2012) also the area gradient `pull`, `twist`.
#pragma once
#include "core/types.hpp"

namespace granulab::geom {

struct AreaContact {
    bool touching = false;
    Real area = 0;  ///< [m^2] area A of the overlap region
    Vec2 c1, c2;    ///< [m] the two crossing points of the boundaries; contact line c1c2, L_c = |c2 - c1|
    Vec2 point;     ///< [m] contact point s = (c1 + c2)/2
    Vec2 normal;    ///< unit vector perpendicular to c1c2 that pushes the first body away from the second
    /// [m] -dA/dx of the first body: the sum of -n_e L_e over the edges (or arcs) of the overlap
    /// boundary that lie on the first body's boundary (n_e outward). For two crossings it is
    /// L_c * normal; 0 when one body contains the other. The second body's is -pull.
    Vec2 pull;
    /// [m^2] moment of those edge vectors about `point`: -dA/dtheta of the first body is
    /// cross(point - centre, pull) + twist (0 for two crossings; the second body's is -twist).
    Real twist = 0;
};

}  // namespace granulab::geom
