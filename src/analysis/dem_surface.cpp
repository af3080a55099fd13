// SPDX-License-Identifier: MIT
// Surface profile and angle of repose of a pile (gc2d spec section 7 item 5).
//
// Why the integral method is measured above the profile's own lowest level: with centroids, h(x)
// lies a nearly constant distance c below the true surface. A fit's slope ignores c; the area
// a = integral (h - floor) would lose c b and bias tan phi by -2c/b. Measuring a above h0 = the
// lowest h of the half-pile (which carries the same offset) and b as the extent of the bins used
// makes a right-triangle profile give exactly its slope, whichever surface definition is chosen.
#include "analysis/dem_surface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/dem_geometry.hpp"
#include "analysis/table_note.hpp"

namespace granulab::analysis {

namespace {

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
constexpr Real kDeg = 180 / kPi;

/// Least-squares line through the non-empty bins [first, last] with keep(i) true.
template <class Keep>
LineFit fitLine(const SurfaceProfile& p, std::size_t first, std::size_t last, Keep keep) {
    Real sx = 0, sy = 0, sxx = 0, sxy = 0;
    LineFit f;
    f.xFrom = kNaN;
    for (std::size_t i = first; i <= last && i < p.x.size(); ++i) {
        if (std::isnan(p.h[i]) || !keep(i)) continue;
        if (f.points == 0) f.xFrom = p.x[i];
        f.xTo = p.x[i];
        ++f.points;
        sx += p.x[i];
        sy += p.h[i];
    }
    if (f.points < 2) {
        f.slope = f.intercept = f.angle = f.angleDeg = f.xTo = kNaN;
        return f;
    }
    const auto n = static_cast<Real>(f.points);
    const Real mx = sx / n, my = sy / n;  // centred sums for round-off
    for (std::size_t i = first; i <= last && i < p.x.size(); ++i) {
        if (std::isnan(p.h[i]) || !keep(i)) continue;
        sxx += (p.x[i] - mx) * (p.x[i] - mx);
        sxy += (p.x[i] - mx) * (p.h[i] - my);
    }
    f.slope = sxy / sxx;
    f.intercept = my - f.slope * mx;
    f.angle = std::atan(std::abs(f.slope));
    f.angleDeg = f.angle * kDeg;
    return f;
}

/// Integral method over the non-empty bins [first, last].
IntegralRepose integralOverBins(const SurfaceProfile& p, std::size_t first, std::size_t last) {
    IntegralRepose r;
    std::vector<std::size_t> used;
    for (std::size_t i = first; i <= last && i < p.x.size(); ++i)
        if (!std::isnan(p.h[i])) used.push_back(i);
    if (used.size() < 2) {
        r.xFrom = r.xTo = r.base = r.level = r.rise = r.area = r.tanPhi = r.angle = r.angleDeg = kNaN;
        return r;
    }
    r.xFrom = p.x[used.front()];
    r.xTo = p.x[used.back()];
    r.base = r.xTo - r.xFrom;
    r.level = p.h[used.front()];
    Real top = r.level;
    for (std::size_t i : used) {
        r.level = std::min(r.level, p.h[i]);
        top = std::max(top, p.h[i]);
    }
    r.rise = top - r.level;
    for (std::size_t k = 1; k < used.size(); ++k) {
        const std::size_t i = used[k - 1], j = used[k];
        r.area += 0.5 * (p.h[i] + p.h[j] - 2 * r.level) * (p.x[j] - p.x[i]);  // [m^2]
    }
    r.tanPhi = 2 * r.area / (r.base * r.base);  // spec 7 item 5b
    r.angle = std::atan(r.tanPhi);
    r.angleDeg = r.angle * kDeg;
    return r;
}

}  // namespace

SurfaceProfile surfaceProfile(const GrainFrame& grains, const SurfaceParams& params) {
    if (!(params.binWidth > 0) || !std::isfinite(params.binWidth))
        throw std::invalid_argument("surfaceProfile: binWidth must be finite and > 0");
    const std::size_t n = grains.size();
    Real lo = params.xMin.value_or(kNaN), hi = params.xMax.value_or(kNaN);  // [m]
    if (!params.xMin || !params.xMax) {
        Real minX = n > 0 ? grains.x[0] : 0, maxX = minX;
        for (std::size_t i = 0; i < n; ++i) {
            minX = std::min(minX, grains.x[i]);
            maxX = std::max(maxX, grains.x[i]);
        }
        if (!params.xMin) lo = minX;
        if (!params.xMax) hi = maxX;
    }
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi)
        throw std::invalid_argument("surfaceProfile: the bin range needs finite xMin <= xMax");
    const Real binsReal = std::max<Real>(1, std::ceil((hi - lo) / params.binWidth));
    if (binsReal > 1e7)
        throw std::invalid_argument("surfaceProfile: more than 1e7 bins; use a wider binWidth");
    const auto bins = static_cast<std::size_t>(binsReal);

