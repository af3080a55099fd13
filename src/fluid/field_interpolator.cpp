// SPDX-License-Identifier: MIT
// Building and sampling the interpolators of fluid/field_interpolator.hpp (cfddem spec 5.4).
#include "fluid/field_interpolator.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace granulab::fluid {

namespace {

/// Sorted distinct values of v, merged within `tol`.
std::vector<Real> distinctSorted(std::vector<Real> v, Real tol) {
    std::sort(v.begin(), v.end());
    std::vector<Real> out;
    for (const Real a : v)
        if (out.empty() || a - out.back() > tol) out.push_back(a);
    return out;
}

/// Index of the grid line equal to v within tol, or -1.
std::int64_t lineIndex(const std::vector<Real>& lines, Real v, Real tol) {
    auto it = std::lower_bound(lines.begin(), lines.end(), v - tol);
    if (it == lines.end() || std::abs(*it - v) > tol) return -1;
    return it - lines.begin();
}

bool isUniform(const std::vector<Real>& lines, Real& step) {
    if (lines.size() < 2) return false;
    step = (lines.back() - lines.front()) / static_cast<Real>(lines.size() - 1);
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (std::abs(lines[i] - (lines.front() + step * static_cast<Real>(i))) > 1e-9 * step) return false;
    return true;
}

std::vector<Real> gather(const std::vector<Real>& v, const std::vector<std::uint32_t>& order) {
    std::vector<Real> out(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[k] = v[order[k]];
    return out;
}

/// Nearest-node value for Outside::Nearest (scattered nodes).
void nearestValue(const NodeIndex& index, const std::vector<Real>& x, const std::vector<Real>& y,
                  const std::vector<Real>& ux, const std::vector<Real>& uy, const std::vector<Real>& p,
                  Vec2 pos, FluidSample& out) noexcept {
    std::uint32_t node = 0;
    Real d2 = 0;
    if (index.nearest(x.data(), y.data(), pos, 1, &node, &d2) == 1) {
        out.u = {ux[node], uy[node]};
        out.p = p.empty() ? 0 : p[node];
    }
}

}  // namespace

bool tensorGridOf(const std::vector<Real>& x, const std::vector<Real>& y, std::vector<Real>& xs,
                  std::vector<Real>& ys, std::vector<std::uint32_t>& order) {
    const std::size_t n = x.size();
    if (n < 4) return false;
    const auto [xlo, xhi] = std::minmax_element(x.begin(), x.end());
    const auto [ylo, yhi] = std::minmax_element(y.begin(), y.end());
    const Real tol = 1e-9 * std::max({*xhi - *xlo, *yhi - *ylo, 1e-300});
    xs = distinctSorted(x, tol);
    if (xs.size() < 2 || n % xs.size() != 0) return false;  // scattered nodes: (nearly) all x distinct
    ys = distinctSorted(y, tol);
    if (ys.size() < 2 || xs.size() * ys.size() != n) return false;
    const std::uint32_t unset = 0xffffffffu;
    order.assign(n, unset);
    for (std::size_t k = 0; k < n; ++k) {
        const std::int64_t i = lineIndex(xs, x[k], tol), j = lineIndex(ys, y[k], tol);
        if (i < 0 || j < 0) return false;
        std::uint32_t& slot = order[static_cast<std::size_t>(i) + xs.size() * static_cast<std::size_t>(j)];
        if (slot != unset) return false;  // two nodes at one grid point: not a tensor grid
        slot = static_cast<std::uint32_t>(k);
    }
    return true;
}

std::size_t BilinearGrid::cellOf(const std::vector<Real>& lines, bool uniform, Real step, Real v) noexcept {
    const std::size_t last = lines.size() - 2;
    if (uniform) {
        const Real f = std::floor((v - lines.front()) / step);
        return f <= 0 ? 0 : (f >= static_cast<Real>(last) ? last : static_cast<std::size_t>(f));
    }
    const auto it = std::upper_bound(lines.begin(), lines.end(), v);
    const std::size_t i = static_cast<std::size_t>(it - lines.begin());
    return i == 0 ? 0 : std::min(i - 1, last);
}

void BilinearGrid::sample(Vec2 pos, FluidSample& out, LocalPatch& patch) const noexcept {
    patch.kind = LocalPatch::kNone;
    out.inside = pos.x >= xs.front() && pos.x <= xs.back() && pos.y >= ys.front() && pos.y <= ys.back();
    if (!out.inside) {
        if (outside == Outside::Zero) {
            out.u = {};
            out.p = 0;
            return;
        }
        pos = {std::clamp(pos.x, xs.front(), xs.back()), std::clamp(pos.y, ys.front(), ys.back())};
    }
    const std::size_t nx = xs.size();
    const std::size_t i = cellOf(xs, uniformX, dx, pos.x), j = cellOf(ys, uniformY, dy, pos.y);
    const Real x1 = xs[i], x2 = xs[i + 1], y1 = ys[j], y2 = ys[j + 1];
    const std::size_t k11 = i + nx * j, k21 = k11 + 1, k12 = k11 + nx, k22 = k12 + 1;
    LocalPatch cell;
    cell.kind = LocalPatch::kRectangle;
    const Real c[12] = {x1,      x2,      y1,      y2,      ux[k11], uy[k11],
                        ux[k21], uy[k21], ux[k12], uy[k12], ux[k22], uy[k22]};
    std::copy(c, c + 12, cell.c);
    // cfddem Eq. 3.66-3.68: along x on the rows y1 and y2, then along y (LocalPatch::velocity).
    out.u = cell.velocity(pos);
    if (!p.empty()) {
        const Real ax = (x2 - pos.x) / (x2 - x1), bx = (pos.x - x1) / (x2 - x1);
        const Real ay = (y2 - pos.y) / (y2 - y1), by = (pos.y - y1) / (y2 - y1);
        out.p = ay * (ax * p[k11] + bx * p[k21]) + by * (ax * p[k12] + bx * p[k22]);
    } else {
        out.p = 0;
    }
    if (out.inside) patch = cell;
}

void ShepardNodes::sample(Vec2 pos, FluidSample& out) const noexcept {
    out.inside = pos.x >= lo.x && pos.x <= hi.x && pos.y >= lo.y && pos.y <= hi.y;
    out.u = {};
    out.p = 0;
    if (!out.inside) {
        if (outside == Outside::Nearest) nearestValue(index, x, y, ux, uy, p, pos, out);
        return;
    }
    std::uint32_t nodes[NodeIndex::kMaxNearest];
    Real dist2[NodeIndex::kMaxNearest];
    const int found = index.nearest(x.data(), y.data(), pos, count, nodes, dist2);
    if (found == 0) return;
    if (dist2[0] == 0) {  // on a node: its value (Eq. 3.70 is singular there)
        out.u = {ux[nodes[0]], uy[nodes[0]]};
        out.p = p.empty() ? 0 : p[nodes[0]];
        return;
    }
    // cfddem Eq. 3.69-3.71: w_i = h_i^-p / sum_j h_j^-p, h_i the distance to node i.
    Real wsum = 0, u = 0, v = 0, pr = 0;
    for (int k = 0; k < found; ++k) {
        const Real w = power == 2 ? 1.0 / dist2[k] : std::pow(dist2[k], -0.5 * power);
        wsum += w;
        u += w * ux[nodes[k]];
        v += w * uy[nodes[k]];
        if (!p.empty()) pr += w * p[nodes[k]];
    }
    out.u = {u / wsum, v / wsum};
    out.p = pr / wsum;
}

bool CellMesh::inTriangle(std::size_t t, Vec2 pos, FluidSample& out, LocalPatch& patch) const noexcept {
    const std::uint32_t* k = &tri[3 * t];
    const Node& n0 = nodes[k[0]];
    const Node& n1 = nodes[k[1]];
    const Node& n2 = nodes[k[2]];
    const Vec2 e1{n1.x - n0.x, n1.y - n0.y}, e2{n2.x - n0.x, n2.y - n0.y}, d{pos.x - n0.x, pos.y - n0.y};
    const Real det = cross(e1, e2);
    const Real l1 = cross(d, e2) / det, l2 = cross(e1, d) / det, l0 = 1 - l1 - l2;
    constexpr Real eps = -1e-12;
    if (l0 < eps || l1 < eps || l2 < eps) return false;
    out.inside = true;
    // The triangle's linear interpolant, built the same way whoever asks (LocalPatch).
    patch.kind = LocalPatch::kTriangle;
    const Real c[12] = {n0.x,  n0.y,  e2.y / det,    -e2.x / det,   -e1.y / det,   e1.x / det,
                        n0.ux, n0.uy, n1.ux - n0.ux, n1.uy - n0.uy, n2.ux - n0.ux, n2.uy - n0.uy};
    std::copy(c, c + 12, patch.c);
    out.u = patch.velocity(pos);
    out.p = p.empty() ? 0 : l0 * p[k[0]] + l1 * p[k[1]] + l2 * p[k[2]];
    return true;
}

void CellMesh::sample(Vec2 pos, FluidSample& out, LocalPatch& patch) const noexcept {
    out.u = {};
    out.p = 0;
    out.inside = false;
    patch.kind = LocalPatch::kNone;
    const Real fx = std::floor((pos.x - lo.x) / bin), fy = std::floor((pos.y - lo.y) / bin);
    if (fx >= 0 && fy >= 0 && fx < static_cast<Real>(nx) && fy < static_cast<Real>(ny)) {
        const std::size_t b =
            static_cast<std::size_t>(fx) + static_cast<std::size_t>(nx) * static_cast<std::size_t>(fy);
        for (std::uint32_t q = binStart[b]; q < binStart[b + 1]; ++q)
            if (inTriangle(binTris[q], pos, out, patch)) return;
    }
    if (outside == Outside::Nearest) {
        std::uint32_t node = 0;
        Real d2 = 0;
        if (nearestIndex.nearest(nodeX.data(), nodeY.data(), pos, 1, &node, &d2) == 1) {
            out.u = {nodes[node].ux, nodes[node].uy};
            out.p = p.empty() ? 0 : p[node];
        }
    }
}

namespace {

BilinearGrid makeBilinear(FlowField& f, std::vector<Real> xs, std::vector<Real> ys,
                          const std::vector<std::uint32_t>& order, const InterpolatorOptions& o) {
    BilinearGrid g;
    g.xs = std::move(xs);
    g.ys = std::move(ys);
    g.ux = gather(f.ux, order);
    g.uy = gather(f.uy, order);
    if (o.keepPressure && f.hasPressure()) g.p = gather(f.p, order);
    g.uniformX = isUniform(g.xs, g.dx);
    g.uniformY = isUniform(g.ys, g.dy);
    g.outside = o.outside;
    return g;
}

ShepardNodes makeShepard(FlowField& f, const InterpolatorOptions& o, Vec2 lo, Vec2 hi) {
    ShepardNodes s;
    s.x = std::move(f.x);
    s.y = std::move(f.y);
    s.ux = std::move(f.ux);
    s.uy = std::move(f.uy);
    if (o.keepPressure) s.p = std::move(f.p);
    s.index = NodeIndex(s.x, s.y);
    s.count = std::clamp(o.shepardNodes, 1, NodeIndex::kMaxNearest);
    s.power = o.shepardPower;
    s.lo = lo;
    s.hi = hi;
    s.outside = o.outside;
    return s;
}

/// Permutation that lists the items by ascending key (counting sort, stable): order[new] = old.
std::vector<std::uint32_t> orderByKey(const std::vector<std::uint32_t>& key, std::size_t keys) {
    std::vector<std::uint32_t> start(keys + 1, 0), order(key.size());
    for (const std::uint32_t k : key) ++start[k + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    for (std::size_t i = 0; i < key.size(); ++i) order[start[key[i]]++] = static_cast<std::uint32_t>(i);
    return order;
}

CellMesh makeCells(FlowField& f, const InterpolatorOptions& o, Vec2 lo, Vec2 hi) {
    CellMesh m;
    // Fan triangulation of each convex cell; degenerate triangles (collinear corners) are dropped.
    std::vector<std::uint32_t> tri;
    const std::size_t cells = f.cellOffsets.size() - 1;
    tri.reserve(3 * (f.cellNodes.size() - 2 * cells));
    for (std::size_t c = 0; c < cells; ++c) {
        const std::uint32_t b = f.cellOffsets[c], e = f.cellOffsets[c + 1];
        for (std::uint32_t k = b + 1; k + 1 < e; ++k) {
            const std::uint32_t t[3] = {f.cellNodes[b], f.cellNodes[k], f.cellNodes[k + 1]};
            const Vec2 a{f.x[t[0]], f.y[t[0]]};
            const Real area2 = cross(Vec2{f.x[t[1]], f.y[t[1]]} - a, Vec2{f.x[t[2]], f.y[t[2]]} - a);
            if (area2 == 0) continue;
            tri.insert(tri.end(), t, t + 3);
        }
    }
    std::vector<std::uint32_t>().swap(f.cellOffsets);
    std::vector<std::uint32_t>().swap(f.cellNodes);
    const std::size_t ntri = tri.size() / 3;
    if (ntri == 0) throw std::invalid_argument("the field's cells have no area");
    // Bins of about four triangles' area; a triangle is listed in every bin its box touches (about
    // two on average).
    const Real w = std::max(hi.x - lo.x, 1e-300), h = std::max(hi.y - lo.y, 1e-300);
    m.lo = lo;
    m.bin = std::max(std::sqrt(8 * w * h / static_cast<Real>(ntri)), 1e-6 * std::max(w, h));
    m.nx = static_cast<std::int64_t>(std::floor(w / m.bin)) + 1;
    m.ny = static_cast<std::int64_t>(std::floor(h / m.bin)) + 1;
    const auto clampBin = [](Real v, std::int64_t n) {
        return v <= 0 ? std::int64_t{0}
                      : (v >= static_cast<Real>(n - 1) ? n - 1 : static_cast<std::int64_t>(v));
    };
    const auto binOf = [&](Real x, Real y) {
        return static_cast<std::uint32_t>(clampBin(std::floor((x - lo.x) / m.bin), m.nx) +
                                          m.nx * clampBin(std::floor((y - lo.y) / m.bin), m.ny));
    };
    const std::size_t bins = static_cast<std::size_t>(m.nx * m.ny);
    // Nodes in bin order, one record each (the particles, sorted in space, then read them in order).
    const std::size_t n = f.size();
    std::vector<std::uint32_t> key(n);
    for (std::size_t i = 0; i < n; ++i) key[i] = binOf(f.x[i], f.y[i]);
    const std::vector<std::uint32_t> nodeOrder = orderByKey(key, bins);
    std::vector<std::uint32_t> newIndex(n);
    m.nodes.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t i = nodeOrder[k];
        newIndex[i] = static_cast<std::uint32_t>(k);
        m.nodes[k] = {f.x[i], f.y[i], f.ux[i], f.uy[i]};
    }
    if (o.keepPressure && f.hasPressure()) {
        m.p.resize(n);
        for (std::size_t k = 0; k < n; ++k) m.p[k] = f.p[nodeOrder[k]];
    }
    std::vector<Real>().swap(f.ux);
    std::vector<Real>().swap(f.uy);
    std::vector<Real>().swap(f.p);
    // Triangles in the bin order of their centroids, over the new node numbers.
    key.assign(ntri, 0);
    for (std::size_t t = 0; t < ntri; ++t) {
        Real cx = 0, cy = 0;
        for (int k = 0; k < 3; ++k) {
            cx += f.x[tri[3 * t + k]] / 3;
            cy += f.y[tri[3 * t + k]] / 3;
        }
        key[t] = binOf(cx, cy);
    }
    const std::vector<std::uint32_t> triOrder = orderByKey(key, bins);
    std::vector<std::uint32_t>().swap(key);
    m.tri.resize(tri.size());
    for (std::size_t t = 0; t < ntri; ++t)
        for (int k = 0; k < 3; ++k) m.tri[3 * t + k] = newIndex[tri[3 * triOrder[t] + k]];
    std::vector<std::uint32_t>().swap(tri);
    std::vector<std::uint32_t>().swap(newIndex);
    const auto binRange = [&](std::size_t t, std::int64_t& i0, std::int64_t& i1, std::int64_t& j0,
                              std::int64_t& j1) {
        const CellMesh::Node& a = m.nodes[m.tri[3 * t]];
        Real xa = a.x, xb = xa, ya = a.y, yb = ya;
        for (int k = 1; k < 3; ++k) {
            const CellMesh::Node& c = m.nodes[m.tri[3 * t + k]];
            xa = std::min(xa, c.x);
            xb = std::max(xb, c.x);
            ya = std::min(ya, c.y);
            yb = std::max(yb, c.y);
        }
        i0 = clampBin(std::floor((xa - lo.x) / m.bin), m.nx);
        i1 = clampBin(std::floor((xb - lo.x) / m.bin), m.nx);
        j0 = clampBin(std::floor((ya - lo.y) / m.bin), m.ny);
        j1 = clampBin(std::floor((yb - lo.y) / m.bin), m.ny);
    };
    m.binStart.assign(bins + 1, 0);
    std::int64_t i0, i1, j0, j1;
    for (std::size_t t = 0; t < ntri; ++t) {
        binRange(t, i0, i1, j0, j1);
        for (std::int64_t j = j0; j <= j1; ++j)
            for (std::int64_t i = i0; i <= i1; ++i) ++m.binStart[static_cast<std::size_t>(i + m.nx * j) + 1];
    }
    std::partial_sum(m.binStart.begin(), m.binStart.end(), m.binStart.begin());
    m.binTris.resize(m.binStart.back());
    std::vector<std::uint32_t> fill(m.binStart.begin(), m.binStart.end() - 1);
    for (std::size_t t = 0; t < ntri; ++t) {
        binRange(t, i0, i1, j0, j1);
        for (std::int64_t j = j0; j <= j1; ++j)
            for (std::int64_t i = i0; i <= i1; ++i)
                m.binTris[fill[static_cast<std::size_t>(i + m.nx * j)]++] = static_cast<std::uint32_t>(t);
    }
    m.outside = o.outside;
    if (o.outside == Outside::Nearest) {
        m.nodeX.resize(n);
        m.nodeY.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            m.nodeX[k] = m.nodes[k].x;
            m.nodeY[k] = m.nodes[k].y;
        }
        m.nearestIndex = NodeIndex(m.nodeX, m.nodeY);
    }
    std::vector<Real>().swap(f.x);
    std::vector<Real>().swap(f.y);
    return m;
}

}  // namespace

