// SPDX-License-Identifier: MIT
// Result of an overlap-area contact (gc2d spec section 3.1, Fig. 2.4), shared by every shape
// pair: polygon-polygon (geom/convex_contact), circle-polygon and circle-circle
// (geom/circle_contact). The force law (gc2d Eq. 2.20-2.29) needs only these quantities.
#pragma once
#include "core/types.hpp"

namespace granulab::geom {

struct AreaContact {
    bool touching = false;
    Real area = 0;  ///< [m^2] area A of the overlap region
    Vec2 c1, c2;    ///< [m] the two crossing points of the boundaries; contact line c1c2, L_c = |c2 - c1|
    Vec2 point;     ///< [m] contact point s = (c1 + c2)/2
    Vec2 normal;    ///< unit vector perpendicular to c1c2 that pushes the first body away from the second
};

}  // namespace granulab::geom
