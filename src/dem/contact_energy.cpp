// SPDX-License-Identifier: MIT
// Elastic energy stored in the contacts, for the energy balance (no side effects): the springs of
// the depth laws (cfddem spec section 3) and, for the gc2d area law (gc2d spec section 3.2), the
// estimate F_n h_eff / 2 plus the tangential spring; for area_potential the exact potential
// E A^2/(2 l0^2) - k_coh A (Feng, Han & Owen 2012).
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "core/parallel.hpp"
#include "dem/contact/kernel.hpp"
#include "dem/forces.hpp"
#include "dem/forces_area.hpp"
#include "dem/forces_detail.hpp"
#include "geom/segment.hpp"

namespace granulab::dem {

namespace {

using detail::kAreaForm;
using detail::kDepthForm;

/// Energy of the area contacts of one bucket: for the gc2d law the estimate F_n h_eff / 2, for
/// area_potential the exact potential E A^2/(2 l0^2) - k_coh A; plus k_t xi^2 / 2.
template <class N, class T>
Real areaEnergy(const model::ParticleStore& s, const model::WallSet& walls, const ContactList& cl,
                std::uint32_t b, std::uint32_t e, const LawTable& laws, bool wall, const ShapeContext& sc,
                geom::FeatureStats& features) {
    constexpr bool kPotential = std::is_same_v<N, AreaPotentialNormal>;
    Real energy = 0;
    const std::uint32_t nm = laws.materialCount();
    for (std::uint32_t p = b; p < e; ++p) {
        const std::uint32_t i = cl.first[p];
        geom::FeatureCache cache = cl.features[p];  // a copy: energies do not disturb the tracking
        geom::AreaContact g;
        std::uint32_t otherMat;
        Real l;
        if (wall) {
            const auto& seg = walls.segments[cl.second[p]];
            g = area::wallGeometry(s, sc, walls, i, cl.second[p], cache, features);
            otherMat = seg.material;
            l = kPotential ? s.radius[i] : norm(g.point - Vec2{s.x[i], s.y[i]});
            if (!kPotential && walls.walls[seg.wall].body) {  // r_j from the body's centroid, as in the force
                const Real rj = norm(g.point - walls.bodyCentroid[seg.wall]);
                l = l + rj > 0 ? l * rj / (l + rj) : 0;
            }
        } else {
            const std::uint32_t j = cl.second[p];
            g = area::pairGeometry(s, sc, i, j, cache, features);
            otherMat = s.material[j];
            const Real ri = kPotential ? s.radius[i] : norm(g.point - Vec2{s.x[i], s.y[i]});
            const Real rj = kPotential ? s.radius[j] : norm(g.point - Vec2{s.x[j], s.y[j]});
            l = ri + rj > 0 ? ri * rj / (ri + rj) : 0;
        }
        if (!g.touching || !(l > 0)) continue;
        const ContactLaw& law = laws.laws()[static_cast<std::size_t>(s.material[i]) * nm + otherMat];
        const N& nl = *std::get_if<N>(&law.normal);
        if constexpr (kPotential) {
            energy += nl.potential(g.area, 1.0 / l);
        } else {
            const Real h = g.area / l;
            energy += 0.5 * nl.E * h * h;
        }
        if constexpr (std::is_same_v<T, AreaFriction>) {
            const Real kt = std::get_if<AreaFriction>(&law.tangential)->kt;
            energy += 0.5 * kt * cl.xi[p] * cl.xi[p];
        }
    }
    return energy;
}
}  // namespace

Real contactEnergy(const model::ParticleStore& s, const model::WallSet& walls, const NeighborList& list,
                   const LawTable& laws, const model::ShapePool& shapes, Real scale, int threads) {
    const std::uint32_t nm = laws.materialCount();
    ShapeContext sc;  // own world corners and statistics: energies do not disturb the step
    sc.pool = &shapes;
    sc.anyPolygon = shapes.size() > 0;
    sc.scale = scale;
    sc.update(s, threads);
    // One partial sum per slot tile, added in tile order: the same for any thread count.
    const std::uint32_t tiles = list.tiles.slots == s.size() ? list.tiles.count : 0;
    std::vector<Real> partial(std::max<std::uint32_t>(tiles, 1), 0.0);
    const auto eval = [&](const ContactList& cl, bool wall, std::uint32_t firstBucket,
                          std::uint32_t endBucket, Real& energy, geom::FeatureStats& features) {
        detail::forEachBucketIn(
            cl, laws, firstBucket, endBucket,
            [&](auto* nT, auto* dT, auto* tT, std::uint32_t b, std::uint32_t e) {
                using N = std::remove_pointer_t<decltype(nT)>;
                using D = std::remove_pointer_t<decltype(dT)>;
                using T = std::remove_pointer_t<decltype(tT)>;
                if constexpr (kAreaForm<N, D, T>) {
                    energy += areaEnergy<N, T>(s, walls, cl, b, e, laws, wall, sc, features);
                } else if constexpr (kDepthForm<N, D, T>) {
                    for (std::uint32_t p = b; p < e; ++p) {
                        const std::uint32_t i = cl.first[p];
                        Real overlap, reff;
                        std::uint32_t otherMat;
                        if (wall) {
                            const auto& seg = walls.segments[cl.second[p]];
                            const auto g = detail::wallContact(walls, seg, {s.x[i], s.y[i]}, s.radius[i]);
                            overlap = g.touching ? g.overlap : 0;
                            reff = s.radius[i];
                            otherMat = seg.material;
                        } else {
                            const std::uint32_t j = cl.second[p];
                            const Real dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
                            overlap = s.radius[i] + s.radius[j] - std::sqrt(dx * dx + dy * dy);
                            reff = s.radius[i] * s.radius[j] / (s.radius[i] + s.radius[j]);
                            otherMat = s.material[j];
                        }
                        if (overlap <= 0) continue;
                        const auto law = detail::resolve<N, D, T>(
                            laws.laws()[static_cast<std::size_t>(s.material[i]) * nm + otherMat]);
                        energy += dem::contactEnergy(law, overlap, reff, cl.xi[p],
                                                     cl.zeta.empty() ? 0.0 : cl.zeta[p]);
                    }
                }
            });
    };
    if (tiles == 0) {  // lists not built for this store (before the first rebuild): all buckets
        geom::FeatureStats features;
        for (const bool wall : {false, true}) {
            const ContactList& cl = wall ? list.wallPairs : list.pairs;
            if (cl.bucketStart.size() > 1)
                eval(cl, wall, 0, static_cast<std::uint32_t>(cl.bucketStart.size() - 1), partial[0],
                     features);
        }
        return partial[0];
    }
    parallelFor(threads, tiles, [&](std::size_t t) {
        geom::FeatureStats features;  // counted nowhere: energies are not the step's work
        const auto tile = static_cast<std::uint32_t>(t);
        const std::uint32_t first = list.bucket(tile, false, 0), end = list.bucket(tile + 1, false, 0);
        eval(list.pairs, false, first, end, partial[t], features);
        eval(list.wallPairs, true, first, end, partial[t], features);
    });
    Real energy = 0;
    for (const Real e : partial) energy += e;
    return energy;
}

}  // namespace granulab::dem