FieldInterpolator::FieldInterpolator(Vec2 velocity)
    : m_method(UniformFlow{velocity}),
      m_source("uniform"),
      m_spacing(0),
      m_lo{-1e300, -1e300},
      m_hi{1e300, 1e300} {}

FieldInterpolator::FieldInterpolator(FlowField f, const InterpolatorOptions& o) {
    const std::size_t n = f.size();
    if (n == 0) throw std::invalid_argument("the field has no nodes");
    m_source = f.source;
    m_time = f.time;
    m_depth = f.depth;
    m_nodes = n;
    m_hasPressure = o.keepPressure && f.hasPressure();
    const auto [xlo, xhi] = std::minmax_element(f.x.begin(), f.x.end());
    const auto [ylo, yhi] = std::minmax_element(f.y.begin(), f.y.end());
    m_lo = {*xlo, *ylo};
    m_hi = {*xhi, *yhi};
    const Real w = m_hi.x - m_lo.x, h = m_hi.y - m_lo.y;
    m_spacing =
        (w > 0 && h > 0) ? std::sqrt(w * h / static_cast<Real>(n)) : std::max(w, h) / static_cast<Real>(n);
    std::vector<Real> xs, ys;
    std::vector<std::uint32_t> order;
    const std::string& want = o.method;
    if (want == "bilinear" || want == "auto") {
        if (tensorGridOf(f.x, f.y, xs, ys, order)) {
            m_method = makeBilinear(f, std::move(xs), std::move(ys), order, o);
            return;
        }
        if (want == "bilinear")
            throw std::invalid_argument(
                "interpolation = \"bilinear\" needs nodes on a tensor grid (rows of equal x and y); this "
                "field's " +
                std::to_string(n) + " nodes are not one (use \"cell\" or \"shepard\")");
    }
    if (want == "cell" || (want == "auto" && f.hasCells())) {
        if (!f.hasCells())
            throw std::invalid_argument(
                "interpolation = \"cell\" needs a field with cells; this one has only points");
        m_method = makeCells(f, o, m_lo, m_hi);
        return;
    }
    m_method = makeShepard(f, o, m_lo, m_hi);
}

