// SPDX-License-Identifier: MIT
// DEM contact records -> contact files (app/dem/dem_contacts.hpp).
#include "app/dem/dem_contacts.hpp"

#include <filesystem>
#include <unordered_map>

#include "io/contact_file.hpp"

namespace granulab::app {

analysis::ContactFrame contactFrameOf(const dem::ContactLog& log, double time) {
    analysis::ContactFrame c;
    c.time = time;
    const std::size_t n = log.records.size();
    for (auto* col : {&c.px, &c.py, &c.nx, &c.ny, &c.fx, &c.fy, &c.fn, &c.ft, &c.depth, &c.area, &c.length})
        col->reserve(n);
    for (const dem::ContactRecord& r : log.records) {
        c.a.push_back(r.a);
        c.b.push_back(r.wall >= 0 ? -1 : static_cast<std::int64_t>(r.b));
        c.wall.push_back(r.wall);
        c.px.push_back(r.point.x);
        c.py.push_back(r.point.y);
        c.nx.push_back(r.normal.x);
        c.ny.push_back(r.normal.y);
        c.fx.push_back(r.force.x);
        c.fy.push_back(r.force.y);
        c.fn.push_back(-dot(r.force, r.normal));
        c.ft.push_back(dot(r.force, perp(r.normal)));
        c.depth.push_back(r.depth);
        c.area.push_back(r.area);
        c.length.push_back(r.length);
    }
    return c;
}

void writeContactSnapshot(const std::string& dir, int index, const dem::World& world, io::PvdWriter& pvd) {
    const model::ParticleStore& s = world.store();
    std::unordered_map<ParticleId, std::size_t> slotOf;
    slotOf.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) slotOf.emplace(s.id[i], i);
    // The contacts of grains that left through an outlet at the end of the step are dropped, so the
    // contact file names only grains of the particle file of the same snapshot.
    dem::ContactLog kept;
    kept.step = world.contactLog().step;
    for (const dem::ContactRecord& r : world.contactLog().records)
        if (slotOf.count(r.a) && (r.wall >= 0 || slotOf.count(r.b))) kept.records.push_back(r);
    const analysis::ContactFrame c = contactFrameOf(kept, world.time());
    const auto centre = [&](std::int64_t id) {
        const std::size_t i = slotOf.at(static_cast<ParticleId>(id));
        return Vec2{s.x[i], s.y[i]};
    };
    std::vector<Vec2> centreA(c.size()), centreB(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) {
        centreA[k] = centre(c.a[k]);
        centreB[k] = c.atWall(k) ? Vec2{c.px[k], c.py[k]} : centre(c.b[k]);
    }
    const std::filesystem::path folder(dir);
    const std::string npy = io::contactFileName(index);
    const std::string vtp = io::snapshotFileName("contacts", index);
    io::writeContactsNpy((folder / npy).string(), c);
    io::writeContactsVtp((folder / vtp).string(), c, centreA, centreB, c.time);
    pvd.add(c.time, 2, vtp);
    pvd.write();
}

}  // namespace granulab::app
