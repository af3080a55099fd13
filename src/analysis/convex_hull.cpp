// SPDX-License-Identifier: MIT
// Convex-hull area by Andrew's monotone chain (gc2d spec section 7, Eq. 2.45 and 2.52).
#include "analysis/convex_hull.hpp"

#include <algorithm>

namespace granulab::analysis {

Real convexHullArea(std::vector<Vec2>& p) {
    if (p.size() < 3) return 0;
    // Akl-Toussaint: drop the points strictly inside the octagon of the extreme points in x, y,
    // x + y and x - y (they cannot be hull vertices); this removes most of a dense point set.
    std::size_t e[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    const auto key = [](Vec2 v, int m) {
        switch (m) {
            case 0:
                return v.x;
            case 1:
                return v.x + v.y;
            case 2:
                return v.y;
            case 3:
                return v.y - v.x;
            case 4:
                return -v.x;
            case 5:
                return -v.x - v.y;
            case 6:
                return -v.y;
            default:
                return v.x - v.y;
        }
    };
    for (std::size_t i = 1; i < p.size(); ++i)
        for (int m = 0; m < 8; ++m)
            if (key(p[i], m) > key(p[e[m]], m)) e[m] = i;
    Vec2 oct[8];
    for (int m = 0; m < 8; ++m) oct[m] = p[e[m]];  // counter-clockwise order
    std::size_t kept = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        bool inside = true;
        for (int m = 0; m < 8 && inside; ++m) inside = cross(oct[(m + 1) % 8] - oct[m], p[i] - oct[m]) > 0;
        if (!inside) p[kept++] = p[i];
    }
    p.resize(kept);
    const std::size_t n = p.size();
    if (n < 3) return 0;
    std::sort(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<Vec2> hull(2 * n);
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {  // lower chain
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], p[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = p[i];
    }
    for (std::size_t i = n - 1, t = k + 1; i-- > 0;) {  // upper chain
        while (k >= t && cross(hull[k - 1] - hull[k - 2], p[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = p[i];
    }
    Real twice = 0;  // shoelace over the closed chain (last point repeats the first)
    for (std::size_t i = 0; i + 1 < k; ++i) twice += cross(hull[i], hull[i + 1]);
    return 0.5 * twice;
}

}  // namespace granulab::analysis