Vec2 FieldInterpolator::pressureGradient(Vec2 pos) const noexcept {
    if (m_spacing <= 0) return {};  // a uniform flow carries no pressure
    const Real d = 0.25 * m_spacing;
    Vec2 grad;
    for (int axis = 0; axis < 2; ++axis) {
        const Vec2 e = axis == 0 ? Vec2{d, 0} : Vec2{0, d};
        const FluidSample plus = sample(pos + e), minus = sample(pos - e);
        Real g = 0;
        if (plus.inside && minus.inside) {
            g = (plus.p - minus.p) / (2 * d);
        } else if (plus.inside != minus.inside) {  // at the domain's edge: one-sided
            const FluidSample centre = sample(pos);
            if (centre.inside) g = plus.inside ? (plus.p - centre.p) / d : (centre.p - minus.p) / d;
        }
        (axis == 0 ? grad.x : grad.y) = g;
    }
    return grad;
}

const char* FieldInterpolator::methodName() const noexcept {
    switch (m_method.index()) {
        case 0:
            return "uniform";
        case 1:
            return "bilinear";
        case 2:
            return "shepard";
        default:
            return "cell";
    }
}

std::size_t FieldInterpolator::memoryBytes() const noexcept {
    const auto bytes = [](const std::vector<Real>& v) { return v.capacity() * sizeof(Real); };
    return std::visit(
        [&](const auto& m) -> std::size_t {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, UniformFlow>) {
                return 0;
            } else if constexpr (std::is_same_v<M, BilinearGrid>) {
                return bytes(m.xs) + bytes(m.ys) + bytes(m.ux) + bytes(m.uy) + bytes(m.p);
            } else if constexpr (std::is_same_v<M, ShepardNodes>) {
                return bytes(m.x) + bytes(m.y) + bytes(m.ux) + bytes(m.uy) + bytes(m.p) +
                       m.index.memoryBytes();
            } else {
                return m.nodes.capacity() * sizeof(CellMesh::Node) + bytes(m.p) + m.tri.capacity() * 4 +
                       m.binStart.capacity() * 4 + m.binTris.capacity() * 4 + bytes(m.nodeX) +
                       bytes(m.nodeY) + m.nearestIndex.memoryBytes();
            }
        },
        m_method);
}

}  // namespace granulab::fluid
