// SPDX-License-Identifier: MIT
// What `granulab render` takes from a contact file (analysis::ContactFrame): the per-grain
// pressure and coordination number, and the force network drawn from each grain's centroid to
// the contact point (gc2d spec 7.12), line width proportional to |F|.
#pragma once
#include <cairo.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "app/render.hpp"

namespace granulab::app::render {

/// Grain index in a frame by global id.
class GrainIndex {
public:
    static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    explicit GrainIndex(const analysis::GrainFrame& g);
    std::size_t find(std::int64_t id) const noexcept;

private:
    std::vector<std::size_t> m_dense;  ///< ids 0..size-1 (the usual case)
    std::unordered_map<std::int64_t, std::size_t> m_sparse;
};

/// Per-grain quantities of the contacts of one frame.
struct GrainContactSums {
    /// [N/m] p_i = -(sigma_xx + sigma_yy) / 2, sigma_i = (1/A_i) sum_c (x_c - x_i) (x) F_c on i;
    /// compressive positive; 0 without contacts.
    std::vector<double> pressure;
    std::vector<int> coordination;  ///< contacts of grain i (grains and walls)
};
GrainContactSums grainContactSums(const analysis::GrainFrame& g, const analysis::ContactFrame& c,
                                  const GrainIndex& index);

/// Largest |F| [N] of a frame's contacts (0 without contacts).
double maxForce(const analysis::ContactFrame& c);

/// Line widths of the force network, fixed for a run.
struct ForceStyle {
    double maxForce = 0;      ///< [N] largest |F| over all frames
    double maxWidth = 1;      ///< [px] width at maxForce (0.6 typical grain radius)
    double minWidth = 0.5;    ///< [px] thinnest line drawn
    double skipBelow = 1e-3;  ///< forces below this fraction of maxForce are not drawn (speed)
};

/// Draws, for every contact, a black line from grain a's centroid to the contact point and, for a
/// grain pair, one from grain b's centroid to it (wall contacts: the grain's half only); butt
/// caps, so each line ends at the contact point.
void drawForces(cairo_t* cr, const RenderLayout& L, const analysis::GrainFrame& g,
                const analysis::ContactFrame& c, const GrainIndex& index, const ForceStyle& style);

}  // namespace granulab::app::render
