// SPDX-License-Identifier: MIT
// Contact-force direction and magnitude distributions (gc2d spec section 7 item 3).
#include "analysis/dem_force_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/table_note.hpp"

namespace granulab::analysis {

namespace {

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();

}  // namespace

ForceDirections forceDirections(const ContactFrame& contacts, const ForceDirectionParams& params) {
    if (params.bins == 0) throw std::invalid_argument("forceDirections: bins must be >= 1");
    ForceDirections r;
    const std::size_t bins = params.bins;
    const Real width = 2 * kPi / static_cast<Real>(bins);  // [rad]
    r.count.assign(bins, 0);
    const auto add = [&](Real fx, Real fy) {
        const Real alpha = std::atan2(fy, fx);  // [-pi, pi]
        auto bin = static_cast<std::size_t>(std::max<Real>(0, std::floor((alpha + kPi) / width)));
        if (bin >= bins) bin = 0;  // alpha = pi is the direction -pi
        ++r.count[bin];
        ++r.forces;
    };
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const bool wall = contacts.atWall(k);
        if (wall && !params.includeWalls) continue;
        const Real fx = contacts.fx[k], fy = contacts.fy[k];
        if (fx == 0 && fy == 0) {
            ++r.zeroForces;
            continue;
        }
        add(fx, fy);
        if (!wall) add(-fx, -fy);  // the partner b feels -F
    }
    r.alpha.resize(bins);
    r.density.resize(bins);
    for (std::size_t b = 0; b < bins; ++b) {
        r.alpha[b] = -kPi + (static_cast<Real>(b) + 0.5) * width;
        r.density[b] =
            r.forces > 0 ? static_cast<Real>(r.count[b]) / (static_cast<Real>(r.forces) * width) : kNaN;
    }
    if (r.forces == 0) r.notes.push_back("warning: no non-zero contact force; P(alpha) is undefined (NaN)");
    return r;
}

Table toTable(const ForceDirections& result) {
    Table t;
    t.name = "force_directions";
    t.add("alpha", "rad").values = result.alpha;
    t.add("P", "1/rad").values = result.density;
    t.add("forces", "1").values.assign(result.count.begin(), result.count.end());
    t.notes.push_back(
        "alpha = atan2(Fy, Fx); grain pairs add +F and -F, wall contacts the force on the grain "
        "(gc2d spec 7 item 3)");
    t.notes.push_back(noteLine("forces", static_cast<Real>(result.forces)));
    t.notes.push_back(noteLine("zero_forces_skipped", static_cast<Real>(result.zeroForces)));
    for (const std::string& n : result.notes) t.notes.push_back(n);
    return t;
}

ForceMagnitudes forceMagnitudes(const ContactFrame& contacts, const ForceMagnitudeParams& params) {
    if (params.bins == 0) throw std::invalid_argument("forceMagnitudes: bins must be >= 1");
    if (!(params.maxRatio > 0) || !std::isfinite(params.maxRatio))
        throw std::invalid_argument("forceMagnitudes: maxRatio must be finite and > 0");
    ForceMagnitudes r;
    std::vector<Real> magnitude;  // [N]
    magnitude.reserve(contacts.size());
    Real sum = 0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        if (contacts.atWall(k) && !params.includeWalls) continue;
        magnitude.push_back(std::hypot(contacts.fx[k], contacts.fy[k]));
        sum += magnitude.back();
    }
    const std::size_t bins = params.bins;
    const Real width = params.maxRatio / static_cast<Real>(bins);
    r.contacts = magnitude.size();
    r.count.assign(bins, 0);
    r.ratio.resize(bins);
    r.density.assign(bins, kNaN);
    for (std::size_t b = 0; b < bins; ++b) r.ratio[b] = (static_cast<Real>(b) + 0.5) * width;
    r.meanForce = r.contacts > 0 ? sum / static_cast<Real>(r.contacts) : kNaN;
    if (!(r.meanForce > 0)) {
        r.overflowFraction = kNaN;
        r.notes.push_back(r.contacts == 0 ? "warning: no contact selected; P(F/<F>) is undefined (NaN)"
                                          : "warning: all forces are zero; P(F/<F>) is undefined (NaN)");
        return r;
    }
    std::uint64_t overflow = 0;
    for (Real f : magnitude) {
        const Real x = f / r.meanForce;
        const auto bin = static_cast<std::size_t>(x / width);
        if (x >= params.maxRatio || bin >= bins) {
            ++overflow;
            continue;
        }
        ++r.count[bin];
    }
    const auto n = static_cast<Real>(r.contacts);
    for (std::size_t b = 0; b < bins; ++b) r.density[b] = static_cast<Real>(r.count[b]) / (n * width);
    r.overflowFraction = static_cast<Real>(overflow) / n;
    return r;
}

Table toTable(const ForceMagnitudes& result) {
    Table t;
    t.name = "force_magnitudes";
    t.add("F/<F>", "1").values = result.ratio;
    t.add("P", "1").values = result.density;
    t.add("contacts", "1").values.assign(result.count.begin(), result.count.end());
    t.notes.push_back(noteLine("mean_force", result.meanForce, "N"));
    t.notes.push_back(noteLine("contacts", static_cast<Real>(result.contacts)));
    t.notes.push_back(noteLine("overflow_fraction", result.overflowFraction));
    for (const std::string& n : result.notes) t.notes.push_back(n);
    return t;
}

}  // namespace granulab::analysis