    SurfaceProfile p;
    p.binWidth = params.binWidth;
    p.height = params.height;
    p.x.resize(bins);
    p.h.assign(bins, kNaN);
    p.grains.assign(bins, 0);
    for (std::size_t b = 0; b < bins; ++b) p.x[b] = lo + (static_cast<Real>(b) + 0.5) * params.binWidth;
    Real radiusSum = 0;
    std::size_t binned = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Real x = grains.x[i];
        if (!(x >= lo && x <= hi)) continue;
        const auto b = std::min(bins - 1, static_cast<std::size_t>((x - lo) / params.binWidth));
        const Real h =
            params.height == SurfaceHeight::Top ? grainReach(grains, i, {0, 1}) : grains.y[i];  // [m]
        if (!(p.h[b] >= h)) p.h[b] = h;  // NaN-safe max
        ++p.grains[b];
        radiusSum += grains.radius[i];
        ++binned;
    }
    p.meanRadius = binned > 0 ? radiusSum / static_cast<Real>(binned) : kNaN;
    return p;
}

IntegralRepose integralRepose(const SurfaceProfile& profile, Real xFrom, Real xTo) {
    if (!std::isfinite(xFrom) || !std::isfinite(xTo) || !(xFrom < xTo))
        throw std::invalid_argument("integralRepose: the half-pile range needs finite xFrom < xTo");
    std::size_t first = profile.x.size(), last = 0;
    for (std::size_t i = 0; i < profile.x.size(); ++i)
        if (profile.x[i] >= xFrom && profile.x[i] <= xTo) {
            first = std::min(first, i);
            last = i;
        }
    return integralOverBins(profile, first, last);
}

Repose angleOfRepose(const SurfaceProfile& profile, const ReposeParams& params) {
    if (!(params.bandLo >= 0) || !(params.bandHi <= 1) || !(params.bandLo < params.bandHi))
        throw std::invalid_argument("angleOfRepose: the band needs 0 <= bandLo < bandHi <= 1");
    if (params.footTolerance < 0) throw std::invalid_argument("angleOfRepose: footTolerance must be >= 0");
    Repose r;
    r.profile = profile;
    const SurfaceProfile& p = r.profile;
    const std::size_t bins = p.x.size();
    const Real tolerance = std::isnan(params.footTolerance) ? p.meanRadius : params.footTolerance;  // [m]

    // Apex.
    std::size_t nonEmpty = 0;
    for (Real h : p.h) nonEmpty += std::isnan(h) ? 0 : 1;
    const auto fail = [&](const std::string& why) {
        r.apexX = r.apexH = r.levelLeft = r.levelRight = r.meanAngleDeg = kNaN;
        r.left = fitLine(p, 1, 0, [](std::size_t) { return false; });
        r.right = r.left;
        r.integralLeft = integralOverBins(p, 1, 0);
        r.integralRight = r.integralLeft;
        r.notes.push_back("warning: " + why + "; no angle of repose (NaN)");
        return r;
    };
    if (nonEmpty < 3) return fail("fewer than 3 non-empty bins");
    if (params.apexX) {
        const Real x0 = p.x.front() - 0.5 * p.binWidth;
        const Real k = std::floor((*params.apexX - x0) / p.binWidth);
        if (!(k >= 0 && k < static_cast<Real>(bins)))
            throw std::invalid_argument("angleOfRepose: apexX lies outside the profile");
        r.apexFirst = r.apexLast = static_cast<std::size_t>(k);
        if (std::isnan(p.h[r.apexFirst])) return fail("the bin at apexX is empty");
    } else {
        Real top = -std::numeric_limits<Real>::infinity();
        for (std::size_t i = 0; i < bins; ++i)
            if (p.h[i] > top) {
                top = p.h[i];
                r.apexFirst = r.apexLast = i;
            } else if (p.h[i] == top) {
                r.apexLast = i;
            }
    }
    r.apexH = p.h[r.apexFirst];
    r.apexX = 0.5 * (p.x[r.apexFirst] + p.x[r.apexLast]);

    // Each side's level h0 and foot.
    r.levelLeft = r.levelRight = r.apexH;  // the lowest non-empty h of each side
    for (std::size_t i = 0; i < bins; ++i) {
        if (std::isnan(p.h[i])) continue;
        if (i <= r.apexFirst) r.levelLeft = std::min(r.levelLeft, p.h[i]);
        if (i >= r.apexLast) r.levelRight = std::min(r.levelRight, p.h[i]);
    }
    r.footLeft = r.apexFirst;
    for (std::size_t i = r.apexFirst + 1; i-- > 0;) {
        r.footLeft = i;
        if (p.h[i] <= r.levelLeft + tolerance) break;
    }
    r.footRight = r.apexLast;
    for (std::size_t i = r.apexLast; i < bins; ++i) {
        r.footRight = i;
        if (p.h[i] <= r.levelRight + tolerance) break;
    }

    // 5a: straight lines over the band of each flank.
    const auto inBand = [&](Real level) {
        const Real rise = r.apexH - level;
        return [&p, level, rise, &params](std::size_t i) {
            const Real rel = (p.h[i] - level) / rise;
            return rel >= params.bandLo && rel <= params.bandHi;
        };
    };
    r.left = fitLine(p, r.footLeft, r.apexFirst, inBand(r.levelLeft));
    r.right = fitLine(p, r.apexLast, r.footRight, inBand(r.levelRight));
    // 5b: the half-piles [foot, apex].
    r.integralLeft = integralOverBins(p, r.footLeft, r.apexFirst);
    r.integralRight = integralOverBins(p, r.apexLast, r.footRight);

    Real sum = 0;
    int finite = 0;
    for (const LineFit* f : {&r.left, &r.right}) {
        if (std::isnan(f->angleDeg)) continue;
        sum += f->angleDeg;
        ++finite;
    }
    r.meanAngleDeg = finite > 0 ? sum / finite : kNaN;
    if (std::isnan(r.left.angle))
        r.notes.push_back("warning: fewer than 2 bins in the band of the left flank");
    if (std::isnan(r.right.angle))
        r.notes.push_back("warning: fewer than 2 bins in the band of the right flank");
    return r;
}

