// SPDX-License-Identifier: MIT
// gsi -> SceneDef (io/gsi_scene.hpp; gc2d spec 9.3): the thesis's sample and one keyword of each
// kind of mapping, with gc2d's defaults and its clockwise angles turned.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/gsi_scene.hpp"

using granulab::SceneError;
using granulab::io::gsiToScene;
using granulab::io::parseGsi;
using granulab::model::BlockDef;
using granulab::model::SceneDef;

namespace {

SceneDef scene(const std::string& body) {
    return gsiToScene(parseGsi("PARAMETER v1.4\n\n" + body, "s.gsi"));
}

std::string errorsOf(const std::string& body) {
    try {
        scene(body);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

const char* kSquare = "CORNERS\n0 0\n0.01 0\n0.01 0.01\n0 0.01\nEND\n";

}  // namespace

TEST(GsiScene, ThesisSamplePiston) {
    const SceneDef s =
        granulab::io::readGsiFile(std::string(GRANULAB_SOURCE_DIR) + "/tests/data/gsi/piston.gsi");
    EXPECT_EQ(s.run.engine, "dem");
    EXPECT_EQ(s.run.title, "data/piston2");
    EXPECT_DOUBLE_EQ(s.dem.dt, 1.5e-5);
    EXPECT_DOUBLE_EQ(s.run.endTime, 0.2);
    EXPECT_EQ(s.dem.integrator, "gear");
    EXPECT_EQ(s.dem.gravity.y, -0.0);
    EXPECT_DOUBLE_EQ(s.output.seriesInterval, 1000 * 1.5e-5);
    EXPECT_DOUBLE_EQ(s.output.checkpointInterval, 100 * 1.5e-5);
    ASSERT_EQ(s.contacts.size(), 1u);
    const auto& law = s.contacts[0];
    EXPECT_EQ(law.normal, "area");
    EXPECT_EQ(law.damping, "gamma");
    EXPECT_EQ(law.tangential, "gc2d");
    EXPECT_DOUBLE_EQ(law.params.at("E").value, 1e7);
    EXPECT_DOUBLE_EQ(law.params.at("gamma").value, 0.5);
    EXPECT_DOUBLE_EQ(law.params.at("mu").value, 0.6);  // default MUE_STATISCH
    EXPECT_EQ(law.params.at("E").loc.line, 8);
    ASSERT_EQ(s.walls.size(), 4u);
    const auto& piston = s.walls[0];
    EXPECT_EQ(piston.kind, "polygon");
    EXPECT_EQ(piston.points.size(), 4u);
    EXPECT_DOUBLE_EQ(piston.offset.x, -0.3);
    ASSERT_TRUE(piston.pistonForce);
    EXPECT_DOUBLE_EQ(*piston.pistonForce, 10000);
    EXPECT_DOUBLE_EQ(piston.pistonDirection, 0);
    EXPECT_DOUBLE_EQ(piston.pistonMaxSpeed, 1);
    EXPECT_FALSE(s.walls[1].pistonForce);
    EXPECT_DOUBLE_EQ(s.walls[2].offset.y, 0.11);
    ASSERT_EQ(s.blocks.size(), 1u);
    const auto& b = s.blocks[0];
    EXPECT_EQ(b.lattice, BlockDef::Lattice::Fcc);
    EXPECT_EQ(b.jitter, BlockDef::Jitter::None);
    EXPECT_DOUBLE_EQ(b.xmin, -0.247);
    EXPECT_DOUBLE_EQ(b.ymax, 0.098);
    EXPECT_DOUBLE_EQ(b.grid.x, 0.005);
    ASSERT_EQ(s.shapes.size(), 1u);
    const auto& grain = s.shapes[0];
    EXPECT_EQ(b.shape, grain.name);
    EXPECT_EQ(grain.kind, "grain");
    EXPECT_DOUBLE_EQ(grain.size.x, 0.003);  // semi-axes (erratum 26)
    EXPECT_EQ(grain.cornerCount, 8);
    EXPECT_EQ(grain.cornerVariation, 1);
    EXPECT_EQ(grain.cornerCountMode, "equal");
    EXPECT_EQ(grain.cornerAngles, "rand1");
    EXPECT_EQ(grain.sizeMode, "const");
    EXPECT_EQ(grain.rotationMode, "equal");
    EXPECT_DOUBLE_EQ(grain.rotation, -1);  // clockwise in gc2d
    EXPECT_EQ(b.loc.line, 60);
}

TEST(GsiScene, GeneralDefaultsAreTheThesis) {
    const SceneDef s = scene("");
    EXPECT_DOUBLE_EQ(s.dem.dt, 1e-4);
    EXPECT_DOUBLE_EQ(s.run.endTime, 1);
    EXPECT_DOUBLE_EQ(s.dem.gravity.y, -9.81);
    EXPECT_EQ(s.run.title, "default");
    EXPECT_DOUBLE_EQ(s.output.seriesInterval, 1.0);  // 10000 steps of 1e-4 s
    EXPECT_DOUBLE_EQ(s.contacts[0].params.at("E").value, 1e7);
    EXPECT_DOUBLE_EQ(s.contacts[0].params.at("cohesion").value, 0);
    ASSERT_EQ(s.materials.size(), 2u);
    EXPECT_DOUBLE_EQ(s.materials[0].density, 5000);
    EXPECT_FALSE(s.machines.gravity.present);
    EXPECT_FALSE(s.machines.sizeScaling.present);
    EXPECT_NE(scene("Seed 1 2").run.seed, scene("Seed 2 1").run.seed);
    EXPECT_DOUBLE_EQ(scene("Steps_Checkpoint 4294967295\n").output.checkpointInterval,
                     0);  // infinity: at the end
}

TEST(GsiScene, VariableGravityAndHeating) {
    const SceneDef s =
        scene("G 9.81 3.0\nG_Time 0.1 0.4\nG_Type Smooth_Step\nG_Parameter 4 0.25\nHeat_Time 0 2\n");
    const auto& g = s.machines.gravity;
    ASSERT_TRUE(g.present);
    EXPECT_DOUBLE_EQ(g.g1, 9.81);
    EXPECT_DOUBLE_EQ(g.g2, 3.0);
    EXPECT_DOUBLE_EQ(g.t2, 0.4);
    EXPECT_EQ(g.type, "smooth_step");
    EXPECT_DOUBLE_EQ(g.steps, 4);
    EXPECT_DOUBLE_EQ(g.ramp, 0.25);
    EXPECT_DOUBLE_EQ(s.dem.gravity.y, 0);  // the schedule alone (the engine refuses both)
    ASSERT_TRUE(s.machines.sizeScaling.present);
    EXPECT_DOUBLE_EQ(s.machines.sizeScaling.t2, 2);
    EXPECT_DOUBLE_EQ(s.machines.sizeScaling.amplitude, 0.01);
    EXPECT_FALSE(scene("G 9.81\nG_Type LINEAR\n").machines.gravity.present);  // one G value: constant
}

TEST(GsiScene, ParticleCentredTurnedAndPulled) {
    const SceneDef s =
        scene(std::string("PARTICLE\n") + kSquare + "COM 1 2\nANGLE 0.5\nOMEGA 3\nVELOCITY 0.1 0\n" +
              "PARTICLE\n" + kSquare + "POSITION_ABSOLUT\nDrag_K 50\nDrag_Pulling_Point 0.2 0.3\n");
    ASSERT_EQ(s.particles.size(), 2u);
    EXPECT_DOUBLE_EQ(s.particles[0].position.x, 1);
    EXPECT_DOUBLE_EQ(s.particles[0].angle, -0.5);  // gc2d: clockwise
    EXPECT_DOUBLE_EQ(s.particles[0].omega, -3);
    EXPECT_DOUBLE_EQ(s.particles[0].velocity.x, 0.1);
    EXPECT_NEAR(s.particles[1].position.x, 0.005, 1e-15);  // the centroid of the absolute corners
    EXPECT_NEAR(s.particles[1].position.y, 0.005, 1e-15);
    ASSERT_EQ(s.shapes.size(), 2u);
    EXPECT_EQ(s.shapes[1].kind, "polygon");
    ASSERT_EQ(s.springs.size(), 1u);
    EXPECT_EQ(s.springs[0].particle, 1);
    EXPECT_DOUBLE_EQ(s.springs[0].stiffness, 50);
    EXPECT_DOUBLE_EQ(s.springs[0].speed, 0.1);  // DRAG_VELOCITY default
    EXPECT_DOUBLE_EQ(s.springs[0].pullStart.y, 0.3);
}

TEST(GsiScene, VibratingWallAndDropSource) {
    const SceneDef s =
        scene(std::string("WALL\n") + kSquare +
              "Vib_Type Tapping\nVib_Width 0.002\nVib_Frequence 30\nANGLE 0.1\nVelocity 0.5 0\n" +
              "DROPSOURCE\nPos 0.1 0.2\nType REL\nWidth 0.01\nDelta_T 0.05\nTime 0 3\n");
    ASSERT_EQ(s.walls.size(), 1u);
    const auto& w = s.walls[0];
    EXPECT_EQ(w.vibType, "tapping");
    EXPECT_DOUBLE_EQ(w.vibWidth, 0.002);
    EXPECT_DOUBLE_EQ(w.vibFrequency, 30);
    EXPECT_DOUBLE_EQ(w.vibDirection, granulab::kPi / 2);  // VIB_ANGLE default: up
    EXPECT_DOUBLE_EQ(w.angle, -0.1);
    EXPECT_DOUBLE_EQ(w.surfaceVelocity.x, 0.5);
    EXPECT_EQ(scene(std::string("WALL\n") + kSquare + "Vib_Width 1\n").walls[0].vibType, "cosine");
    ASSERT_EQ(s.machines.sources.size(), 1u);
    const auto& src = s.machines.sources[0];
    EXPECT_EQ(src.placement, "rel");
    EXPECT_DOUBLE_EQ(src.interval, 0.05);
    EXPECT_DOUBLE_EQ(src.to, 3);
    const auto& shape = s.shapes.back();
    EXPECT_EQ(src.insert.shape, shape.name);
    EXPECT_DOUBLE_EQ(shape.size.x, 0.01);  // DROPSOURCE's own defaults
    EXPECT_DOUBLE_EQ(shape.sizeVariation, 0.1);
    EXPECT_EQ(shape.cornerCount, 8);
}

TEST(GsiScene, WhatIsNotReadIsAnError) {
    std::string e = errorsOf("Steps_Data 0\nSteps_Checkpoint -5\n");
    EXPECT_NE(e.find("s.gsi:3: STEPS_DATA: STEPS_DATA is a number of steps, at least 1"), std::string::npos)
        << e;
    EXPECT_NE(e.find("s.gsi:4"), std::string::npos) << e;
    e = errorsOf("WALL\nOffset 1 0\n");
    EXPECT_NE(e.find("s.gsi:3"), std::string::npos) << e;
    EXPECT_NE(e.find("a WALL needs CORNERS"), std::string::npos) << e;
    e = errorsOf("Next_Data_Filenumber 0\nNext_Setup_Filenumber 10000\n");
    EXPECT_NE(e.find("s.gsi:3: NEXT_DATA_FILENUMBER"), std::string::npos) << e;
    EXPECT_NE(e.find("s.gsi:4: NEXT_SETUP_FILENUMBER"), std::string::npos) << e;
}

TEST(GsiScene, RestartStateOfAGso) {
    // TIME t0 t1: the clock starts at t0. The Gear state: ACCELERATION and OMEGA_DOT give
    // r2 = dt^2/2 a; PC_TRANS3-5 and PC_ROT3-5 are r3..r5 as written (rotations clockwise in gsi).
    const SceneDef s = scene(std::string("Delta_T 0.01\nTime 0.5 1\nPARTICLE\nID 7\n") + kSquare +
                             "Acceleration 2 -4\nOmega_Dot 6\nPC_Trans3 1 2\nPC_Trans4 3 4\nPC_Trans5 5 "
                             "6\nPC_Rot3 7\nPC_Rot4 8\nPC_Rot5 9\n");
    EXPECT_EQ(s.run.startTime, 0.5);
    EXPECT_EQ(s.run.endTime, 1.0);
    ASSERT_EQ(s.particles.size(), 1u);
    EXPECT_EQ(s.particles[0].gc2dId, 7);
    const double half = 0.01 * 0.01 / 2;
    const std::vector<double> expected = {2 * half, 1, 3, 5, -4 * half, 2, 4, 6, -6 * half, -7, -8, -9};
    EXPECT_EQ(s.particles[0].gear, expected);
    // A PARTICLE without any of them has no Gear state.
    EXPECT_TRUE(scene(std::string("PARTICLE\n") + kSquare).particles[0].gear.empty());
}

TEST(GsiScene, CompressedFileIsReadAsIs) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / fmt::format("granulab_gsi_gz_{}", ::getpid());
    fs::create_directories(dir);
    const fs::path plain = dir / "scene.gsi";
    {
        std::ofstream out(plain);
        out << "PARAMETER v1.4\n\nDelta_T 2e-5\nWALL\n" << kSquare;
    }
    ASSERT_EQ(std::system(("gzip -kf " + plain.string()).c_str()), 0);  // scene.gsi.gz beside it
    EXPECT_TRUE(granulab::io::isGsiPath((dir / "scene.gsi.gz").string()));
    EXPECT_TRUE(granulab::io::isGsiPath("A.GSI"));
    EXPECT_FALSE(granulab::io::isGsiPath("scene.gsi.toml"));
    const SceneDef s = granulab::io::readGsiFile((dir / "scene.gsi.gz").string());
    EXPECT_DOUBLE_EQ(s.dem.dt, 2e-5);
    ASSERT_EQ(s.walls.size(), 1u);
    EXPECT_EQ(s.walls[0].loc.file, (dir / "scene.gsi.gz").string());
    EXPECT_EQ(s.walls[0].loc.line, 5);
    // A damaged file: an error naming it, exit status 2 for the run.
    {
        std::ofstream out(dir / "bad.gsi.gz", std::ios::binary);
        out << "\x1f\x8b\x08\x00garbage";
    }
    EXPECT_THROW(granulab::io::readGsiFile((dir / "bad.gsi.gz").string()), SceneError);
    EXPECT_THROW(granulab::io::readGsiFile((dir / "missing.gsi").string()), SceneError);
    fs::remove_all(dir);
}
