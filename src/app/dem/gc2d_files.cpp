// SPDX-License-Identifier: MIT
// gc2d's legacy files of a DEM run (app/dem/gc2d_files.hpp; gc2d spec 9.1, 9.5).
#include "app/dem/gc2d_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <unordered_map>

#include "app/dem/dem_contacts.hpp"
#include "app/render_picture.hpp"
#include "geom/rotation.hpp"
#include "io/atomic_file.hpp"

namespace granulab::app {

namespace {

/// Slots of the store in id order.
std::vector<std::size_t> slotsById(const model::ParticleStore& s) {
    std::vector<std::size_t> order(s.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.id[a] < s.id[b]; });
    return order;
}

/// Whether wall w's outline is a closed ring (a body, a closed polyline).
bool closedWall(const model::WallSet& ws, std::size_t w) {
    const model::Wall& wall = ws.walls[w];
    if (wall.body) return true;
    return wall.segmentCount > 0 && ws.segments[wall.firstSegment + wall.segmentCount - 1].endShared;
}

/// The corners of wall w: reference placement (a0, b0) or now (a, b).
std::vector<Vec2> wallCorners(const model::WallSet& ws, std::size_t w, bool reference) {
    const model::Wall& wall = ws.walls[w];
    std::vector<Vec2> c;
    c.reserve(wall.segmentCount + 1);
    for (std::uint32_t k = 0; k < wall.segmentCount; ++k) {
        const model::WallSegment& s = ws.segments[wall.firstSegment + k];
        c.push_back(reference ? s.a0 : s.a);
    }
    if (wall.segmentCount > 0 && !closedWall(ws, w)) {
        const model::WallSegment& last = ws.segments[wall.firstSegment + wall.segmentCount - 1];
        c.push_back(reference ? last.b0 : last.b);
    }
    return c;
}

/// Centroid [m] of wall w, reference placement or now (a body's is the contact law's).
Vec2 wallCentroid(const model::WallSet& ws, std::size_t w, bool reference) {
    if (ws.walls[w].body) return reference ? ws.bodyCentroid0[w] : ws.bodyCentroid[w];
    return io::outlineCentroid(wallCorners(ws, w, reference), closedWall(ws, w));
}

/// The most corners a grain of [[shape]] `name` can have (sources draw theirs during the run).
std::size_t maxCornersOf(const model::SceneDef& scene, const std::string& name) {
    for (const model::ShapeDef& s : scene.shapes) {
        if (s.name != name) continue;
        if (s.kind == "polygon") return s.corners.size();
        if (s.kind == "rectangle") return s.chamfer > 0 ? 8 : 4;
        if (s.kind == "grain")
            return static_cast<std::size_t>(std::max<std::int64_t>(3, s.cornerCount + s.cornerVariation));
        return static_cast<std::size_t>(std::max<std::int64_t>(0, s.cornerCount));  // regular, ellipse
    }
    return 0;  // a disk (refused by the checks when output.gc2d is on)
}

/// |g| [m/s^2] in effect (0 with dem.weight off): gc2d's scalar G.
double gravityMagnitude(const dem::World& world) {
    return world.config().weight ? norm(world.gravity()) : 0.0;
}

}  // namespace

analysis::GrainFrame grainFrameOf(const dem::World& world) {
    const model::ParticleStore& s = world.store();
    const model::ShapePool& pool = world.shapes();
    const Real scale = world.sizeScale();
    analysis::GrainFrame g;
    g.time = world.time();
    for (const std::size_t i : slotsById(s)) {
        g.id.push_back(static_cast<std::int64_t>(s.id[i]));
        g.x.push_back(s.x[i]);
        g.y.push_back(s.y[i]);
        g.vx.push_back(s.vx[i]);
        g.vy.push_back(s.vy[i]);
        g.omega.push_back(s.omega[i]);
        g.angle.push_back(s.angle[i]);
        g.radius.push_back(s.radius[i]);
        g.speed.push_back(std::hypot(s.vx[i], s.vy[i]));
        g.mass.push_back(s.mass[i]);
        g.material.push_back(static_cast<std::int32_t>(s.material[i]));
        const std::uint32_t k = s.shape[i];
        if (k != model::kDiskShape) {  // world corners, gc2d Eq. 2.35 with counter-clockwise angles
            const auto [c, sn] = geom::rotationOf(s.angle[i]);  // as the force kernel's
            for (std::uint32_t q = 0; q < pool.count[k]; ++q) {
                const Vec2 b = pool.corners[pool.start[k] + q] * scale;
                g.corners.push_back({s.x[i] + c * b.x - sn * b.y, s.y[i] + sn * b.x + c * b.y});
            }
        }
        g.cornerStart.push_back(g.corners.size());
    }
    return g;
}