Table toTable(const Repose& result) {
    const SurfaceProfile& p = result.profile;
    Table t;
    t.name = "repose_profile";
    t.add("x", "m").values = p.x;
    t.add("h", "m").values = p.h;
    t.add("fit_left", "m");
    t.add("fit_right", "m");
    for (std::size_t i = 0; i < p.x.size(); ++i) {
        const bool left = i >= result.footLeft && i <= result.apexFirst && !std::isnan(result.left.slope);
        const bool right = i >= result.apexLast && i <= result.footRight && !std::isnan(result.right.slope);
        t.columns[2].values.push_back(left ? result.left.slope * p.x[i] + result.left.intercept : kNaN);
        t.columns[3].values.push_back(right ? result.right.slope * p.x[i] + result.right.intercept : kNaN);
    }
    t.notes.push_back(p.height == SurfaceHeight::Top
                          ? "surface h(x) = highest grain point of the grains centred in the bin"
                          : "surface h(x) = highest grain centre in the bin (a constant offset below the "
                            "surface; slopes are unaffected)");
    t.notes.push_back(noteLine("repose_left_deg", result.left.angleDeg, "deg"));
    t.notes.push_back(noteLine("repose_right_deg", result.right.angleDeg, "deg"));
    t.notes.push_back(noteLine("repose_mean_deg", result.meanAngleDeg, "deg"));
    t.notes.push_back(noteLine("slope_left", result.left.slope));
    t.notes.push_back(noteLine("intercept_left", result.left.intercept, "m"));
    t.notes.push_back(noteLine("slope_right", result.right.slope));
    t.notes.push_back(noteLine("intercept_right", result.right.intercept, "m"));
    t.notes.push_back(noteLine("integral_left_deg", result.integralLeft.angleDeg, "deg"));
    t.notes.push_back(noteLine("integral_right_deg", result.integralRight.angleDeg, "deg"));
    t.notes.push_back(noteLine("apex_x", result.apexX, "m"));
    t.notes.push_back(noteLine("apex_h", result.apexH, "m"));
    t.notes.push_back(noteLine("bin_width", p.binWidth, "m"));
    for (const std::string& n : result.notes) t.notes.push_back(n);
    return t;
}

}  // namespace granulab::analysis
