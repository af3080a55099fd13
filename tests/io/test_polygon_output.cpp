// SPDX-License-Identifier: MIT
// Output of polygon particles (issue 4): VTK snapshots (polygon cells with the world corners,
// per-particle cell data) read back through io/vtk_reader, final.csv shape and corners columns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support.hpp"
#include "io/csv_writers.hpp"
#include "io/vtk_reader.hpp"
#include "io/vtk_writer.hpp"

namespace granulab::io {
namespace {

namespace fs = std::filesystem;

/// Two hexagons, a triangle, a square and a disk, all moving and turned.
const char* kPolygonScene = R"(
[run]
end_time = 0.01
[dem]
dt = 1.0e-6
[[material]]
name = "grain"
density = 2.0
[[material]]
name = "rock"
density = 3.0
[[shape]]
name = "hex"
kind = "regular"
corner_count = 6
radius = 0.001
[[shape]]
name = "tri"
kind = "polygon"
corners = [[0.0, 0.0], [0.002, 0.0], [0.0, 0.002]]
[[shape]]
name = "square"
kind = "polygon"
corners = [[-0.001, -0.001], [0.001, -0.001], [0.001, 0.001], [-0.001, 0.001]]
[[particle]]
shape = "hex"
position = [0, 0]
velocity = [0.3, -0.1]
angle = 0.4
omega = 2.0
material = "grain"
[[particle]]
shape = "tri"
position = [0.005, 0.0003]
velocity = [-0.2, 0.05]
angle = -1.1
omega = -3.5
material = "rock"
[[particle]]
position = [0.0, 0.005]
velocity = [0.0, 0.7]
angle = 0.25
radius = 0.0012
material = "grain"
[[particle]]
shape = "hex"
position = [0.005, 0.005]
angle = 2.5
material = "rock"
[[particle]]
shape = "square"
position = [0.0101, 0.0025]
velocity = [1.0e-3, 0.0]
angle = 0.7
material = "grain"
[[contact]]
materials = ["*", "*"]
normal = "area"
E = 1e7
)";

std::string slurp(const fs::path& p) {
    std::ifstream is(p, std::ios::binary);
    std::ostringstream ss;
    ss << is.rdbuf();
    return ss.str();
}

/// World corners of slot i: (x, y) + R(angle) * body corner.
std::vector<Vec2> worldCorners(const model::ParticleStore& s, const model::ShapePool& pool, std::size_t i) {
    std::vector<Vec2> out;
    const std::uint32_t k = s.shape[i];
    const double cs = std::cos(s.angle[i]), sn = std::sin(s.angle[i]);
    for (std::uint32_t c = 0; c < pool.count[k]; ++c) {
        const Vec2 b = pool.corners[pool.start[k] + c];
        out.push_back({s.x[i] + cs * b.x - sn * b.y, s.y[i] + sn * b.x + cs * b.y});
    }
    return out;
}

std::map<std::int64_t, std::size_t> slotsById(const model::ParticleStore& s) {
    std::map<std::int64_t, std::size_t> m;
    for (std::size_t i = 0; i < s.size(); ++i) m[static_cast<std::int64_t>(s.id[i])] = i;
    return m;
}

/// Independent look at one appended array of a .vtp written by our writer (section as the XML
/// element name, e.g. "CellData"): finds `Name="name"` after `<section`, reads its offset.
template <class T>
std::vector<T> appendedArray(const std::string& text, const std::string& section, const std::string& name) {
    const auto sec = text.find("<" + section);
    if (sec == std::string::npos) throw std::runtime_error("no section " + section);
    const auto secEnd = text.find("</" + section, sec);
    const auto at = text.find("Name=\"" + name + "\"", sec);
    if (at == std::string::npos || at > secEnd)
        throw std::runtime_error("no array " + name + " in " + section);
    const auto off = text.find("offset=\"", at) + 8;
    const std::size_t offset = std::stoull(text.substr(off, text.find('"', off) - off));
    const std::size_t data = text.find('_', text.find("<AppendedData")) + 1 + offset;
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, text.data() + data, sizeof bytes);
    std::vector<T> v(bytes / sizeof(T));
    std::memcpy(v.data(), text.data() + data + sizeof bytes, bytes);
    return v;
}