io::GrainAccelerations accelerationsOf(const dem::World& world, const analysis::GrainFrame& grains) {
    const model::ParticleStore& s = world.store();
    std::unordered_map<std::int64_t, std::size_t> slot;
    slot.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) slot.emplace(static_cast<std::int64_t>(s.id[i]), i);
    io::GrainAccelerations a;
    for (std::size_t k = 0; k < grains.size(); ++k) {
        const std::size_t i = slot.at(grains.id[k]);
        a.ax.push_back(s.fx[i] * s.invMass[i]);
        a.ay.push_back(s.fy[i] * s.invMass[i]);
        a.alpha.push_back(s.torque[i] * s.invInertia[i]);
    }
    return a;
}

io::Gc2dWalls gc2dWallsOf(const model::WallSet& ws) {
    io::Gc2dWalls out;
    for (std::size_t w = 0; w < ws.walls.size(); ++w) {
        const Vec2 c = wallCentroid(ws, w, false);
        out.centroid.push_back(c);
        out.angle.push_back(ws.walls[w].rotation);
        out.velocity.push_back(ws.velocityAt(static_cast<std::uint32_t>(w), c));
        out.omega.push_back(ws.walls[w].omega);
    }
    return out;
}

std::vector<Vec2> wallBodyOutline(const model::WallSet& ws, std::size_t w) {
    std::vector<Vec2> c = wallCorners(ws, w, true);
    const Vec2 c0 = wallCentroid(ws, w, true);
    for (Vec2& p : c) p = p - c0;
    return c;
}

Gc2dFiles::Gc2dFiles(const model::SceneDef& scene, const dem::World& world) : m_scene(scene), m_world(world) {
    m_ids.wallCount = static_cast<std::int64_t>(world.walls().walls.size());
}

void Gc2dFiles::open(const std::string& dir, double resumeTime) {
    const model::Gc2dOutputDef& def = m_scene.output.gc2d;
    const auto path = [&](const char* ext) {
        return (std::filesystem::path(dir) / io::gc2dFileName(def.basename, ext)).string();
    };
    const bool resumed = resumeTime >= 0;
    const bool lines = def.lineInterval > 0;
    if (resumed) {  // keep what the run wrote up to its checkpoint (the times are exact: step * dt)
        const io::GgfContents ggf = io::readGgfContents(path("ggf"), m_ids);
        m_width = ggf.width;
        m_wallsWritten = ggf.walls;
        m_nextGrain = ggf.nextGrainId;
        io::keepGc2dLines(path("ggf"), [](std::string_view) { return true; });  // drops a cut line
        io::keepGc2dLines(path("gtf"), [&](std::string_view l) {
            const auto f = io::gc2dFields(l);
            return f.size() >= 2 && f[1] <= resumeTime;
        });
        if (lines)
            io::keepGc2dLines(path("gpl"), [&](std::string_view l) {
                const auto f = io::gc2dFields(l);
                return !f.empty() && f[0] <= resumeTime;
            });
    }
    m_ggf = io::Gc2dAppender(path("ggf"), resumed);
    m_gtf = io::Gc2dAppender(path("gtf"), resumed);
    if (lines) m_gpl = io::Gc2dAppender(path("gpl"), resumed);
}

std::size_t Gc2dFiles::ggfWidth() const {
    std::size_t widest = 0;
    const model::ShapePool& pool = m_world.shapes();
    for (std::uint32_t k = 0; k < pool.size(); ++k) widest = std::max<std::size_t>(widest, pool.count[k]);
    for (std::size_t w = 0; w < m_world.walls().walls.size(); ++w)
        widest = std::max(widest, wallCorners(m_world.walls(), w, true).size());
    for (const model::InsertDef* in : m_scene.machines.inserts())
        widest = std::max(widest, maxCornersOf(m_scene, in->shape));
    return io::gc2dOutlineWidth(widest);
}

