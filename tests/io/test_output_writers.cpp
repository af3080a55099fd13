// SPDX-License-Identifier: MIT
// The shared output writers of every engine (docs/architecture.md "The run loop"): AtomicFile
// (temporary name + rename), the final.csv contract's column order, the checkpoint
// container's identity check, and series.csv kept across a resume.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "../support.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/csv_writers.hpp"
#include "io/final_csv.hpp"

using namespace granulab;
namespace fs = std::filesystem;

TEST(OutputWriters, AtomicFileAppearsOnlyWhenCommitted) {
    const test::ScratchDir scratch;
    const std::string path = (scratch.path / "sub" / "out.txt").string();
    test::writeText(scratch.path / "keep.txt", "old\n");
    {
        io::AtomicFile f(path);  // creates the folder
        f.write("half");
        EXPECT_FALSE(fs::exists(path));
        EXPECT_TRUE(fs::exists(path + ".tmp"));
    }  // abandoned: no file under the final name, no temporary left
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    {
        io::AtomicFile f((scratch.path / "keep.txt").string());
        f.write("new\n");
    }
    EXPECT_EQ(test::readText(scratch.path / "keep.txt"), "old\n");  // the old file survives
    io::writeFileAtomically(path, "done\n");
    EXPECT_EQ(test::readText(path), "done\n");
}

TEST(OutputWriters, FinalCsvPutsTheContractColumnsFirst) {
    const test::ScratchDir scratch;
    const std::string path2 = (scratch.path / "f2.csv").string(), path3 = (scratch.path / "f3.csv").string();
    {
        io::FinalCsvWriter w(path2, {2, true, {"mass", "material"}});
        io::FinalCsvParticle p;
        p.id = 7;
        p.shape = "disk";
        p.x[0] = 0.5;
        p.x[1] = -1;
        p.v[0] = 0.25;
        p.angle = 0.125;
        p.omega[2] = 3;
        p.radius = 0.1;
        w.row(p);
        w.extra(Real(2));
        w.extra(std::string_view("steel"));
        w.endRow();
        w.commit();
    }
    EXPECT_EQ(test::readText(path2),
              "id,shape,x,y,vx,vy,angle,omega,radius,mass,material\n"
              "7,disk,0.5,-1,0.25,0,0.125,3,0.10000000000000001,2,steel\n");
    {
        io::FinalCsvWriter w(path3, {3, false, {"collisions"}});
        io::FinalCsvParticle p;
        p.shape = "sphere";
        p.omega[0] = 1;
        w.row(p);
        w.extra(std::uint64_t{12});
        w.endRow();
        w.commit();
    }
    EXPECT_EQ(test::readText(path3),
              "id,shape,x,y,z,vx,vy,vz,omega_x,omega_y,omega_z,radius,collisions\n"
              "0,sphere,0,0,0,0,0,0,1,0,0,0,12\n");
}

TEST(OutputWriters, CheckpointContainerChecksEngineIdentityAndBlobLength) {
    const test::ScratchDir scratch;
    const std::string dir = scratch.path.string();
    const io::CheckpointHeader header{"toy", {{"toy.mode", "a"}, {"particles", "3"}}, {5}};
    io::writeCheckpoint(dir, header, [](std::ostream& out) { out << "state"; });
    std::string blob;
    const auto book = io::readCheckpoint(dir, header, [&](std::istream& in) {
        blob.resize(5);
        in.read(blob.data(), 5);
    });
    EXPECT_EQ(blob, "state");
    EXPECT_EQ(book.nextSnapshot, 5);
    const auto message = [&](const io::CheckpointHeader& expected, int bytes) {
        try {
            io::readCheckpoint(dir, expected, [&](std::istream& in) {
                std::string s(static_cast<std::size_t>(bytes), ' ');
                in.read(s.data(), bytes);
            });
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message({"other", header.identity, {}}, 5).find("written by the toy engine"),
              std::string::npos);
    EXPECT_NE(message({"toy", {{"toy.mode", "b"}, {"particles", "3"}}, {}}, 5).find("--set toy.mode=a"),
              std::string::npos);
    EXPECT_NE(message({"toy", {{"toy.mode", "a"}, {"particles", "4"}}, {}}, 5).find("another scene"),
              std::string::npos);
    EXPECT_NE(message(header, 4).find("not 5 bytes"), std::string::npos);  // an engine reading too little
}

TEST(OutputWriters, SeriesKeptAcrossAResumeWhoseColumnsChanged) {
    // A scene edited between checkpoint and resume (a floor stamp that now moves) adds columns:
    // the rows up to the checkpoint are rewritten in the new layout by column name, nan where the
    // old run had no such column; the rows after the checkpoint time are dropped.
    const test::ScratchDir scratch;
    const std::string path = (scratch.path / "series.csv").string();
    test::writeText(path, "time,a,b\n0,1,2\n0.5,3,4\n1,5,6\n");
    {
        io::SeriesWriter same(path, {"time", "a", "b"}, 0.5);
        same.row({0.75, 7, 8});
    }
    EXPECT_EQ(test::readText(path), "time,a,b\n0,1,2\n0.5,3,4\n0.75,7,8\n");
    {
        io::SeriesWriter changed(path, {"time", "b", "stamp_dy", "a"}, 0.5);
        changed.row({1, 10, 11, 12});
    }
    EXPECT_EQ(test::readText(path), "time,b,stamp_dy,a\n0,2,nan,1\n0.5,4,nan,3\n1,10,11,12\n");
}
