// SPDX-License-Identifier: MIT
// The fluid velocity (and pressure) at any point of the plane from a FlowField (cfddem spec 5.4):
// bilinear on tensor-product grids (Eq. 3.66-3.68), Shepard's inverse-distance weighting of the
// nearest nodes (Eq. 3.69-3.71) on scattered nodes, linear (barycentric) interpolation in the
// containing cell when the field has cells, or a uniform value. Each method is a struct with one
// noexcept `sample`; FieldInterpolator holds one of them and `visit` hands the concrete one to a
// templated loop, so the per-particle loop has no dispatch (DESIGN.md "Hot loops").
// Outside the field's domain the policy is zero velocity (the seed's [R]) or the nearest value.
#pragma once
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "core/types.hpp"
#include "fluid/flow_field.hpp"
#include "fluid/node_index.hpp"

namespace granulab::fluid {

enum class Outside { Zero, Nearest };

struct InterpolatorOptions {
    std::string method = "auto";  ///< auto | bilinear | shepard | cell (auto: bilinear on a tensor
                                  ///< grid, else cell when the field has cells, else shepard)
    Outside outside = Outside::Zero;
    int shepardNodes = 4;       ///< nop
    Real shepardPower = 2;      ///< p
    bool keepPressure = false;  ///< keep the field's pressure (pressure-gradient force)
};

/// The fluid at a point: velocity [m/s], pressure (unit of the file), inside the domain or not.
struct FluidSample {
    Vec2 u;
    Real p = 0;
    bool inside = true;
};

/// The velocity interpolant of one grid rectangle or one triangle, valid inside it: the cells are
/// linear (triangles) or bilinear (rectangles), so a particle that stays in its cell needs none of
/// the field's memory. The DEM keeps one patch per particle slot (dem/fluid_forces.cpp). A patch
/// is a function of its cell only, whoever built it, and the methods compute every sample through
/// it, so cached and fresh samples are bit-identical. Near the cell's edge (where the neighbouring
/// cell might be chosen) a patch declines and the full lookup decides.
struct LocalPatch {
    enum Kind : std::uint8_t { kNone, kTriangle, kRectangle };
    Kind kind = kNone;
    /// kTriangle: origin (node 0), lambda map rows (lambda1, lambda2 from pos - origin), velocity at
    /// node 0 and its increments to nodes 1 and 2. kRectangle: x1, x2, y1, y2, then the corner
    /// velocities (11, 21, 12, 22) as (ux, uy) pairs.
    Real c[12] = {};

    /// True if pos is inside the cell, away from its edges by a relative 1e-9.
    bool interior(Vec2 pos) const noexcept {
        if (kind == kTriangle) {
            const Real dx = pos.x - c[0], dy = pos.y - c[1];
            const Real l1 = c[2] * dx + c[3] * dy, l2 = c[4] * dx + c[5] * dy;
            constexpr Real m = 1e-9;
            return l1 > m && l2 > m && 1 - l1 - l2 > m;
        }
        if (kind == kRectangle) {
            const Real mx = 1e-9 * (c[1] - c[0]), my = 1e-9 * (c[3] - c[2]);
            return pos.x > c[0] + mx && pos.x < c[1] - mx && pos.y > c[2] + my && pos.y < c[3] - my;
        }
        return false;
    }
    /// The interpolated velocity [m/s] at pos (cfddem Eq. 3.66-3.68 on rectangles).
    Vec2 velocity(Vec2 pos) const noexcept {
        if (kind == kTriangle) {
            const Real dx = pos.x - c[0], dy = pos.y - c[1];
            const Real l1 = c[2] * dx + c[3] * dy, l2 = c[4] * dx + c[5] * dy;
            return {c[6] + l1 * c[8] + l2 * c[10], c[7] + l1 * c[9] + l2 * c[11]};
        }
        const Real ax = (c[1] - pos.x) / (c[1] - c[0]), bx = (pos.x - c[0]) / (c[1] - c[0]);
        const Real ay = (c[3] - pos.y) / (c[3] - c[2]), by = (pos.y - c[2]) / (c[3] - c[2]);
        return {ay * (ax * c[4] + bx * c[6]) + by * (ax * c[8] + bx * c[10]),
                ay * (ax * c[5] + bx * c[7]) + by * (ax * c[9] + bx * c[11])};
    }
};

/// The same velocity everywhere (a scene without field files).
struct UniformFlow {
    Vec2 u;
    void sample(Vec2, FluidSample& out) const noexcept {
        out.u = u;
        out.p = 0;
        out.inside = true;
    }
};

/// Bilinear interpolation on a tensor grid xs x ys (cfddem Eq. 3.66-3.68); outside: zero, or the
/// value at the nearest point of the grid's rectangle (which is the nearest boundary value).
struct BilinearGrid {
    std::vector<Real> xs, ys;     ///< [m] ascending grid lines
    std::vector<Real> ux, uy, p;  ///< values in grid order i + nx j (p empty: none)
    bool uniformX = false, uniformY = false;
    Real dx = 0, dy = 0;  ///< [m] spacing when uniform
    Outside outside = Outside::Zero;