bool Gc2dFiles::dump(const std::string& dir, int index) {
    const model::Gc2dOutputDef& def = m_scene.output.gc2d;
    const dem::World& world = m_world;
    const model::ParticleStore& s = world.store();
    const model::ShapePool& pool = world.shapes();
    const model::WallSet& ws = world.walls();
    if (m_width == 0) m_width = ggfWidth();

    // ggf: the walls once, then the grains that appeared since the last dump, in id order.
    std::string ggf;
    if (!m_wallsWritten) {
        for (std::size_t w = 0; w < ws.walls.size(); ++w)
            ggf += io::ggfLine(m_ids.wall(static_cast<std::int64_t>(w)), io::kGc2dWall,
                               wallBodyOutline(ws, w), m_width);
        m_wallsWritten = true;
    }
    std::int64_t next = m_nextGrain;
    for (const std::size_t i : slotsById(s)) {
        const auto id = static_cast<std::int64_t>(s.id[i]);
        if (id < m_nextGrain) continue;
        const std::vector<Vec2> body =
            s.shape[i] == model::kDiskShape ? std::vector<Vec2>{} : pool.shapeCorners(s.shape[i]);
        ggf += io::ggfLine(m_ids.grain(id), io::kGc2dParticle, body, m_width);
        next = std::max(next, id + 1);
    }
    m_nextGrain = next;
    if (!ggf.empty()) m_ggf.write(ggf);

    const analysis::GrainFrame grains = grainFrameOf(world);
    const io::Gc2dWalls walls = gc2dWallsOf(ws);

    // gff: the contacts of this step's force evaluation (those of grains that left through an
    // outlet at the end of the step are dropped), then gravity and the pull springs.
    const dem::ContactLog& log = world.contactLog();
    const bool fresh = log.step == world.stepIndex();
    std::unordered_map<ParticleId, std::size_t> slotOf;
    slotOf.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) slotOf.emplace(s.id[i], i);
    dem::ContactLog kept;
    if (fresh)
        for (const dem::ContactRecord& r : log.records)
            if (slotOf.count(r.a) && (r.wall >= 0 || slotOf.count(r.b))) kept.records.push_back(r);
    const analysis::ContactFrame contacts = contactFrameOf(kept, world.time());
    std::vector<io::OneBodyForce> oneBody;
    const Vec2 g = world.config().weight ? world.gravity() : Vec2{0, 0};
    if (g.x != 0 || g.y != 0)
        for (std::size_t k = 0; k < grains.size(); ++k)
            oneBody.push_back({grains.id[k], {grains.x[k], grains.y[k]}, g * grains.mass[k]});
    for (const dem::PullSpring& sp : world.springs()) {  // as dem/forces.cpp springForces
        const auto it = slotOf.find(sp.id);
        if (it == slotOf.end()) continue;
        const std::size_t i = it->second;
        const auto [c, sn] = geom::rotationOf(s.angle[i]);
        const Vec2 at = Vec2{s.x[i], s.y[i]} +
                        Vec2{c * sp.attach.x - sn * sp.attach.y, sn * sp.attach.x + c * sp.attach.y};
        oneBody.push_back(
            {static_cast<std::int64_t>(sp.id), at, (sp.freeEnd(world.time()) - at) * sp.stiffness});
    }
    const std::int64_t number = def.nextDataNumber + index;
    const std::filesystem::path folder(dir);
    io::writeFileAtomically((folder / io::gc2dFileName(def.basename, number, "gff")).string(),
                            io::gffText(m_ids, walls, grains, contacts, oneBody));
    io::writeFileAtomically((folder / io::gc2dFileName(def.basename, number, "gpf")).string(),
                            io::gpfText(m_ids, walls, grains, accelerationsOf(world, grains)));
    m_gtf.write(io::gtfLine(number, world.time(), gravityMagnitude(world), world.sizeScale()));
    return fresh;
}

void Gc2dFiles::line() {
    if (!m_gpl.isOpen()) return;
    m_gpl.write(io::gplLine(m_ids, m_world.time(), gravityMagnitude(m_world), gc2dWallsOf(m_world.walls()),
                            grainFrameOf(m_world)));
}

bool Gc2dFiles::picture(const std::string& dir) const {
    const model::WallSet& ws = m_world.walls();
    analysis::WallSegments segments;
    for (const model::WallSegment& seg : ws.segments) {
        if (!ws.walls[seg.wall].solid) continue;  // an outlet's lid after it opened
        segments.a.push_back(seg.a);
        segments.b.push_back(seg.b);
        segments.wall.push_back(static_cast<std::int32_t>(seg.wall));
    }
    const std::string path =
        (std::filesystem::path(dir) / io::gc2dFileName(m_scene.output.gc2d.basename, "ps")).string();
    return writePicturePs(path, grainFrameOf(m_world), segments, m_world.time());
}

}  // namespace granulab::app
