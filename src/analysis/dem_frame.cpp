// SPDX-License-Identifier: MIT
// Derived per-grain quantities of a DEM snapshot (analysis/dem_frame.hpp).
#include "analysis/dem_frame.hpp"

namespace granulab::analysis {

double GrainFrame::area(std::size_t i) const noexcept {
    if (!isPolygon(i)) return kPi * radius[i] * radius[i];
    double twice = 0;  // shoelace
    const std::size_t b = cornerStart[i], e = cornerStart[i + 1];
    for (std::size_t c = b; c < e; ++c) {
        const Vec2 p = corners[c], q = corners[c + 1 < e ? c + 1 : b];
        twice += p.x * q.y - q.x * p.y;
    }
    return 0.5 * twice;
}

}  // namespace granulab::analysis
