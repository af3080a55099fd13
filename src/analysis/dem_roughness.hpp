// SPDX-License-Identifier: MIT
// Surface-roughness power spectrum of a pile (gc2d spec section 7 item 11, the cohesion
// diagnostics of section 8.8): the power spectrum of the surface's deviation from its fitted
// repose line, averaged over several x ranges (the draining-crater regions A and B), with the
// wavenumber in units of 1/l (l = base length).
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "analysis/dem_surface.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// One-sided discrete power spectrum of equally spaced samples (no detrending, no window):
/// X_m = sum_j s_j exp(-2 pi i j m / n); P_m = c_m |X_m|^2 / n^2 for m = 0 .. floor(n/2), with
/// c_m = 2 except c_0 = 1 and c_{n/2} = 1 (even n), so sum_m P_m = mean(s^2) (Parseval) and a sine
/// of amplitude A with an integer number m of periods over the samples gives P_m = A^2/2.
/// Plain DFT, O(n^2): n up to a few thousand. Throws std::invalid_argument for n == 0.
std::vector<Real> powerSpectrum(const std::vector<Real>& samples);

struct RoughnessParams {
    std::vector<std::pair<Real, Real>> ranges;  ///< [m] x ranges [from, to] (regions A, B ...), >= 1
    Real baseLength = 0;                        ///< [m] l, the unit of 1/k (> 0)
};

struct RoughnessSpectrum {
    /// [1/l] wavenumber k l = 2 pi l m / (n dx), m = 1 .. floor(n/2) (k = 2 pi / wavelength).
    std::vector<Real> k;
    std::vector<Real> power;           ///< [m^2] P_m (powerSpectrum) of the deviation, averaged over ranges
    std::size_t ranges = 0;            ///< ranges averaged
    std::size_t samples = 0;           ///< n: bins per range after trimming to the shortest range
    Real binWidth = 0;                 ///< [m] dx
    Real baseLength = 0;               ///< [m] l
    Real rmsDeviation = 0;             ///< [m] sqrt(mean square deviation), over the ranges
    std::vector<LineFit> lines;        ///< the fitted repose line per range
    std::size_t interpolatedBins = 0;  ///< empty bins inside a range, filled linearly
    std::vector<std::string> notes;
};

/// Per range: the bins with centre in [from, to], empty bins at the ends dropped and inside filled
/// by linear interpolation; every range is cut to the central n bins, n = the shortest range's
/// count (equal n gives equal k grids); the least-squares line over those n bins is subtracted
/// (the fitted repose line), and the power spectra of the deviations are averaged. A range with
/// fewer than 4 bins makes the result NaN with a note. Throws std::invalid_argument for no range,
/// from >= to, baseLength <= 0 or more than 20000 bins per range.
RoughnessSpectrum roughnessSpectrum(const SurfaceProfile& profile, const RoughnessParams& params);

/// Table "roughness_spectrum": k [1/l], P [m^2] (not normalised; sum of P = mean square deviation
/// minus its k = 0 part); notes: l, dx, n, ranges, rms deviation, the fitted lines.
Table toTable(const RoughnessSpectrum& result);

}  // namespace granulab::analysis
