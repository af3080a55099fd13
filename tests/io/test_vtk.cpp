// SPDX-License-Identifier: MIT
// VTK writer/reader round trips (exact doubles), .pvd write/load/truncate, malformed input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "../support.hpp"
#include "io/vtk_reader.hpp"
#include "io/vtk_writer.hpp"

namespace granulab::io {
namespace {

namespace fs = std::filesystem;

model::ParticleStore sampleParticles() {
    model::ParticleStore s;
    s.add(7, {0.1, 1.0 / 3.0}, {3.0, -4.0}, 0.25, -1.5, 0.01, 2e-3, 1e-7, 0);
    s.add(42, {-2.5e-3, 1e300}, {0.0, 1e-17}, -kPi, 0.0, 0.123456789012345, 1.0, 1.0, 3);
    s.add(4000000000u, {5.0, -6.0}, {-1.0, 0.0}, 6.0, 12.0, 0.5, 0.7, 0.1, 1);
    return s;
}

std::string slurp(const fs::path& p) {
    std::ifstream is(p, std::ios::binary);
    std::ostringstream ss;
    ss << is.rdbuf();
    return ss.str();
}

TEST(Vtk, ParticlesRoundTripExactly) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    const model::ParticleStore s = sampleParticles();
    const std::string path = (dir / "vtk" / "particles_000000.vtp").string();  // creates vtk/
    writeParticlesVtp(path, s, 1.0 / 7.0);

    const ParticleFrame f = readParticlesVtp(path);
    EXPECT_EQ(f.time, 1.0 / 7.0);
    ASSERT_EQ(f.x.size(), s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        EXPECT_EQ(f.x[i], s.x[i]);
        EXPECT_EQ(f.y[i], s.y[i]);
        EXPECT_EQ(f.radius[i], s.radius[i]);
        EXPECT_EQ(f.angle[i], s.angle[i]);
        EXPECT_EQ(f.speed[i], std::hypot(s.vx[i], s.vy[i]));
        EXPECT_EQ(f.id[i], static_cast<std::int64_t>(s.id[i]));
    }
    EXPECT_EQ(f.speed[0], 5.0);
    EXPECT_EQ(f.id[2], 4000000000LL);

    const std::string text = slurp(path);
    EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
    EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
    for (const char* name :
         {"\"id\"", "\"velocity\"", "\"omega\"", "\"mass\"", "\"material\"", "\"TimeValue\""})
        EXPECT_NE(text.find(name), std::string::npos) << name;
}

TEST(Vtk, EmptyParticleSet) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    writeParticlesVtp((dir / "p.vtp").string(), model::ParticleStore{}, 2.0);
    const ParticleFrame f = readParticlesVtp((dir / "p.vtp").string());
    EXPECT_EQ(f.time, 2.0);
    EXPECT_TRUE(f.x.empty());
}

TEST(Vtk, WallsRoundTripExactly) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    model::WallSet w;
    w.addPolyline("floor", {{-1.0, 0.1}, {1.0 / 3.0, 0.0}, {2.0, 0.1}}, false, 0, {});
    w.addPolyline("box", {{0, 0}, {1, 0}, {1, 1}}, true, 1, {0.0, 1.0});
    const std::string path = (dir / "walls.vtp").string();
    writeWallsVtp(path, w, 0.5);

    const WallFrame f = readWallsVtp(path);
    ASSERT_EQ(f.a.size(), w.segments.size());
    ASSERT_EQ(f.a.size(), 5u);
    for (std::size_t k = 0; k < f.a.size(); ++k) {
        EXPECT_EQ(f.a[k], w.segments[k].a);
        EXPECT_EQ(f.b[k], w.segments[k].b);
    }
    EXPECT_NE(slurp(path).find("Name=\"wall\""), std::string::npos);
}

TEST(Vtk, PvdWriteLoadTruncate) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    const std::string path = (dir / "snapshots.pvd").string();
    PvdWriter pvd(path);
    for (int k = 0; k < 4; ++k) {
        pvd.add(0.1 * k, 0, snapshotFileName("particles", k));
        pvd.add(0.1 * k, 1, snapshotFileName("walls", k));
        pvd.write();
    }
    EXPECT_EQ(snapshotFileName("walls", 3), "vtk/walls_000003.vtp");

    const std::vector<PvdEntry> read = readPvd(path);
    ASSERT_EQ(read.size(), 8u);
    EXPECT_EQ(read[5].time, 0.1 * 2);  // exact: shortest round-trip text
    EXPECT_EQ(read[5].part, 1);
    EXPECT_EQ(read[5].file, "vtk/walls_000002.vtp");

    PvdWriter resumed(path);
    resumed.load();
    ASSERT_EQ(resumed.entries().size(), 8u);
    resumed.truncateAfter(0.1 * 1);
    ASSERT_EQ(resumed.entries().size(), 4u);
    EXPECT_EQ(resumed.entries().back().file, "vtk/walls_000001.vtp");
    resumed.write();
    EXPECT_EQ(readPvd(path).size(), 4u);
    EXPECT_FALSE(fs::exists(path + ".tmp"));

    PvdWriter fresh((dir / "none.pvd").string());
    fresh.load();  // a missing file is an empty collection
    EXPECT_TRUE(fresh.entries().empty());
}

TEST(Vtk, WriteSnapshotLaysOutFolder) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    model::WallSet w;
    w.addPolyline("floor", {{0, 0}, {1, 0}}, false, 0, {});
    PvdWriter pvd((dir / "snapshots.pvd").string());
    writeSnapshot(dir.string(), 0, sampleParticles(), model::ShapePool{}, w, 0.0, pvd);
    writeSnapshot(dir.string(), 1, sampleParticles(), model::ShapePool{}, w, 0.25, pvd);
    EXPECT_TRUE(fs::exists(dir / "vtk" / "particles_000001.vtp"));
    EXPECT_TRUE(fs::exists(dir / "vtk" / "walls_000001.vtp"));
    const auto entries = readPvd((dir / "snapshots.pvd").string());
    ASSERT_EQ(entries.size(), 4u);
    EXPECT_EQ(entries[2].time, 0.25);
    EXPECT_EQ(entries[2].file, "vtk/particles_000001.vtp");
}

TEST(Vtk, MalformedInputThrowsWithFileName) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    const std::string good = (dir / "p.vtp").string();
    writeParticlesVtp(good, sampleParticles(), 0.0);
    const std::string text = slurp(good);

    const std::string truncated = (dir / "truncated.vtp").string();
    std::ofstream(truncated, std::ios::binary) << text.substr(0, text.find("<AppendedData") + 80);
    const std::string notVtk = (dir / "garbage.vtp").string();
    std::ofstream(notVtk) << "hello";
    const std::string badPvd = (dir / "bad.pvd").string();
    std::ofstream(badPvd) << "<VTKFile type=\"Collection\"><DataSet timestep=\"x1\" file=\"a\"/>";

    const auto expectThrowNaming = [](auto&& fn, const std::string& path) {
        try {
            fn(path);
            ADD_FAILURE() << "no exception for " << path;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    };
    expectThrowNaming(readParticlesVtp, truncated);
    expectThrowNaming(readParticlesVtp, notVtk);
    expectThrowNaming(readParticlesVtp, (dir / "missing.vtp").string());
    expectThrowNaming(readWallsVtp, good);  // a particle file has no Lines
    expectThrowNaming(readPvd, badPvd);
}

}  // namespace
}  // namespace granulab::io
