// SPDX-License-Identifier: MIT
// Flow-field interpolation (cfddem spec 5.4, T7): bilinear reproduces a + bx + cy + dxy exactly,
// Shepard reproduces constants and node values and finds the same nearest nodes as a brute-force
// search, cell interpolation is exact for linear fields on an unstructured mesh, the outside
// policies, and the time series' selection rules (Eq. 4.2) with lazy loading.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fluid/field_interpolator.hpp"
#include "fluid/field_series.hpp"

namespace granulab::fluid {
namespace {

Real bilinearField(Vec2 p) {
    return 0.3 + 1.7 * p.x - 0.8 * p.y + 2.5 * p.x * p.y;
}
Real linearField(Vec2 p) {
    return -1.2 + 0.4 * p.x + 3.1 * p.y;
}

/// A tensor grid with uneven spacing, nodes listed in shuffled order.
FlowField unevenGrid(std::mt19937& rng) {
    const std::vector<Real> xs = {0.0, 0.1, 0.35, 0.4, 0.9, 1.0}, ys = {-1.0, -0.2, 0.5, 0.55};
    FlowField f;
    for (const Real y : ys)
        for (const Real x : xs) {
            f.x.push_back(x);
            f.y.push_back(y);
        }
    std::vector<std::size_t> order(f.x.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::shuffle(order.begin(), order.end(), rng);
    FlowField g;
    for (const std::size_t k : order) {
        g.x.push_back(f.x[k]);
        g.y.push_back(f.y[k]);
        g.ux.push_back(bilinearField({f.x[k], f.y[k]}));
        g.uy.push_back(-bilinearField({f.x[k], f.y[k]}));
        g.p.push_back(bilinearField({f.x[k], f.y[k]}));
    }
    return g;
}

/// A jittered n x n point lattice on [0, 1]^2 (not a tensor grid) with quad cells.
FlowField jitteredMesh(int n, std::mt19937& rng, bool cells) {
    std::uniform_real_distribution<Real> jitter(-0.2, 0.2);
    FlowField f;
    const Real h = 1.0 / (n - 1);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const bool edgeX = i == 0 || i == n - 1, edgeY = j == 0 || j == n - 1;
            const Vec2 p{i * h + (edgeX ? 0 : jitter(rng) * h), j * h + (edgeY ? 0 : jitter(rng) * h)};
            f.x.push_back(p.x);
            f.y.push_back(p.y);
            f.ux.push_back(linearField(p));
            f.uy.push_back(2 * linearField(p));
        }
    if (cells) {
        f.cellOffsets.push_back(0);
        for (int j = 0; j + 1 < n; ++j)
            for (int i = 0; i + 1 < n; ++i) {
                const auto k = static_cast<std::uint32_t>(i + n * j);
                const auto un = static_cast<std::uint32_t>(n);
                for (const std::uint32_t c : {k, k + 1, k + 1 + un, k + un}) f.cellNodes.push_back(c);
                f.cellOffsets.push_back(static_cast<std::uint32_t>(f.cellNodes.size()));
            }
    }
    return f;
}

TEST(FluidInterpolation, BilinearReproducesBilinearFieldsExactly) {
    std::mt19937 rng(7);
    InterpolatorOptions o;
    o.keepPressure = true;
    const FieldInterpolator f(unevenGrid(rng), o);
    EXPECT_STREQ(f.methodName(), "bilinear");
    std::uniform_real_distribution<Real> ux(0, 1), uy(-1, 0.55);
    for (int k = 0; k < 1000; ++k) {
        const Vec2 p{ux(rng), uy(rng)};
        const FluidSample s = f.sample(p);
        ASSERT_TRUE(s.inside);
        EXPECT_NEAR(s.u.x, bilinearField(p), 1e-12);
        EXPECT_NEAR(s.u.y, -bilinearField(p), 1e-12);
        EXPECT_NEAR(s.p, bilinearField(p), 1e-12);
    }
    // The pressure gradient of a bilinear field is exact inside a cell (central differences).
    const Vec2 p{0.6, 0.0};
    const Vec2 g = f.pressureGradient(p);
    EXPECT_NEAR(g.x, 1.7 + 2.5 * p.y, 1e-9);
    EXPECT_NEAR(g.y, -0.8 + 2.5 * p.x, 1e-9);
}

TEST(FluidInterpolation, UniformGridLookupMatchesSearch) {
    // Equal spacing takes the O(1) path; the result must equal the searched one of the same grid.
    FlowField f;
    for (int j = 0; j <= 20; ++j)
        for (int i = 0; i <= 30; ++i) {
            f.x.push_back(0.1 * i);
            f.y.push_back(0.2 * j);
            f.ux.push_back(bilinearField({0.1 * i, 0.2 * j}));
            f.uy.push_back(0);
        }
    const FieldInterpolator g(f, {});
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> ux(0, 3), uy(0, 4);
    for (int k = 0; k < 500; ++k) {
        const Vec2 p{ux(rng), uy(rng)};
        EXPECT_NEAR(g.sample(p).u.x, bilinearField(p), 1e-11);
    }
}

TEST(FluidInterpolation, ShepardReproducesConstantsAndNodeValues) {
    std::mt19937 rng(11);
    FlowField f = jitteredMesh(15, rng, false);
    InterpolatorOptions o;
    o.method = "shepard";
    FlowField constant = f;
    std::fill(constant.ux.begin(), constant.ux.end(), 3.4993);
    std::fill(constant.uy.begin(), constant.uy.end(), -0.25);
    const FieldInterpolator c(constant, o), s(f, o);
    EXPECT_STREQ(s.methodName(), "shepard");
    std::uniform_real_distribution<Real> u(0, 1);
    for (int k = 0; k < 300; ++k) {
        const FluidSample v = c.sample({u(rng), u(rng)});
        EXPECT_NEAR(v.u.x, 3.4993, 1e-12);
        EXPECT_NEAR(v.u.y, -0.25, 1e-12);
    }
    for (std::size_t k = 0; k < f.size(); k += 7) {
        const FluidSample v = s.sample({f.x[k], f.y[k]});
        EXPECT_EQ(v.u.x, f.ux[k]);
        EXPECT_EQ(v.u.y, f.uy[k]);
    }
}

TEST(FluidInterpolation, NearestNodesEqualBruteForce) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> u(-1, 2);
    std::vector<Real> x(3000), y(3000);
    for (std::size_t k = 0; k < x.size(); ++k) {  // clustered: half the nodes in a small corner
        x[k] = k % 2 ? u(rng) : 0.1 * u(rng);
        y[k] = k % 2 ? u(rng) : 0.1 * u(rng);
    }
    const NodeIndex index(x, y);
    for (int q = 0; q < 400; ++q) {
        const Vec2 p{2 * u(rng), 2 * u(rng)};  // also far outside the nodes
        std::uint32_t nodes[8];
        Real d2[8];
        ASSERT_EQ(index.nearest(x.data(), y.data(), p, 8, nodes, d2), 8);
        std::vector<Real> all(x.size());
        for (std::size_t k = 0; k < x.size(); ++k)
            all[k] = (x[k] - p.x) * (x[k] - p.x) + (y[k] - p.y) * (y[k] - p.y);
        std::sort(all.begin(), all.end());
        for (int k = 0; k < 8; ++k) EXPECT_EQ(d2[k], all[static_cast<std::size_t>(k)]) << q << " " << k;
    }
}

TEST(FluidInterpolation, CellInterpolationIsExactForLinearFieldsOnUnstructuredMeshes) {
    std::mt19937 rng(13);
    const FieldInterpolator f(jitteredMesh(25, rng, true), {});
    EXPECT_STREQ(f.methodName(), "cell");  // auto: not a tensor grid, but cells are known
    std::uniform_real_distribution<Real> u(0, 1);
    for (int k = 0; k < 2000; ++k) {
        const Vec2 p{u(rng), u(rng)};
        const FluidSample s = f.sample(p);
        ASSERT_TRUE(s.inside) << p.x << " " << p.y;
        EXPECT_NEAR(s.u.x, linearField(p), 1e-11);
        EXPECT_NEAR(s.u.y, 2 * linearField(p), 1e-11);
    }
}

TEST(FluidInterpolation, OutsidePoliciesZeroOrNearest) {
    std::mt19937 rng(17);
    const FlowField grid = unevenGrid(rng);
    InterpolatorOptions zero, nearest;
    nearest.outside = Outside::Nearest;
    const Vec2 far{2.0, 0.0};  // right of the grid (x <= 1): nearest grid point (1, 0)
    const FluidSample z = FieldInterpolator(grid, zero).sample(far);
    EXPECT_FALSE(z.inside);
    EXPECT_EQ(z.u.x, 0);
    const FluidSample n = FieldInterpolator(grid, nearest).sample(far);
    EXPECT_FALSE(n.inside);
    EXPECT_NEAR(n.u.x, bilinearField({1.0, 0.0}), 1e-12);
    FlowField mesh = jitteredMesh(6, rng, true);
    const Vec2 corner{mesh.x[0], mesh.y[0]};
    const Real cornerValue = mesh.ux[0];
    const FluidSample c = FieldInterpolator(mesh, nearest).sample(corner - Vec2{0.5, 0.5});
    EXPECT_FALSE(c.inside);
    EXPECT_EQ(c.u.x, cornerValue);
    EXPECT_EQ(FieldInterpolator(mesh, zero).sample(corner - Vec2{0.5, 0.5}).u.x, 0);
}

TEST(FluidInterpolation, MethodsThatCannotWorkAreRefused) {
    std::mt19937 rng(19);
    InterpolatorOptions bilinear, cell;
    bilinear.method = "bilinear";
    cell.method = "cell";
    EXPECT_THROW(FieldInterpolator(jitteredMesh(5, rng, false), bilinear), std::invalid_argument);
    EXPECT_THROW(FieldInterpolator(jitteredMesh(5, rng, false), cell), std::invalid_argument);
    EXPECT_THROW(FieldInterpolator(FlowField{}, {}), std::invalid_argument);
}

TEST(FluidInterpolation, BilinearAndShepardAgreeOnASmoothField) {
    // cfddem T6 (d): the same field as a tensor grid (bilinear) and as scattered nodes (Shepard).
    FlowField f;
    for (int j = 0; j <= 60; ++j)
        for (int i = 0; i <= 60; ++i) {
            const Real x = 0.1 * i, y = 0.1 * j;
            f.x.push_back(x);
            f.y.push_back(y);
            f.ux.push_back(0);
            f.uy.push_back(3.5 + 0.1 * std::sin(x) * (1 - std::exp(-y)));
        }
    InterpolatorOptions shepard;
    shepard.method = "shepard";
    const FieldInterpolator b(f, {}), s(f, shepard);
    Real worst = 0;
    for (Real x = 0.05; x < 6; x += 0.37)
        for (Real y = 0.05; y < 6; y += 0.41)
            worst = std::max(worst, std::abs(b.sample({x, y}).u.y - s.sample({x, y}).u.y));
    EXPECT_LT(worst, 2e-3);  // the field varies by ~1e-2 across a cell; both errors are below that
}

TEST(FluidSeries, EvenRuleLoadsFileKOnceTimeExceedsKTOverN) {
    // cfddem Eq. 4.2: 10 files over t_end = 10 s load one new file per second, file k once t > k.
    FieldSource src;
    for (int k = 0; k < 10; ++k) src.times.push_back(k);
    src.afterTime = true;
    int loads = 0;
    src.load = [&](std::size_t k) {
        ++loads;
        FlowField f = FlowField{};
        f = uniformField({0, 0}, {1, 1}, {static_cast<Real>(k), 0});
        f.source = "f" + std::to_string(k);
        return f;
    };
    FieldSeries s(src);
    s.update(0.0);
    EXPECT_EQ(s.currentIndex(), 0u);
    s.update(1.0);
    EXPECT_EQ(s.currentIndex(), 0u);  // t = 1 is not > 1
    s.update(1.0001);
    EXPECT_EQ(s.currentIndex(), 1u);
    EXPECT_EQ(s.sample({0.5, 0.5}).u.x, 1.0);
    s.update(9.99);
    s.update(25);
    EXPECT_EQ(s.currentIndex(), 9u);
    EXPECT_EQ(loads, 3);  // lazily: only the fields that were due
}

TEST(FluidSeries, FileTimesWithLinearBlendingKeepTwoFields) {
    FieldSource src;
    src.times = {0.5, 1.0, 2.0};
    src.interpolateInTime = true;
    int loads = 0;
    src.load = [&](std::size_t k) {
        ++loads;
        return uniformField({0, 0}, {1, 1}, {10.0 * static_cast<Real>(k), 0});
    };
    FieldSeries s(src);
    s.update(0.0);  // before the first time: the first field, unblended
    EXPECT_EQ(s.sample({0.5, 0.5}).u.x, 0.0);
    s.update(0.75);  // half way from 0.5 to 1.0
    EXPECT_NEAR(s.sample({0.5, 0.5}).u.x, 5.0, 1e-12);
    s.update(1.5);
    EXPECT_NEAR(s.sample({0.5, 0.5}).u.x, 15.0, 1e-12);
    s.update(3.0);  // after the last: the last field
    EXPECT_EQ(s.sample({0.5, 0.5}).u.x, 20.0);
    EXPECT_EQ(loads, 3);  // each field read once although two are kept
}

}  // namespace
}  // namespace granulab::fluid