TEST(PolygonOutput, SnapshotRoundTripsWorldCorners) {
    const test::ScratchDir scratch;
    const dem::World world = test::makeWorldFromToml(kPolygonScene);
    const model::ParticleStore& s = world.store();
    const model::ShapePool& pool = world.shapes();
    ASSERT_EQ(s.size(), 5u);
    ASSERT_GE(pool.size(), 3u);
    PvdWriter pvd((scratch.path / "snapshots.pvd").string());
    writeSnapshot(scratch.path.string(), 0, s, pool, world.walls(), 0.125, pvd);
    const fs::path file = scratch.path / "vtk" / "particles_000000.vtp";
    ASSERT_TRUE(fs::exists(file));
    ASSERT_EQ(readPvd((scratch.path / "snapshots.pvd").string()).size(),
              2u);  // particles and walls, as before

    const ParticleFrame f = readParticlesVtp(file.string());
    EXPECT_EQ(f.time, 0.125);
    ASSERT_EQ(f.size(), s.size());
    ASSERT_EQ(f.cornerStart.size(), s.size() + 1);
    const auto slots = slotsById(s);
    std::size_t polygons = 0;
    for (std::size_t p = 0; p < f.size(); ++p) {
        SCOPED_TRACE("particle id " + std::to_string(f.id[p]));
        ASSERT_EQ(slots.count(f.id[p]), 1u);
        const std::size_t i = slots.at(f.id[p]);
        EXPECT_EQ(f.x[p], s.x[i]);
        EXPECT_EQ(f.y[p], s.y[i]);
        EXPECT_EQ(f.radius[p], s.radius[i]);
        EXPECT_EQ(f.angle[p], s.angle[i]);
        EXPECT_EQ(f.speed[p], std::hypot(s.vx[i], s.vy[i]));
        const bool polygon = s.shape[i] != model::kDiskShape;
        ASSERT_EQ(f.isPolygon(p), polygon);
        if (!polygon) {
            EXPECT_EQ(p, 0u) << "disks (vertex cells) come first";
            continue;
        }
        ++polygons;
        const std::vector<Vec2> want = worldCorners(s, pool, i);
        ASSERT_EQ(f.cornerCount(p), want.size());
        for (std::size_t c = 0; c < want.size(); ++c) {
            const Vec2 got = f.corners[f.cornerStart[p] + c];
            EXPECT_NEAR(got.x, want[c].x, 1e-12) << "corner " << c;
            EXPECT_NEAR(got.y, want[c].y, 1e-12) << "corner " << c;
            // every corner lies on the circumcircle or inside it
            EXPECT_LE(std::hypot(got.x - s.x[i], got.y - s.y[i]), s.radius[i] * (1 + 1e-12));
        }
        // counter-clockwise in the world (positive signed area)
        double area2 = 0;
        for (std::size_t c = 0; c < want.size(); ++c) {
            const Vec2 a = f.corners[f.cornerStart[p] + c],
                       b = f.corners[f.cornerStart[p] + (c + 1) % want.size()];
            area2 += a.x * b.y - a.y * b.x;
        }
        EXPECT_GT(area2, 0);
    }
    EXPECT_EQ(polygons, 4u);

    // Header: 1 vertex + 4 polygons; corner points 6 + 3 + 6 + 4 plus the disk centre.
    const std::string text = slurp(file);
    EXPECT_NE(text.find("NumberOfPoints=\"20\" NumberOfVerts=\"1\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                        "NumberOfPolys=\"4\""),
              std::string::npos);
    EXPECT_NE(text.find("<Polys>"), std::string::npos);
}

