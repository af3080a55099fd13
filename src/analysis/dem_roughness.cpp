// SPDX-License-Identifier: MIT
// Surface-roughness power spectrum of a pile (gc2d spec section 7 item 11).
#include "analysis/dem_roughness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/table_note.hpp"

namespace granulab::analysis {

namespace {

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
constexpr std::size_t kMaxSamples = 20000;

/// The bins of [from, to] with interior gaps filled; counts the filled bins.
std::vector<Real> rangeSamples(const SurfaceProfile& p, Real from, Real to, std::vector<Real>& x,
                               std::size_t& filled) {
    std::vector<std::size_t> inRange;
    for (std::size_t i = 0; i < p.x.size(); ++i)
        if (p.x[i] >= from && p.x[i] <= to) inRange.push_back(i);
    while (!inRange.empty() && std::isnan(p.h[inRange.back()])) inRange.pop_back();
    std::size_t start = 0;
    while (start < inRange.size() && std::isnan(p.h[inRange[start]])) ++start;
    std::vector<Real> h;
    x.clear();
    std::size_t lastGood = 0;
    for (std::size_t k = start; k < inRange.size(); ++k) {
        const std::size_t i = inRange[k];
        x.push_back(p.x[i]);
        h.push_back(p.h[i]);
        if (std::isnan(p.h[i])) continue;
        const std::size_t here = h.size() - 1;
        for (std::size_t g = lastGood + 1; g < here; ++g) {  // fill the gap since the last good bin
            const Real t = static_cast<Real>(g - lastGood) / static_cast<Real>(here - lastGood);
            h[g] = (1 - t) * h[lastGood] + t * h[here];
            ++filled;
        }
        lastGood = here;
    }
    return h;
}

}  // namespace

std::vector<Real> powerSpectrum(const std::vector<Real>& samples) {
    const std::size_t n = samples.size();
    if (n == 0) throw std::invalid_argument("powerSpectrum: no samples");
    std::vector<Real> c(n), s(n);  // twiddles exp(-2 pi i q / n)
    for (std::size_t q = 0; q < n; ++q) {
        const Real phase = 2 * kPi * static_cast<Real>(q) / static_cast<Real>(n);
        c[q] = std::cos(phase);
        s[q] = std::sin(phase);
    }
    const std::size_t half = n / 2;
    std::vector<Real> power(half + 1);
    const Real n2 = static_cast<Real>(n) * static_cast<Real>(n);
    for (std::size_t m = 0; m <= half; ++m) {
        Real re = 0, im = 0;
        std::size_t q = 0;  // (j m) mod n
        for (std::size_t j = 0; j < n; ++j) {
            re += samples[j] * c[q];
            im -= samples[j] * s[q];
            q += m;
            if (q >= n) q -= n;
        }
        const Real weight = (m == 0 || 2 * m == n) ? 1 : 2;
        power[m] = weight * (re * re + im * im) / n2;
    }
    return power;
}

RoughnessSpectrum roughnessSpectrum(const SurfaceProfile& profile, const RoughnessParams& params) {
    const std::string who = "roughnessSpectrum";
    if (params.ranges.empty()) throw std::invalid_argument(who + ": no x range given");
    if (!(params.baseLength > 0) || !std::isfinite(params.baseLength))
        throw std::invalid_argument(who + ": baseLength l must be finite and > 0");
    for (const auto& [from, to] : params.ranges)
        if (!std::isfinite(from) || !std::isfinite(to) || !(from < to))
            throw std::invalid_argument(who + ": every range needs finite from < to");

    RoughnessSpectrum r;
    r.binWidth = profile.binWidth;
    r.baseLength = params.baseLength;
    std::vector<std::vector<Real>> xs, hs;
    std::size_t n = std::numeric_limits<std::size_t>::max();
    for (const auto& [from, to] : params.ranges) {
        xs.emplace_back();
        hs.push_back(rangeSamples(profile, from, to, xs.back(), r.interpolatedBins));
        if (hs.back().size() > kMaxSamples)
            throw std::invalid_argument(who + ": more than 20000 bins in a range; use wider bins");
        n = std::min(n, hs.back().size());
    }
    if (n < 4) {
        r.notes.push_back("warning: a range holds fewer than 4 non-empty bins; no spectrum");
        r.rmsDeviation = kNaN;
        return r;
    }
    r.samples = n;
    const std::size_t half = n / 2;
    r.power.assign(half, 0);
    Real meanSquare = 0;  // [m^2]
    for (std::size_t a = 0; a < hs.size(); ++a) {
        const std::size_t skip = (hs[a].size() - n) / 2;  // keep the central n bins
        std::vector<Real> x(xs[a].begin() + static_cast<std::ptrdiff_t>(skip),
                            xs[a].begin() + static_cast<std::ptrdiff_t>(skip + n));
        std::vector<Real> d(hs[a].begin() + static_cast<std::ptrdiff_t>(skip),
                            hs[a].begin() + static_cast<std::ptrdiff_t>(skip + n));
        // Least-squares repose line over the n bins.
        Real mx = 0, my = 0;
        for (std::size_t j = 0; j < n; ++j) {
            mx += x[j];
            my += d[j];
        }
        mx /= static_cast<Real>(n);
        my /= static_cast<Real>(n);
        Real sxx = 0, sxy = 0;
        for (std::size_t j = 0; j < n; ++j) {
            sxx += (x[j] - mx) * (x[j] - mx);
            sxy += (x[j] - mx) * (d[j] - my);
        }
        LineFit line;
        line.slope = sxy / sxx;
        line.intercept = my - line.slope * mx;
        line.xFrom = x.front();
        line.xTo = x.back();
        line.points = n;
        line.angle = std::atan(std::abs(line.slope));
        line.angleDeg = line.angle * 180 / kPi;
        r.lines.push_back(line);
        for (std::size_t j = 0; j < n; ++j) {
            d[j] -= line.slope * x[j] + line.intercept;
            meanSquare += d[j] * d[j];
        }
        const std::vector<Real> p = powerSpectrum(d);
        for (std::size_t m = 1; m <= half; ++m) r.power[m - 1] += p[m];
    }
    r.ranges = hs.size();
    for (Real& p : r.power) p /= static_cast<Real>(r.ranges);
    r.rmsDeviation = std::sqrt(meanSquare / static_cast<Real>(n * r.ranges));
    r.k.resize(half);
    for (std::size_t m = 1; m <= half; ++m)
        r.k[m - 1] = 2 * kPi * params.baseLength * static_cast<Real>(m) / (static_cast<Real>(n) * r.binWidth);
    if (r.interpolatedBins > 0)
        r.notes.push_back(fmt::format("{} empty bins inside the ranges were filled by linear interpolation",
                                      r.interpolatedBins));
    return r;
}

Table toTable(const RoughnessSpectrum& result) {
    Table t;
    t.name = "roughness_spectrum";
    t.add("k", "1/l").values = result.k;
    t.add("P", "m^2").values = result.power;
    t.notes.push_back(
        "P = one-sided power spectrum of the surface's deviation from the least-squares repose line "
        "(not normalised: sum P = mean square deviation), averaged over the ranges; k = 2 pi / "
        "wavelength in units of 1/l (gc2d spec 7 item 11)");
    t.notes.push_back(noteLine("base_length_l", result.baseLength, "m"));
    t.notes.push_back(noteLine("bin_width", result.binWidth, "m"));
    t.notes.push_back(noteLine("samples_per_range", static_cast<Real>(result.samples)));
    t.notes.push_back(noteLine("ranges", static_cast<Real>(result.ranges)));
    t.notes.push_back(noteLine("rms_deviation", result.rmsDeviation, "m"));
    for (std::size_t a = 0; a < result.lines.size(); ++a) {
        t.notes.push_back(noteLine(fmt::format("range{}_slope", a), result.lines[a].slope));
        t.notes.push_back(noteLine(fmt::format("range{}_intercept", a), result.lines[a].intercept, "m"));
        t.notes.push_back(noteLine(fmt::format("range{}_angle_deg", a), result.lines[a].angleDeg, "deg"));
    }
    for (const std::string& n : result.notes) t.notes.push_back(n);
    return t;
}

}  // namespace granulab::analysis