    /// Grid cell index along one axis containing v (clamped to [0, n - 2]).
    static std::size_t cellOf(const std::vector<Real>& lines, bool uniform, Real step, Real v) noexcept;
    void sample(Vec2 pos, FluidSample& out) const noexcept {
        LocalPatch patch;
        sample(pos, out, patch);
    }
    /// Also sets `patch` to the rectangle's interpolant (kNone outside the grid).
    void sample(Vec2 pos, FluidSample& out, LocalPatch& patch) const noexcept;
};

/// Shepard's method (cfddem Eq. 3.69-3.71): w_i = h_i^-p / sum h_j^-p over the nearest `count`
/// nodes; a point on a node gets the node's value. Outside the nodes' bounding box: zero, or the
/// nearest node's value.
struct ShepardNodes {
    std::vector<Real> x, y, ux, uy, p;
    NodeIndex index;
    int count = 4;
    Real power = 2;
    Vec2 lo, hi;
    Outside outside = Outside::Zero;

    void sample(Vec2 pos, FluidSample& out) const noexcept;
};

/// Linear interpolation in the containing triangle (each 2D cell split into a fan of triangles):
/// barycentric weights, exact for linear fields, continuous across cells. Triangles are found
/// through a bin grid (O(1) expected); a caller that samples the same particles again keeps their
/// LocalPatch and needs the mesh only when a particle leaves its triangle. Nodes and triangles
/// are renumbered in bin order and each node's data is one record, so that particles sorted in
/// space read the mesh almost sequentially. Outside every cell: zero, or the nearest node's value.
struct CellMesh {
    struct Node {
        Real x, y, ux, uy;  ///< [m], [m/s]
    };
    std::vector<Node> nodes;
    std::vector<Real> p;             ///< by node (empty: none)
    std::vector<std::uint32_t> tri;  ///< 3 node indices per triangle
    Vec2 lo;
    Real bin = 1;  ///< [m]
    std::int64_t nx = 1, ny = 1;
    std::vector<std::uint32_t> binStart, binTris;
    std::vector<Real> nodeX, nodeY;  ///< coordinates again, only for Outside::Nearest
    NodeIndex nearestIndex;          ///< built only for Outside::Nearest
    Outside outside = Outside::Zero;

    void sample(Vec2 pos, FluidSample& out) const noexcept {
        LocalPatch patch;
        sample(pos, out, patch);
    }
    /// Also sets `patch` to the containing triangle's interpolant (kNone outside the mesh).
    void sample(Vec2 pos, FluidSample& out, LocalPatch& patch) const noexcept;
    /// Interpolates in triangle t if pos lies in it.
    bool inTriangle(std::size_t t, Vec2 pos, FluidSample& out, LocalPatch& patch) const noexcept;
};

class FieldInterpolator {
public:
    /// Builds the lookup structure; throws std::invalid_argument (message without the file name)
    /// when the method cannot work on this field (bilinear on scattered nodes, cell without cells,
    /// an empty field).
    FieldInterpolator(FlowField field, const InterpolatorOptions& options);
    /// A uniform flow.
    explicit FieldInterpolator(Vec2 velocity);

    /// Calls fn(const Method&) with the concrete method (once per loop, not per particle).
    template <class Fn>
    decltype(auto) visit(Fn&& fn) const {
        return std::visit(std::forward<Fn>(fn), m_method);
    }
    FluidSample sample(Vec2 pos) const noexcept {
        FluidSample s;
        std::visit([&](const auto& m) { m.sample(pos, s); }, m_method);
        return s;
    }
    /// Pressure gradient [file pressure unit / m] by central differences over a quarter of the node
    /// spacing (one-sided at the domain's edge).
    Vec2 pressureGradient(Vec2 pos) const noexcept;

    const char* methodName() const noexcept;
    const std::string& source() const noexcept { return m_source; }
    Real time() const noexcept { return m_time; }
    Real depth() const noexcept { return m_depth; }
    Real spacing() const noexcept { return m_spacing; }  ///< [m] typical node spacing (0: uniform flow)
    Vec2 lo() const noexcept { return m_lo; }            ///< [m] bounding box of the nodes
    Vec2 hi() const noexcept { return m_hi; }
    std::size_t nodes() const noexcept { return m_nodes; }
    bool hasPressure() const noexcept { return m_hasPressure; }
    std::size_t memoryBytes() const noexcept;

private:
    std::variant<UniformFlow, BilinearGrid, ShepardNodes, CellMesh> m_method;
    std::string m_source;
    Real m_time = 0, m_depth = 0, m_spacing = 1;
    Vec2 m_lo, m_hi;
    std::size_t m_nodes = 0;
    bool m_hasPressure = false;
};

/// True if the nodes form a full tensor grid (every (xs[i], ys[j]) exactly once); fills xs, ys
/// (ascending) and order[i + nx j] = node index.
bool tensorGridOf(const std::vector<Real>& x, const std::vector<Real>& y, std::vector<Real>& xs,
                  std::vector<Real>& ys, std::vector<std::uint32_t>& order);

}  // namespace granulab::fluid