TEST(PolygonOutput, CellDataHoldsPerParticleValues) {
    const test::ScratchDir scratch;
    const dem::World world = test::makeWorldFromToml(kPolygonScene);
    const model::ParticleStore& s = world.store();
    const fs::path file = scratch.path / "p.vtp";
    writeParticlesVtp(file.string(), s, world.shapes(), 0.0);
    const std::string text = slurp(file);

    const auto id = appendedArray<std::int64_t>(text, "CellData", "id");
    const auto velocity = appendedArray<double>(text, "CellData", "velocity");
    const auto omega = appendedArray<double>(text, "CellData", "omega");
    const auto mass = appendedArray<double>(text, "CellData", "mass");
    const auto material = appendedArray<std::int32_t>(text, "CellData", "material");
    const auto kind = appendedArray<std::int32_t>(text, "CellData", "shape_kind");
    const auto corners = appendedArray<std::int32_t>(text, "CellData", "corners");
    const auto position = appendedArray<double>(text, "CellData", "position");
    ASSERT_EQ(id.size(), s.size());
    ASSERT_EQ(velocity.size(), 3 * s.size());
    ASSERT_EQ(position.size(), 3 * s.size());
    ASSERT_EQ(kind.size(), s.size());
    const auto slots = slotsById(s);
    for (std::size_t c = 0; c < id.size(); ++c) {
        const std::size_t i = slots.at(id[c]);
        const bool polygon = s.shape[i] != model::kDiskShape;
        EXPECT_EQ(velocity[3 * c], s.vx[i]);
        EXPECT_EQ(velocity[3 * c + 1], s.vy[i]);
        EXPECT_EQ(velocity[3 * c + 2], 0.0);
        EXPECT_EQ(omega[c], s.omega[i]);
        EXPECT_EQ(mass[c], s.mass[i]);
        EXPECT_EQ(material[c], static_cast<std::int32_t>(s.material[i]));
        EXPECT_EQ(kind[c], polygon ? 1 : 0);
        EXPECT_EQ(corners[c], polygon ? static_cast<std::int32_t>(world.shapes().count[s.shape[i]]) : 0);
        EXPECT_EQ(position[3 * c], s.x[i]);
        EXPECT_EQ(position[3 * c + 1], s.y[i]);
    }
    // Point data at polygon corners repeats the particle's values with radius 0 (no glyph there).
    const auto pointRadius = appendedArray<double>(text, "PointData", "radius");
    const auto pointId = appendedArray<std::int64_t>(text, "PointData", "id");
    ASSERT_EQ(pointRadius.size(), 20u);
    int zero = 0;
    for (std::size_t p = 0; p < pointRadius.size(); ++p) {
        const std::size_t i = slots.at(pointId[p]);
        EXPECT_EQ(pointRadius[p], s.shape[i] == model::kDiskShape ? s.radius[i] : 0.0);
        zero += pointRadius[p] == 0.0;
    }
    EXPECT_EQ(zero, 19);
}

TEST(PolygonOutput, DiskOnlyFileKeepsTheDiskLayout) {
    const test::ScratchDir scratch;
    model::ParticleStore s;
    s.add(3, {0.1, 0.2}, {1.0, 0.0}, 0.5, 1.0, 0.01, 1.0, 1.0, 0);
    s.add(1, {0.3, 0.2}, {0.0, 0.0}, 0.0, 0.0, 0.02, 1.0, 1.0, 0);
    const fs::path withPool = scratch.path / "a.vtp", without = scratch.path / "b.vtp";
    writeParticlesVtp(withPool.string(), s, model::ShapePool{}, 0.5);
    writeParticlesVtp(without.string(), s, 0.5);
    const std::string text = slurp(withPool);
    EXPECT_EQ(text, slurp(without));
    EXPECT_EQ(text.find("<CellData"), std::string::npos);
    EXPECT_EQ(text.find("<Polys>"), std::string::npos);
    EXPECT_NE(text.find("NumberOfPolys=\"0\""), std::string::npos);
    const ParticleFrame f = readParticlesVtp(withPool.string());
    ASSERT_EQ(f.size(), 2u);
    EXPECT_FALSE(f.isPolygon(0));
    EXPECT_FALSE(f.isPolygon(1));
    EXPECT_TRUE(f.corners.empty());
    EXPECT_EQ(f.id[0], 3);
    EXPECT_EQ(f.radius[1], 0.02);
}

