// SPDX-License-Identifier: MIT
// The scene machines from their Defs (gc2d spec 6.1-6.7, cfddem spec 4): walls (polylines and
// convex bodies with their drivers), drums, cfddem boundaries, outlet lids, the particle flow
// (sources, inlets, outlets), the gravity schedule and the law changes.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "dem/particle_flow.hpp"
#include "dem/schedules.hpp"
#include "dem/world.hpp"
#include "model/scene_def.hpp"
#include "model/shape_pool.hpp"
#include "model/walls.hpp"

namespace granulab::dem {

/// The wall points of a [[wall]] after its OFFSET and ANGLE (rotation about their centroid).
std::vector<Vec2> placedWallPoints(const model::WallDef& def);
/// True if a [[wall]] is a convex polygon body (kind "polygon"); its corners are then made
/// counter-clockwise. A closed polyline stays a container of segments.
bool wallIsBody(const model::WallDef& def);

/// Every wall of the scene: [[wall]]s, then drums, boundary walls and outlet lids, in this order.
model::WallSet buildWalls(const model::SceneDef& scene, const std::vector<std::string>& materialNames);

/// Sources, inlets and outlets; deterministic [[shape]]s they insert are added to `pool`.
FlowConfig buildFlow(const model::SceneDef& scene, const std::vector<std::string>& materialNames,
                     model::ShapePool& pool);

/// Largest bounding radius [m] a source or inlet can insert (0: none).
Real largestInsertedRadius(const model::SceneDef& scene);

std::optional<GravitySchedule> buildGravitySchedule(const model::SceneDef& scene);

std::optional<SizeCycle> buildSizeCycle(const model::SceneDef& scene);

/// The law tables after each [[change]] (cumulative, in time order), at whole steps of dt.
std::vector<WorldConfig::LawChange> buildLawChanges(const model::SceneDef& scene, Real dt);

/// Corners of drum segment k (counter-clockwise): the inner edge at distance r from the centre.
std::vector<Vec2> drumSegment(const model::DrumDef& d, std::int64_t k);

}  // namespace granulab::dem
