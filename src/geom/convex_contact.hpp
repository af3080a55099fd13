// SPDX-License-Identifier: MIT
// Tracked contact of two convex polygons (gc2d spec sections 3.1, 5.3 and erratum 6 of
// section 12): a 2D closest-feature (Lin-Canny) walk while the pair is apart, and two cached
// boundary crossings while it overlaps, so that a persistent contact or a persistent near miss
// costs O(1) whatever the corner count. A cold start (a new pair) costs O(n m).
//
// While the polygons overlap, the overlap polygon is the chain of A's corners inside B between
// the crossing where A's boundary enters B (A-edge a1 crossing B-edge b1) and the crossing where
// B's boundary enters A (B-edge b2 crossing A-edge a2), followed by the chain of B's corners
// inside A back to the first crossing; c1 and c2 are these crossings. Overlaps deeper than a
// quarter of the smaller inscribed radius, where convex boundaries may cross more than twice,
// are computed by full clipping with the farthest pair of crossings (erratum 6).
#pragma once
#include <cstdint>

#include "core/error.hpp"
#include "core/types.hpp"
#include "geom/area_contact.hpp"

namespace granulab::geom {

/// A convex counter-clockwise polygon placed in the world. The world corners are computed once
/// per particle and force evaluation (gc2d spec section 5.4, step 3), not per contact.
struct PolygonFrame {
    const Vec2* corners = nullptr;  ///< [m] world corners, counter-clockwise
    int n = 0;
    Vec2 centre;        ///< [m] centroid
    Real inradius = 0;  ///< [m] inscribed radius about the centroid

    /// Corner k for k in [-n, 2n) (index arithmetic one turn either way).
    Vec2 corner(int k) const noexcept {
        GL_ASSERT(k >= -n && k < 2 * n, "corner index within one turn");
        if (k >= n) k -= n;
        if (k < 0) k += n;
        return corners[k];
    }
};

/// Per-contact cache of the features found at the last evaluation.
struct FeatureCache {
    enum State : std::uint16_t { Cold = 0, Apart = 1, Crossing = 2 };
    /// Apart: f[0], f[1] closest features of A and B (2k: corner k, 2k+1: edge k from corner k).
    /// Crossing: f[0], f[1] = (a1, b1), A's boundary enters B; f[2], f[3] = (a2, b2), B's enters A.
    std::uint16_t f[4] = {0, 0, 0, 0};
    std::uint16_t state = Cold;

    /// The cache of the same pair with the roles of A and B exchanged.
    FeatureCache swapped() const noexcept {
        FeatureCache s;
        s.state = state;
        if (state == Apart) {
            s.f[0] = f[1];
            s.f[1] = f[0];
        } else if (state == Crossing) {
            s.f[0] = f[3];  // B enters A becomes "new A enters new B"
            s.f[1] = f[2];
            s.f[2] = f[1];
            s.f[3] = f[0];
        }
        return s;
    }
};

/// Counts of the work done, for the closest-feature statistics in summary.json.
struct FeatureStats {
    std::uint64_t evaluations = 0;  ///< tracked pair evaluations
    std::uint64_t iterations = 0;   ///< feature tests (Lin-Canny steps and crossing candidates)
    std::uint64_t coldStarts = 0;   ///< O(n m) searches
    std::uint64_t fullClips = 0;    ///< deep overlaps computed by full clipping
};

/// Contact of polygon a with polygon b; updates `cache`. The normal pushes a away from b.
AreaContact trackPolygonContact(const PolygonFrame& a, const PolygonFrame& b, FeatureCache& cache,
                                FeatureStats& stats) noexcept;

/// Reference without cache (cold start every time); same results as the tracked version.
AreaContact polygonContact(const PolygonFrame& a, const PolygonFrame& b) noexcept;

}  // namespace granulab::geom
