// SPDX-License-Identifier: MIT
// *Def structs of the scene machines (docs/scene-format.md; gc2d spec sections 6.2-6.7, cfddem spec
// section 4): drums, drop sources, inlets, outlets and sinks, cfddem boundaries, the gravity
// schedule and material changes at given times. Filled by io/dem_machine_sections.cpp.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "model/dem_def.hpp"

namespace granulab::model {

/// gc2d_drum (spec 6.2): a ring of `count` convex wall bodies of inner radius r and thickness d.
struct DrumDef {
    std::string name;
    Vec2 centre;           ///< [m]
    Real innerRadius = 0;  ///< [m] r
    Real thickness = 0;    ///< [m] d
    std::int64_t count = 24;
    Real surfaceSpeed = 0;  ///< [m/s] inner-surface speed, counter-clockwise positive
    bool rotating = false;  ///< false: fixed ring lined with a belt (gc2d); true: the ring turns
    std::string material;
    SourceLoc loc;
};

/// What a source, an inlet or a boundary inlet inserts.
struct InsertDef {
    std::string shape = "disk";  ///< "disk" or a [[shape]] name (a grain shape draws one per particle)
    SizeDistDef radius;          ///< disks
    std::string material;
    Vec2 velocity;               ///< [m/s]
    Real angle = 0;              ///< [rad] added to the shape's rotation draw
    Real omega = 0;              ///< [rad/s]
    std::int64_t attempts = 20;  ///< overlap-safe placement: tries before an insertion is skipped
};

/// gc2d DROPSOURCE (spec 6.5): one particle every `interval` in [from, to] at x uniform in
/// [x - b/2, x + b/2], the width b shrinking linearly from `width` to `widthEnd` over the window.
struct SourceDef {
    std::string name;
    Vec2 position{0, 0.01};         ///< [m] (x, y): y absolute (ABS) or above the pile top (REL)
    std::string placement = "abs";  ///< "abs" | "rel"
    Real width = 0;                 ///< [m] b at `from`
    std::optional<Real> widthEnd;   ///< [m] b at `to` (default: width; 0 gives the layered pile)
    Real interval = 0.1;            ///< [s] DELTA_T
    Real from = 0, to = 1;          ///< [s] TIME window
    InsertDef insert;
    SourceLoc loc;
};

/// cfddem inlet (spec 4.2): an edge from -> to; n_out = z x d (left of from -> to) points out of
/// the domain. Emits one particle per step when (t - from) pps > emitted + dt (Eq. 4.1).
struct InletDef {
    std::string name;
    Vec2 a, b;                  ///< [m] edge end points
    Real rate = 0;              ///< [1/s] pps
    Real from = 0, to = 1e300;  ///< [s]
    bool inset = true;          ///< centre offset R into the domain, u in [R/L, 1 - R/L] (spec [R])
    InsertDef insert;
    SourceLoc loc;
};

/// cfddem outlet (spec 4.3) or a sink region: particles crossing the edge outward, or whose centre
/// is inside (outside) the region, are removed once t >= openAt; before, an edge outlet is a wall
/// of `material` (the closed floor of a silo).
struct OutletDef {
    std::string name;
    bool isRegion = false;
    Vec2 a, b;                                    ///< [m] edge (n_out = left of a -> b)
    Real xmin = 0, ymin = 0, xmax = 0, ymax = 0;  ///< [m] region
    bool removeInside = true;                     ///< region: remove particles inside (else outside)
    Real openAt = 0;                              ///< [s]
    std::string material;                         ///< lid material (edge outlets with openAt > 0)
    SourceLoc loc;
};

/// cfddem boundary (spec 4.1): points and typed edges; wall edges become walls, outlet and inlet
/// edges outlets and inlets. Outer boundaries clockwise, obstacles counter-clockwise.
struct BoundaryDef {
    std::string name;
    std::vector<Vec2> points;  ///< [m]
    struct Edge {
        std::int64_t from = 0, to = 0;
        std::string type;  ///< "wall" | "outlet" | "inlet"
    };
    std::vector<Edge> edges;
    bool obstacle = false;
    std::string material;  ///< wall material
    Real rate = 0;         ///< [1/s] inlets' pps
    InsertDef insert;      ///< inlets
    Real openAt = 0;       ///< [s] outlets
    SourceLoc loc;
};

/// gc2d variable gravity (spec 6.6): magnitude g1 -> g2 over [t1, t2], direction a1 -> a2
/// linearly over the tilt window.
struct GravityDef {
    bool present = false;
    std::string type = "constant";                      ///< constant | linear | step | smooth_step
    Real g1 = 9.81, g2 = 9.81;                          ///< [m/s^2]
    Real t1 = 0, t2 = 1;                                ///< [s]
    Real steps = 5;                                     ///< p1
    Real ramp = 0.5;                                    ///< p2 in [0, 1]
    Real direction1 = -kPi / 2, direction2 = -kPi / 2;  ///< [rad] counter-clockwise from +x
    Real tilt1 = 0, tilt2 = 0;                          ///< [s] tilt window (default: the window)
    SourceLoc loc;
};

/// gc2d HEAT_* (spec 2.4): global size scaling s(t) = 1 + a (1/2 - tanh(S cos 2 pi f t_c)/2).
struct SizeScalingDef {
    bool present = false;
    Real amplitude = 0.01;    ///< a
    Real frequency = 1;       ///< [1/s] f
    Real slope = 10;          ///< S
    Real t1 = 0, t2 = 1e300;  ///< [s] window of t_c
    SourceLoc loc;
};

/// A change of contact-law parameters at a time (gc2d 6.7): e.g. friction switched off.
struct ChangeDef {
    Real at = 0;                ///< [s]
    std::int64_t contact = -1;  ///< index of the [[contact]] entry
    std::map<std::string, LawParamDef> set;
    SourceLoc loc;
};

struct MachineDefs {
    std::vector<DrumDef> drums;
    std::vector<SourceDef> sources;
    std::vector<InletDef> inlets;
    std::vector<OutletDef> outlets;
    std::vector<BoundaryDef> boundaries;
    GravityDef gravity;
    SizeScalingDef sizeScaling;
    std::vector<ChangeDef> changes;
    /// What every source, inlet and boundary with inlet edges inserts, in this order.
    std::vector<const InsertDef*> inserts() const {
        std::vector<const InsertDef*> out;
        for (const auto& s : sources) out.push_back(&s.insert);
        for (const auto& i : inlets) out.push_back(&i.insert);
        for (const auto& b : boundaries)
            for (const auto& e : b.edges)
                if (e.type == "inlet") {
                    out.push_back(&b.insert);
                    break;
                }
        return out;
    }
    bool any() const noexcept {
        return !drums.empty() || !sources.empty() || !inlets.empty() || !outlets.empty() ||
               !boundaries.empty() || gravity.present || !changes.empty();
    }
};

}  // namespace granulab::model
