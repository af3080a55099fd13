// SPDX-License-Identifier: MIT
// Coarse-grained stress on test areas (gc2d spec section 7 items 7-8, Eq. 2.52): internal
// contacts cancel because both opposite forces act at the same point, so only the forces across
// the area's boundary (and wall forces) remain.
#include "analysis/dem_stress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "analysis/convex_hull.hpp"

namespace granulab::analysis {

PrincipalStress principalStress(Real sxx, Real szz, Real sxz) {
    const Real mean = 0.5 * (sxx + szz), half = 0.5 * (sxx - szz);
    const Real radius = std::hypot(half, sxz);  // Mohr circle
    PrincipalStress p{mean + radius, mean - radius, 0};
    if (radius == 0) return p;
    Real theta = 0.5 * std::atan2(sxz, half);  // major axis from +x, in (-90, 90] deg
    Vec2 axis{std::cos(theta), std::sin(theta)};
    if (axis.y < 0 || (axis.y == 0 && axis.x < 0)) axis = -axis;
    p.psi = std::atan2(axis.x, axis.y) * 180 / kPi;
    if (p.psi <= -90) p.psi += 180;
    return p;
}

StressGrid stressGrid(const GrainFrame& grains, const ContactFrame& contacts, const TestAreaGrid& grid,
                      const StressParams& params) {
    checkGrid(grid, "stressGrid");
    const std::size_t n = grains.size(), areas = grid.count();
    std::unordered_map<std::int64_t, std::size_t> slot;
    slot.reserve(n);
    for (std::size_t i = 0; i < n; ++i) slot.emplace(grains.id[i], i);
    const auto find = [&](std::int64_t id) {
        const auto it = slot.find(id);
        if (it == slot.end())
            throw std::invalid_argument("stressGrid: contact names grain id " + std::to_string(id) +
                                        " that is not in the grain frame");
        return it->second;
    };
    // Forces per grain (compressed): application point and force on that grain.
    std::vector<std::size_t> start(n + 1, 0);
    std::vector<std::size_t> ia(contacts.size()), ib(contacts.size(), n);
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        ia[c] = find(contacts.a[c]);
        ++start[ia[c] + 1];
        if (contacts.b[c] >= 0) {
            ib[c] = find(contacts.b[c]);
            ++start[ib[c] + 1];
        }
    }
    for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    std::vector<Vec2> point(start.back()), force(start.back());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        const Vec2 p{contacts.px[c], contacts.py[c]}, F{contacts.fx[c], contacts.fy[c]};
        point[fill[ia[c]]] = p;
        force[fill[ia[c]]++] = F;
        if (ib[c] < n) {
            point[fill[ib[c]]] = p;
            force[fill[ib[c]]++] = -F;
        }
    }
    const AreaMembers members = areaMembers(grid, n, [&](std::size_t i, Vec2& lo, Vec2& hi) {
        lo = hi = {grains.x[i], grains.y[i]};
        return true;
    });

    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    StressGrid out;
    out.grid = grid;
    for (auto* v : {&out.sigmaXx, &out.sigmaZz, &out.sigmaXz, &out.major, &out.minor, &out.psi})
        v->assign(areas, nan);
    out.hullArea.assign(areas, 0);
    out.grains.assign(areas, 0);
    out.forces.assign(areas, 0);
    std::vector<Vec2> points;
    std::size_t degenerate = 0, sparse = 0;
    for (std::size_t k = 0; k < areas; ++k) {
        const Vec2 o = grid.centre(k);
        points.clear();
        Real xx = 0, zz = 0, xz = 0, zx = 0;  // sum x_i F_j [N m]
        for (std::size_t m = members.start[k]; m < members.start[k + 1]; ++m) {
            const std::size_t i = members.items[m];
            for (std::size_t f = start[i]; f < start[i + 1]; ++f) {
                const Vec2 x = point[f] - o, F = force[f];
                xx += x.x * F.x;
                zz += x.y * F.y;
                xz += x.x * F.y;
                zx += x.y * F.x;
                points.push_back(point[f]);
            }
        }
        out.grains[k] = members.start[k + 1] - members.start[k];
        out.forces[k] = points.size();
        if (out.grains[k] < params.minGrains) ++sparse;
        const Real V = convexHullArea(points);
        out.hullArea[k] = V;
        if (!(V > 0)) {
            ++degenerate;
            continue;
        }
        // Eq. 2.52, compressive-positive: -1/(2V) sum (x_i F_j + x_j F_i).
        out.sigmaXx[k] = -xx / V;
        out.sigmaZz[k] = -zz / V;
        out.sigmaXz[k] = -0.5 * (xz + zx) / V;
        const PrincipalStress p = principalStress(out.sigmaXx[k], out.sigmaZz[k], out.sigmaXz[k]);
        out.major[k] = p.major;
        out.minor[k] = p.minor;
        out.psi[k] = p.psi;
    }
    if (degenerate > 0)
        out.notes.push_back("areas without a force hull (stress = NaN): " + std::to_string(degenerate) +
                            " of " + std::to_string(areas));
    if (sparse > 0)
        out.notes.push_back("areas with fewer than " + std::to_string(params.minGrains) +
                            " grains (rule of thumb 100-200): " + std::to_string(sparse) + " of " +
                            std::to_string(areas));
    return out;
}

Table stressTable(const StressGrid& s) {
    Table t;
    t.name = "stress";
    t.notes.push_back("test area = " + std::to_string(s.grid.w) + " x " + std::to_string(s.grid.h) + " [m]");
    t.notes.push_back("step = " + std::to_string(s.grid.sx) + " x " + std::to_string(s.grid.sy) + " [m]");
    t.notes.push_back("compressive stress positive (-sigma of Eq. 2.52)");
    t.notes.insert(t.notes.end(), s.notes.begin(), s.notes.end());
    const char* names[] = {"x",           "z",   "sigma_xx", "sigma_zz", "sigma_xz", "sigma_major",
                           "sigma_minor", "psi", "V",        "grains",   "forces"};
    const char* units[] = {"m", "m", "N/m", "N/m", "N/m", "N/m", "N/m", "deg", "m^2", "1", "1"};
    for (std::size_t c = 0; c < 11; ++c) t.add(names[c], units[c]);
    for (std::size_t k = 0; k < s.grid.count(); ++k) {
        const Vec2 c = s.grid.centre(k);
        const Real row[] = {c.x,
                            c.y,
                            s.sigmaXx[k],
                            s.sigmaZz[k],
                            s.sigmaXz[k],
                            s.major[k],
                            s.minor[k],
                            s.psi[k],
                            s.hullArea[k],
                            static_cast<Real>(s.grains[k]),
                            static_cast<Real>(s.forces[k])};
        for (std::size_t col = 0; col < 11; ++col) t.columns[col].values.push_back(row[col]);
    }
    return t;
}

}  // namespace granulab::analysis
