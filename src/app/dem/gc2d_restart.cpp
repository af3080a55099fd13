// SPDX-License-Identifier: MIT
// gso/gco restart files of a DEM run (app/dem/gc2d_restart.hpp; gc2d spec 9.4).
#include "app/dem/gc2d_restart.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <map>
#include <numeric>
#include <stdexcept>

#include "core/float_preimage.hpp"
#include "dem/step_clock.hpp"
#include "io/atomic_file.hpp"
#include "io/gci_file.hpp"
#include "io/gsi_writer.hpp"

namespace granulab::app {

namespace {

/// gc2d's identification line: "date time --- host --- user".
std::string identificationLine() {
    char host[256] = "unknown";
    gethostname(host, sizeof host - 1);
    const char* user = std::getenv("USER");
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    return fmt::format("{:%Y-%m-%d %H:%M:%S} UTC --- {} --- {}", tm, host, user ? user : "unknown");
}

/// The k_t of the gc2d friction law between two materials (0: another law).
Real frictionStiffness(const dem::World& world, std::uint32_t a, std::uint32_t b) {
    const auto* f = std::get_if<dem::AreaFriction>(&world.laws().law(a, b).tangential);
    return f ? f->kt : 0;
}

}  // namespace

model::SceneDef gc2dStateOf(const model::SceneDef& scene, const dem::World& world,
                            std::vector<model::RememberedContactDef>& contacts) {
    const model::ParticleStore& s = world.store();
    const model::WallSet& walls = world.walls();
    const io::Gc2dIds ids{static_cast<std::int64_t>(walls.walls.size())};
    model::SceneDef state = scene;  // GENERAL, the laws, sources, gravity and outputs stay
    state.run.startTime = world.time();
    // The counters of the numbered files (NEXT_*_FILENUMBER), so that a restart numbers on: dumps
    // fall on the multiples of their period; the run's first data dump is at its start.
    const std::int64_t step = world.stepIndex(), start = dem::stepsIn(scene.run.startTime, scene.dem.dt);
    auto& files = state.output.gc2d;
    if (files.setupInterval > 0) {
        const std::int64_t every = dem::periodSteps(files.setupInterval, scene.dem.dt);
        files.nextSetupNumber += step / every - start / every;
    }
    if (scene.output.snapshotInterval > 0) {
        const std::int64_t every = dem::periodSteps(scene.output.snapshotInterval, scene.dem.dt);
        files.nextDataNumber += step / every - start / every + (step % every != 0 ? 1 : 0);
    } else {
        files.nextDataNumber += 1;
    }
    state.shapes.clear();
    state.particles.clear();
    state.blocks.clear();
    state.heaps.clear();
    state.springs.clear();
    state.rememberedContacts.clear();
    for (auto& source : state.machines.sources) {  // keep the sources' grain shapes
        const auto it = std::find_if(scene.shapes.begin(), scene.shapes.end(),
                                     [&](const auto& sh) { return sh.name == source.insert.shape; });
        if (it != scene.shapes.end()) state.shapes.push_back(*it);
    }
    // Walls: a piston's current corners (its position is state); the others as the scene placed
    // them (a vibration is a function of the time).
    for (std::size_t k = 0; k < state.walls.size() && k < walls.walls.size(); ++k) {
        model::WallDef& w = state.walls[k];
        w.gc2dId = ids.wall(static_cast<std::int64_t>(k));
        if (w.pistonForce) {
            const model::Wall& body = walls.walls[k];
            w.points.assign(walls.corners.begin() + body.firstSegment,
                            walls.corners.begin() + body.firstSegment + body.segmentCount);
            w.offset = {0, 0};
            w.angle = 0;
        }
    }
    // Grains in id order (their gc2d ids W + id), each its own polygon.
    std::vector<std::uint32_t> order(s.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return s.id[a] < s.id[b]; });
    const std::vector<Real> gear = world.integratorDerivatives();
    std::map<ParticleId, std::size_t> indexOfId;
    for (const std::uint32_t k : order) {
        if (s.shape[k] == model::kDiskShape)
            throw std::invalid_argument("gsi has no disks: a gso holds polygon grains only");
        model::ShapeDef shape;
        shape.name = fmt::format("grain{}", s.id[k]);
        shape.kind = "polygon";
        shape.corners = world.shapes().shapeCorners(s.shape[k]);
        model::ParticleDef p;
        p.shape = shape.name;
        p.position = {s.x[k], s.y[k]};
        p.velocity = {s.vx[k], s.vy[k]};
        p.angle = s.angle[k];
        p.omega = s.omega[k];
        p.material = "grain";
        p.gc2dId = ids.grain(static_cast<std::int64_t>(s.id[k]));
        if (!gear.empty())
            p.gear.assign(gear.begin() + static_cast<std::ptrdiff_t>(12 * k),
                          gear.begin() + static_cast<std::ptrdiff_t>(12 * k + 12));
        indexOfId[s.id[k]] = state.particles.size();
        state.shapes.push_back(std::move(shape));
        state.particles.push_back(std::move(p));
    }
    for (const model::SpringDef& sp : scene.springs) {  // springs follow their grain
        const auto it = indexOfId.find(static_cast<ParticleId>(sp.particle));
        if (it == indexOfId.end()) continue;  // the grain has left
        model::SpringDef moved = sp;
        moved.particle = static_cast<std::int64_t>(it->second);
        state.springs.push_back(moved);
    }
    contacts.clear();
    for (const auto& c : world.rememberedContacts()) {
        model::RememberedContactDef d;
        d.id1 = ids.grain(static_cast<std::int64_t>(s.id[c.a]));
        d.id2 = c.wall ? ids.wall(c.b) : ids.grain(static_cast<std::int64_t>(s.id[c.b]));
        const std::uint32_t other = c.wall ? walls.walls[c.b].material : s.material[c.b];
        // The reader's xi = Summ_Friction / k_t (dem/setup.cpp): chosen to give xi exactly.
        d.friction = preimageOfQuotient(c.xi, frictionStiffness(world, s.material[c.a], other));
        d.oldArea = c.areaOld;
        contacts.push_back(d);
    }
    return state;
}

void writeGc2dRestart(const std::string& gsoPath, const std::string& gcoPath, const model::SceneDef& scene,
                      const dem::World& world) {
    std::vector<model::RememberedContactDef> contacts;
    const model::SceneDef state = gc2dStateOf(scene, world, contacts);
    const std::string identification = identificationLine();
    io::writeFileAtomically(gsoPath, io::sceneToGsi(state, identification));
    io::writeFileAtomically(gcoPath, io::gcoText(identification, contacts));
}

}  // namespace granulab::app
