// SPDX-License-Identifier: MIT
// Displacements averaged on test areas, central-difference strains and the plane-strain elastic
// constants (gc2d spec section 7 item 10, Eq. 4.2-4.5 and 4.11).
#include "analysis/dem_strain.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace granulab::analysis {

namespace {

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();

/// Mean and sample standard deviation of the finite values (NaN, NaN when none).
void meanStd(const std::vector<Real>& v, Real& mean, Real& sd) {
    Real s = 0, s2 = 0;
    std::size_t n = 0;
    for (const Real x : v)
        if (std::isfinite(x)) {
            s += x;
            s2 += x * x;
            ++n;
        }
    if (n == 0) {
        mean = sd = kNaN;
        return;
    }
    const auto nr = static_cast<Real>(n);
    mean = s / nr;
    sd = n > 1 ? std::sqrt(std::max<Real>(0, (s2 - nr * mean * mean) / (nr - 1))) : 0;
}

std::string fmt(Real v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

}  // namespace

StrainGrid strainGrid(const GrainFrame& reference, const GrainFrame& loaded, const StressGrid& stress) {
    const TestAreaGrid& grid = stress.grid;
    checkGrid(grid, "strainGrid");
    const std::size_t areas = grid.count();
    if (stress.sigmaXx.size() != areas || stress.sigmaZz.size() != areas)
        throw std::invalid_argument("strainGrid: the stress grid's vectors do not match its grid");
    std::unordered_map<std::int64_t, std::size_t> ref;
    ref.reserve(reference.size());
    for (std::size_t i = 0; i < reference.size(); ++i) ref.emplace(reference.id[i], i);
    std::vector<std::size_t> match(loaded.size(), reference.size());
    std::size_t unmatched = 0;
    for (std::size_t i = 0; i < loaded.size(); ++i) {
        const auto it = ref.find(loaded.id[i]);
        if (it == ref.end())
            ++unmatched;
        else
            match[i] = it->second;
    }
    const AreaMembers members = areaMembers(grid, loaded.size(), [&](std::size_t i, Vec2& lo, Vec2& hi) {
        lo = hi = {loaded.x[i], loaded.y[i]};
        return match[i] < reference.size();
    });
    StrainGrid out;
    out.grid = grid;
    for (auto* v : {&out.ux, &out.uz, &out.uxx, &out.uzz, &out.nu, &out.E, &out.K}) v->assign(areas, kNaN);
    out.grains.assign(areas, 0);
    for (std::size_t k = 0; k < areas; ++k) {
        Real sx = 0, sz = 0;
        for (std::size_t m = members.start[k]; m < members.start[k + 1]; ++m) {
            const std::size_t i = members.items[m], r = match[i];
            sx += reference.x[r] - loaded.x[i];  // u = x(g ~ 0) - x'(g)
            sz += reference.y[r] - loaded.y[i];
        }
        out.grains[k] = members.start[k + 1] - members.start[k];
        if (out.grains[k] == 0) continue;
        out.ux[k] = sx / static_cast<Real>(out.grains[k]);
        out.uz[k] = sz / static_cast<Real>(out.grains[k]);
    }
    for (std::size_t j = 0; j < grid.ny; ++j)
        for (std::size_t i = 0; i < grid.nx; ++i) {
            const std::size_t k = grid.index(i, j);
            if (i > 0 && i + 1 < grid.nx)
                out.uxx[k] = (out.ux[grid.index(i + 1, j)] - out.ux[grid.index(i - 1, j)]) / (2 * grid.sx);
            if (j > 0 && j + 1 < grid.ny)
                out.uzz[k] = (out.uz[grid.index(i, j + 1)] - out.uz[grid.index(i, j - 1)]) / (2 * grid.sy);
            const Real exx = out.uxx[k], ezz = out.uzz[k], sxx = stress.sigmaXx[k], szz = stress.sigmaZz[k];
            const Real nuDen = (exx - ezz) * (sxx + szz);
            if (!std::isfinite(nuDen) || nuDen == 0) continue;
            const Real nu = (szz * exx - sxx * ezz) / nuDen;  // Eq. 4.2-4.4
            out.nu[k] = nu;
            const Real eDen = exx * (1 - nu) + nu * ezz;
            if (eDen == 0) continue;
            out.E[k] = sxx * (1 + nu) * (1 - 2 * nu) / eDen;  // Eq. 4.5
            const Real kDen = 2 * (1 + nu) * (1 - 2 * nu);
            if (kDen != 0) out.K[k] = out.E[k] / kDen;  // Eq. 4.11
        }
    meanStd(out.nu, out.nuMean, out.nuStd);
    meanStd(out.E, out.EMean, out.EStd);
    meanStd(out.K, out.KMean, out.KStd);
    if (unmatched > 0)
        out.notes.push_back("loaded grains without a reference grain (skipped): " +
                            std::to_string(unmatched));
    if (!std::isfinite(out.nuMean)) out.notes.push_back("no area with finite elastic constants");
    return out;
}

Table strainTable(const StrainGrid& s, const StressGrid& stress) {
    Table t;
    t.name = "elastic";
    t.notes.push_back("nu_avg = " + fmt(s.nuMean) + " +- " + fmt(s.nuStd));
    t.notes.push_back("E_avg = " + fmt(s.EMean) + " +- " + fmt(s.EStd) + " [N/m]");
    t.notes.push_back("K_avg = " + fmt(s.KMean) + " +- " + fmt(s.KStd) + " [N/m]");
    t.notes.push_back("u = x(reference) - x(loaded): compressive strains positive");
    t.notes.insert(t.notes.end(), s.notes.begin(), s.notes.end());
    const char* names[] = {"x", "z", "u_x", "u_z", "u_xx", "u_zz", "sigma_xx", "sigma_zz", "nu", "E", "K"};
    const char* units[] = {"m", "m", "m", "m", "1", "1", "N/m", "N/m", "1", "N/m", "N/m"};
    for (std::size_t c = 0; c < 11; ++c) t.add(names[c], units[c]);
    for (std::size_t k = 0; k < s.grid.count(); ++k) {
        const Vec2 c = s.grid.centre(k);
        const Real row[] = {
            c.x,     c.y,    s.ux[k], s.uz[k], s.uxx[k], s.uzz[k], stress.sigmaXx[k], stress.sigmaZz[k],
            s.nu[k], s.E[k], s.K[k]};
        for (std::size_t col = 0; col < 11; ++col) t.columns[col].values.push_back(row[col]);
    }
    return t;
}

}  // namespace granulab::analysis
