// SPDX-License-Identifier: MIT
// Particle generation: lattices (and gc2d's rect/fcc GENERATE_BLOCK lattices with jitter and
// velocity ranges, spec section 6.5), random sequential addition, size distributions, thermal
// velocities, polygon shapes (gc2d spec section 2.3); heaps are in dem/generate_heap.cpp. Every random draw
// comes from CounterRng(seed, stream): block positions, radii and temperatures from stream 1000 + block
// index, polygon shapes and rotations from the separate shape streams below, so adding polygon
// grains never changes the draws of disk scenes.
#include "dem/generate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

#include "core/rng.hpp"
#include "geom/polygon.hpp"
#include "model/grain_shapes.hpp"
#include "model/size_bounds.hpp"

namespace granulab::dem {

using model::BlockDef;
using model::Grain;
using model::kDiskShape;
using model::maxRadius;
using model::minRadius;
using model::ParticleDef;
using model::SceneDef;
using model::ShapeDef;
using model::ShapePool;
using model::SizeDistDef;

namespace {

std::vector<Vec2> latticeSites(const BlockDef& b) {
    std::vector<Vec2> sites;
    const Real a = b.spacing;
    const bool hex = b.lattice == BlockDef::Lattice::Hexagonal;
    const Real dy = hex ? a * std::sqrt(3.0) / 2.0 : a;
    const Vec2 origin = b.origin.value_or(Vec2{b.xmin + 0.5 * a, b.ymin + 0.5 * a});
    // Lowest row index whose y is >= ymin, lowest column whose x >= xmin (allow origin outside).
    const long row0 = static_cast<long>(std::ceil((b.ymin - origin.y) / dy - 1e-12));
    for (long row = row0;; ++row) {
        const Real y = origin.y + static_cast<Real>(row) * dy;
        if (y >= b.ymax) break;
        const Real shift = (hex && (row % 2 != 0)) ? 0.5 * a : 0.0;
        const Real x0 = origin.x + shift;
        const long col0 = static_cast<long>(std::ceil((b.xmin - x0) / a - 1e-12));
        for (long col = col0;; ++col) {
            const Real x = x0 + static_cast<Real>(col) * a;
            if (x >= b.xmax) break;
            if (x < b.xmin || y < b.ymin) continue;
            sites.push_back({x, y});
            if (b.count >= 0 && static_cast<std::int64_t>(sites.size()) >= b.count) return sites;
        }
    }
    return sites;
}

/// Sites of the gc2d lattices (GENERATE_BLOCK, spec section 6.5): rect rows dy apart with sites
/// dx apart; fcc the same with every other row shifted by dx/2. Same filling rule as
/// latticeSites (half-open region, row by row, `count` cap).
std::vector<Vec2> gridSites(const BlockDef& b) {
    std::vector<Vec2> sites;
    const Real dx = b.grid.x, dy = b.grid.y;
    const bool fcc = b.lattice == BlockDef::Lattice::Fcc;
    const Vec2 origin = b.origin.value_or(Vec2{b.xmin + 0.5 * dx, b.ymin + 0.5 * dy});
    const long row0 = static_cast<long>(std::ceil((b.ymin - origin.y) / dy - 1e-12));
    for (long row = row0;; ++row) {
        const Real y = origin.y + static_cast<Real>(row) * dy;
        if (y >= b.ymax) break;
        const Real x0 = origin.x + ((fcc && (row % 2 != 0)) ? 0.5 * dx : 0.0);
        const long col0 = static_cast<long>(std::ceil((b.xmin - x0) / dx - 1e-12));
        for (long col = col0;; ++col) {
            const Real x = x0 + static_cast<Real>(col) * dx;
            if (x >= b.xmax) break;
            if (x < b.xmin || y < b.ymin) continue;
            sites.push_back({x, y});
            if (b.count >= 0 && static_cast<std::int64_t>(sites.size()) >= b.count) return sites;
        }
    }
    return sites;
}

/// gc2d *_EQUAL / *_GAUSS: each site moves by f dx (u - 1/2) along x and f dy (u' - 1/2) along y,
/// u uniform in [0, 1) or gc2d's special truncated Gaussian (N(1/2, 1/10) on [0, 1]), so within
/// +-f dx/2, +-f dy/2 (erratum 10: the y interval uses dy).
void jitterSites(const BlockDef& b, std::vector<Vec2>& sites, CounterRng& rng) {
    if (b.jitter == BlockDef::Jitter::None) return;
    const bool gauss = b.jitter == BlockDef::Jitter::Gauss;
    const Real wx = b.jitterFraction * b.grid.x, wy = b.jitterFraction * b.grid.y;
    for (Vec2& s : sites) {
        const Real ux = gauss ? model::specialGaussianUnit(rng) : rng.uniform();
        const Real uy = gauss ? model::specialGaussianUnit(rng) : rng.uniform();
        s += Vec2{wx * (ux - 0.5), wy * (uy - 0.5)};
    }
}

/// gc2d ANGLE_RANGE / VELOCITY_RANGE: adds a velocity of uniform direction in directionRange and
/// uniform magnitude in speedRange to particles [first, end). No draws for speed_range [0, 0].
void rangeVelocities(const BlockDef& b, std::vector<InitialParticle>& ps, std::size_t first,
                     CounterRng& rng) {
    if (!(b.speedRange.y > 0)) return;
    for (std::size_t k = first; k < ps.size(); ++k) {
        const Real angle = rng.uniform(b.directionRange.x, b.directionRange.y);
        const Real speed = rng.uniform(b.speedRange.x, b.speedRange.y);
        ps[k].velocity += Vec2{speed * std::cos(angle), speed * std::sin(angle)};
    }
}

/// Random sequential addition of disks with radii `radii` (largest first) into the region,
/// avoiding `existing` disks; returns false if a disk could not be placed.
bool placeRandom(const BlockDef& b, std::vector<Real>& radii, CounterRng& rng,
                 const std::vector<InitialParticle>& existing, std::vector<Vec2>& out, std::size_t& placed) {
    std::sort(radii.begin(), radii.end(), std::greater<>());
    const Real rmax = radii.empty() ? 0 : radii.front();
    Real existingMax = 0;
    for (const auto& p : existing) existingMax = std::max(existingMax, p.radius);
    const Real cell = 2 * std::max(rmax, existingMax);
    if (cell <= 0) return true;
    const auto cellKey = [&](Real x, Real y) {
        const auto cx = static_cast<std::int64_t>(std::floor(x / cell));
        const auto cy = static_cast<std::int64_t>(std::floor(y / cell));
        return (static_cast<std::uint64_t>(cx) << 32) ^ static_cast<std::uint64_t>(cy & 0xffffffff);
    };
    std::unordered_map<std::uint64_t, std::vector<std::pair<Vec2, Real>>> grid;
    for (const auto& p : existing)
        grid[cellKey(p.position.x, p.position.y)].push_back({p.position, p.radius});
    const auto fits = [&](Vec2 c, Real r) {
        const auto cx = static_cast<std::int64_t>(std::floor(c.x / cell));
        const auto cy = static_cast<std::int64_t>(std::floor(c.y / cell));
        for (std::int64_t ix = cx - 1; ix <= cx + 1; ++ix)
            for (std::int64_t iy = cy - 1; iy <= cy + 1; ++iy) {
                const std::uint64_t key =
                    (static_cast<std::uint64_t>(ix) << 32) ^ static_cast<std::uint64_t>(iy & 0xffffffff);
                auto it = grid.find(key);
                if (it == grid.end()) continue;
                for (const auto& [q, rq] : it->second)
                    if (norm2(c - q) < (r + rq) * (r + rq)) return false;
            }
        return true;
    };
    placed = 0;
    for (Real r : radii) {
        bool ok = false;
        for (int attempt = 0; attempt < 20000 && !ok; ++attempt) {
            const Vec2 c{rng.uniform(b.xmin + r, b.xmax - r), rng.uniform(b.ymin + r, b.ymax - r)};
            if (!(b.xmax - b.xmin > 2 * r && b.ymax - b.ymin > 2 * r)) break;
            if (fits(c, r)) {
                grid[cellKey(c.x, c.y)].push_back({c, r});
                out.push_back(c);
                ok = true;
            }
        }
        if (!ok) return false;
        ++placed;
    }
    return true;
}

/// Shape streams: explicit particle k draws from kParticleShapeStream + k, block b from
/// kBlockShapeStream + b (far from the block streams 1000 + b).
constexpr std::uint64_t kParticleShapeStream = 0x7368617065000000ULL;  // "shape"
constexpr std::uint64_t kBlockShapeStream = kParticleShapeStream + (1ULL << 32);
/// gc2d block streams (jitter, velocity ranges): kBlockJitterStream + b, kBlockRangeStream + b,
/// separate from the others, so the gc2d keys never change the draws of existing scenes.
constexpr std::uint64_t kBlockJitterStream = kParticleShapeStream + (2ULL << 32);
constexpr std::uint64_t kBlockRangeStream = kParticleShapeStream + (3ULL << 32);

Vec2 rotated(Vec2 v, Real angle) noexcept {
    const Real c = std::cos(angle), s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

/// Makes the polygon shapes of particles: one pool entry per named deterministic shape, made at
/// its first use and shared by all its particles; one entry per particle for random grains.
class ShapeMaker {
public:
    ShapeMaker(const SceneDef& scene, ShapePool& pool, Diagnostics& diags)
        : m_scene(scene), m_pool(pool), m_diags(diags) {}

    /// The [[shape]] called `name`, or nullptr ("disk", or unknown: reported by validate()).
    const ShapeDef* find(const std::string& name) const {
        for (const auto& s : m_scene.shapes)
            if (s.name == name) return &s;
        return nullptr;
    }

    struct Made {
        std::uint32_t shape = kDiskShape;  ///< pool index; kDiskShape if the shape is invalid
        Real angle = 0;                    ///< [rad] initial angle by rotation_mode
        Vec2 offset;                       ///< [m] centroid relative to the placement point, body frame
    };

    /// One particle's shape and rotation; draws from `rng` (grains, random rotations).
    Made make(const ShapeDef& def, CounterRng& rng) {
        Made m;
        if (def.kind == "grain") {
            const Grain g = randomGrain(def, rng);
            if (!geom::checkConvexPolygon(g.corners).ok()) {
                if (!m_grainReported) {  // practically impossible; report once per shape set
                    m_diags.error(
                        def.loc, "shape",
                        fmt::format(
                            "shape '{}': could not draw a convex grain from semi-axes ({:.4g}, {:.4g}) m; "
                            "make the grain less elongated or use fewer corners",
                            def.name, g.semiAxes.x, g.semiAxes.y));
                    m_grainReported = true;
                }
                return m;
            }
            m.shape = m_pool.add(g.corners);
            m.offset = geom::polygonMass(g.corners).centroid;
        } else {
            const auto it = m_named.find(def.name);
            if (it != m_named.end()) {
                m.shape = it->second;
            } else if (const auto corners = deterministicCorners(def)) {
                m.shape = m_pool.add(*corners);
                m_named[def.name] = m.shape;
            } else {
                return m;  // invalid parameters, reported by validate()
            }
        }
        m.angle = drawRotation(def, rng);
        return m;
    }

private:
    const SceneDef& m_scene;
    ShapePool& m_pool;
    Diagnostics& m_diags;
    std::map<std::string, std::uint32_t> m_named;
    bool m_grainReported = false;
};

/// Random Gaussian velocities with <m v_x^2> = T, zero net momentum, rescaled to exactly T.
void thermalVelocities(std::vector<InitialParticle>& ps, std::size_t first, Real temperature,
                       const std::vector<Real>& masses, CounterRng& rng) {
    const std::size_t n = ps.size() - first;
    if (n < 2 || temperature <= 0) return;
    Vec2 momentum;
    Real totalMass = 0;
    std::vector<Vec2> v(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Real s = std::sqrt(temperature / masses[k]);
        v[k] = {s * rng.normal(), s * rng.normal()};
        momentum += v[k] * masses[k];
        totalMass += masses[k];
    }
    const Vec2 vcm = momentum / totalMass;
    Real twiceKe = 0;
    for (std::size_t k = 0; k < n; ++k) {
        v[k] -= vcm;
        twiceKe += masses[k] * norm2(v[k]);
    }
    const Real dof = 2.0 * static_cast<Real>(n) - 2.0;
    const Real scale = twiceKe > 0 ? std::sqrt(temperature * dof / twiceKe) : 0.0;
    for (std::size_t k = 0; k < n; ++k) ps[first + k].velocity += v[k] * scale;
}

}  // namespace

InitialParticles generateParticles(const SceneDef& scene, const std::vector<std::string>& materialNames,
                                   Diagnostics& diags) {
    InitialParticles out;
    ShapeMaker shapes(scene, out.shapes, diags);
    auto materialOf = [&](const std::string& name) -> std::uint32_t {
        for (std::size_t k = 0; k < materialNames.size(); ++k)
            if (materialNames[k] == name) return static_cast<std::uint32_t>(k);
        return 0;  // unknown names are reported by validate()
    };
    auto densityOf = [&](std::uint32_t m) -> Real {
        for (const auto& md : scene.materials)
            if (md.name == materialNames[m]) return md.density;
        return 1.0;
    };
    for (std::size_t k = 0; k < scene.particles.size(); ++k) {
        const ParticleDef& p = scene.particles[k];
        InitialParticle ip;
        ip.position = p.position;  // the centroid for polygons
        ip.velocity = p.velocity;
        ip.angle = p.angle;
        ip.omega = p.omega;
        ip.radius = p.radius;
        ip.material = materialOf(p.material);
        ip.origin = static_cast<std::uint32_t>(out.origins.size());
        if (const ShapeDef* def = shapes.find(p.shape)) {
            CounterRng rng(scene.run.seed, kParticleShapeStream + k);
            const auto made = shapes.make(*def, rng);
            if (made.shape == kDiskShape) continue;  // invalid shape, reported elsewhere
            ip.shape = made.shape;
            ip.radius = out.shapes.circumradius[made.shape];
            ip.angle = made.angle + p.angle;  // the particle's own angle adds to the shape's rotation
        }
        out.origins.push_back(p.loc);
        out.particles.push_back(ip);
    }
    for (std::size_t bi = 0; bi < scene.blocks.size(); ++bi) {
        const BlockDef& b = scene.blocks[bi];
        CounterRng rng(scene.run.seed, 1000 + bi);
        const std::uint32_t origin = static_cast<std::uint32_t>(out.origins.size());
        out.origins.push_back(b.loc);
        const std::uint32_t mat = materialOf(b.material);
        const ShapeDef* def = shapes.find(b.shape);
        CounterRng shapeRng(scene.run.seed, kBlockShapeStream + bi);
        std::vector<Vec2> sites;
        std::vector<Real> radii;
        std::vector<ShapeMaker::Made> made;  // polygon blocks: per particle, in the order of sites
        if (b.lattice == BlockDef::Lattice::Random) {
            const auto n = static_cast<std::size_t>(std::max<std::int64_t>(b.count, 0));
            radii.resize(n);
            if (def) {
                // Shapes first; their circumradii are the exclusion radii of the placement, which
                // places the largest first: sort the shapes the same way (stable, deterministic).
                made.resize(n);
                for (std::size_t k = 0; k < n; ++k) {
                    made[k] = shapes.make(*def, shapeRng);
                    if (made[k].shape == kDiskShape) break;
                    radii[k] = out.shapes.circumradius[made[k].shape];
                }
                if (n > 0 && made.back().shape == kDiskShape) continue;  // invalid shape
                std::vector<std::size_t> order(n);
                std::iota(order.begin(), order.end(), std::size_t{0});
                std::stable_sort(order.begin(), order.end(),
                                 [&](std::size_t x, std::size_t y) { return radii[x] > radii[y]; });
                std::vector<ShapeMaker::Made> sorted(n);
                for (std::size_t k = 0; k < n; ++k) sorted[k] = made[order[k]];
                made.swap(sorted);
                for (std::size_t k = 0; k < n; ++k) radii[k] = out.shapes.circumradius[made[k].shape];
                for (auto& m : made) m.offset = {};  // random placement places the centroid
            } else {
                for (auto& r : radii) r = drawRadius(b.radius, rng);
            }
            std::size_t placed = 0;
            if (!placeRandom(b, radii, rng, out.particles, sites, placed)) {
                diags.error(b.loc, "block",
                            fmt::format("random placement placed only {} of {} particles in region "
                                        "[{}, {}] x [{}, {}]; enlarge the region or lower count",
                                        placed, b.count, b.xmin, b.xmax, b.ymin, b.ymax));
                continue;
            }
        } else {
            // Invalid lattices are reported by validate(); never loop or allocate on them.
            const double estimate = latticeSiteEstimate(b);
            if (estimate == 0) continue;
            if (estimate > 2e9) {
                diags.error(b.loc, "block",
                            fmt::format("lattice would create about {:.3g} particles (limit 2e9); "
                                        "check spacing and region",
                                        estimate));
                continue;
            }
            if (b.lattice == BlockDef::Lattice::Rect || b.lattice == BlockDef::Lattice::Fcc) {
                sites = gridSites(b);
                CounterRng jitterRng(scene.run.seed, kBlockJitterStream + bi);
                jitterSites(b, sites, jitterRng);
            } else {
                sites = latticeSites(b);
            }
            radii.resize(sites.size());
            if (def) {
                // A grain's ellipse (a deterministic shape's centroid) sits on the lattice site.
                made.resize(sites.size());
                bool ok = true;
                for (std::size_t k = 0; k < sites.size() && ok; ++k) {
                    made[k] = shapes.make(*def, shapeRng);
                    ok = made[k].shape != kDiskShape;
                    if (ok) radii[k] = out.shapes.circumradius[made[k].shape];
                }
                if (!ok) continue;
            } else {
                for (auto& r : radii) r = drawRadius(b.radius, rng);
            }
        }
        const std::size_t first = out.particles.size();
        std::vector<Real> masses;
        for (std::size_t k = 0; k < sites.size(); ++k) {
            InitialParticle ip;
            ip.position = sites[k];
            ip.velocity = b.velocity;
            ip.radius = radii[k];
            ip.material = mat;
            ip.origin = origin;
            if (def) {
                ip.shape = made[k].shape;
                ip.angle = made[k].angle;
                ip.position += rotated(made[k].offset, ip.angle);
            }
            masses.push_back(initialMass(out, ip, model::massModelOf(scene.dem.massModel), densityOf(mat)));
            out.particles.push_back(ip);
        }
        thermalVelocities(out.particles, first, b.temperature, masses, rng);
        CounterRng rangeRng(scene.run.seed, kBlockRangeStream + bi);
        rangeVelocities(b, out.particles, first, rangeRng);
    }
    generateHeaps(scene, materialNames, out, diags);  // ids after the blocks
    return out;
}

}  // namespace granulab::dem