TEST(PolygonOutput, ShapeOutsideThePoolThrows) {
    const test::ScratchDir scratch;
    model::ParticleStore s;
    s.add(0, {0, 0}, {0, 0}, 0, 0, 0.01, 1.0, 1.0, 0, 5);
    EXPECT_THROW(writeParticlesVtp((scratch.path / "p.vtp").string(), s, model::ShapePool{}, 0.0),
                 std::invalid_argument);
    EXPECT_THROW(writeFinalCsv((scratch.path / "final.csv").string(), s, model::ShapePool{}, {"g"},
                               model::MassModel::Disk),
                 std::invalid_argument);
}

TEST(PolygonOutput, FinalCsvNamesShapesAndCountsCorners) {
    const test::ScratchDir scratch;
    const dem::World world = test::makeWorldFromToml(kPolygonScene);
    const fs::path path = scratch.path / "final.csv";
    writeFinalCsv(path.string(), world.store(), world.shapes(), {"grain", "rock"}, model::MassModel::Disk);
    std::vector<std::string> header;
    const auto rows = test::readCsv(path, header);
    // Old columns first and in order, the new one appended.
    const std::vector<std::string> want = {"id",    "shape", "x",      "y",    "vx",       "vy",
                                           "angle", "omega", "radius", "mass", "material", "corners"};
    EXPECT_EQ(header, want);
    ASSERT_EQ(rows.size(), 5u);
    const std::vector<std::pair<std::string, std::string>> shapeAndCorners = {
        {"polygon", "6"}, {"polygon", "3"}, {"disk", "0"}, {"polygon", "6"}, {"polygon", "4"}};
    for (std::size_t r = 0; r < rows.size(); ++r) {
        EXPECT_EQ(rows[r].at("id"), std::to_string(r));  // sorted by id = scene order
        EXPECT_EQ(rows[r].at("shape"), shapeAndCorners[r].first) << "row " << r;
        EXPECT_EQ(rows[r].at("corners"), shapeAndCorners[r].second) << "row " << r;
    }
    EXPECT_EQ(rows[1].at("material"), "rock");
    EXPECT_EQ(std::stod(rows[1].at("omega")), -3.5);
    EXPECT_EQ(std::stod(rows[0].at("vx")), 0.3);
}

TEST(PolygonOutput, FinalCsvCallsSphereParticlesSpheres) {
    const test::ScratchDir scratch;
    const dem::World world = test::makeWorldFromToml(R"(
[run]
end_time = 0.01
[dem]
dt = 1.0e-6
mass_model = "sphere"
[[material]]
name = "steel"
density = 7700.0
[[contact]]
materials = ["steel", "steel"]
kn = 1.0e5
[[particle]]
position = [0.0, 0.0]
radius = 0.01
material = "steel"
[[particle]]
position = [0.05, 0.0]
radius = 0.01
material = "steel"
)");
    const fs::path path = scratch.path / "final.csv";
    writeFinalCsv(path.string(), world.store(), world.shapes(), {"steel"}, model::MassModel::Sphere);
    std::vector<std::string> header;
    const auto rows = test::readCsv(path, header);
    ASSERT_EQ(rows.size(), 2u);
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("shape"), "sphere");
        EXPECT_EQ(row.at("corners"), "0");
    }
    EXPECT_EQ(header.back(), "corners");
}

}  // namespace
}  // namespace granulab::io
