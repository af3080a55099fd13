// SPDX-License-Identifier: MIT
// The [edmd] cell-grid keys (edmd spec 2.4, 3.1, AT-6; docs/scene-format.md "[edmd]"):
// cells_per_particle and cell_grid parse, bad values are reported with the key and the allowed
// range or list, "morton" gives power-of-two cells per axis, "free" and "auto" (the default) the
// count nearest the target, cells_per_particle moves the grid
// both ways from the automatic C/N, a small periodic box falls back from "morton" to "free" with a warning,
// and a target that makes 2^31 cells or more is refused.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "../support/scene.hpp"
#include "edmd/scene_setup.hpp"
#include "io/validate_edmd.hpp"

using namespace granulab;

namespace {

/// A periodic gas scene; `extra` is appended to [edmd].
std::string gasScene(int dim, const std::string& edmd) {
    return fmt::format(
        "[run]\nengine = \"edmd\"\ndimension = {}\nend_time = 1.0\n\n[edmd]\nradius = 1.0\n{}\n", dim, edmd);
}

/// Reads, checks and resolves a scene as `granulab run` does; throws SceneError.
edmd::Setup resolve(const std::string& text) {
    const auto sc = test::readSceneText(text, "cells.toml");
    Diagnostics d;
    io::checkEdmdDef(sc, d);
    d.throwIfAny();
    return edmd::resolveScene(sc);
}

/// The engine's grid for a resolved scene (edmd::chooseCellGrid, as Engine::buildCells uses it).
std::array<int, 3> gridOf(const edmd::Setup& s) {
    const auto n = static_cast<std::uint32_t>(s.init.count);
    const Real a = std::max(s.init.radius, s.init.radiusMax);
    return s.dim == 2 ? edmd::chooseCellGrid<2>(s.config, n, a) : edmd::chooseCellGrid<3>(s.config, n, a);
}

double cellCount(const edmd::Setup& s) {
    const auto g = gridOf(s);
    double c = 1;
    for (int d = 0; d < s.dim; ++d) c *= g[d];
    return c;
}

bool powerOfTwo(int v) {
    return v > 0 && (v & (v - 1)) == 0;
}

/// The SceneError text of a scene that must be refused ("" if it is accepted).
std::string errorOf(const std::string& text) {
    try {
        resolve(text);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(EdmdSceneCells, KeysParseWithTheirDefaults) {
    const auto plain = test::readSceneText(gasScene(2, "count = 400\nvolume_fraction = 0.3"));
    EXPECT_EQ(plain.edmd.cellsPerParticle, 0);
    EXPECT_EQ(plain.edmd.cellGrid, "auto");
    const auto set = test::readSceneText(
        gasScene(3, "count = 400\nvolume_fraction = 0.3\ncells_per_particle = 2.5\ncell_grid = \"free\""));
    EXPECT_EQ(set.edmd.cellsPerParticle, 2.5);
    EXPECT_EQ(set.edmd.cellGrid, "free");
    const auto s =
        resolve(gasScene(3,
                         "count = 400\nvolume_fraction = 0.3\ncells_per_particle = 2.5\ncell_grid = "
                         "\"free\""));
    EXPECT_EQ(s.config.cellsPerParticle, 2.5);
    EXPECT_FALSE(s.config.powerOfTwoCells);
    // "auto": the free grid (on any number of ranks: the parallel engine takes the serial grid).
    EXPECT_FALSE(resolve(gasScene(3, "count = 400\nvolume_fraction = 0.3")).config.powerOfTwoCells);
    EXPECT_TRUE(resolve(gasScene(3, "count = 400\nvolume_fraction = 0.3\ncell_grid = \"morton\""))
                    .config.powerOfTwoCells);
}

TEST(EdmdSceneCells, BadValuesNameTheKeyAndTheAllowedRange) {
    for (const char* bad : {"-1.0", "20000.0", "1e300"}) {
        const std::string err = errorOf(
            gasScene(2, fmt::format("count = 400\nvolume_fraction = 0.3\ncells_per_particle = {}", bad)));
        EXPECT_NE(err.find("cells.toml:6: edmd.cells_per_particle: must be in (0, 10000]"), std::string::npos)
            << bad << ": " << err;
        EXPECT_NE(err.find("or 0 (automatic)"), std::string::npos) << err;
    }
    for (const char* bad : {"nan", "inf"}) {  // refused by the reader
        const std::string err = errorOf(
            gasScene(2, fmt::format("count = 400\nvolume_fraction = 0.3\ncells_per_particle = {}", bad)));
        EXPECT_NE(err.find("cells.toml:10: edmd.cells_per_particle: must be a finite number"),
                  std::string::npos)
            << bad << ": " << err;
    }
    std::string err;
    try {
        test::readSceneText(gasScene(2, "count = 400\nvolume_fraction = 0.3\ncell_grid = \"mortn\""),
                            "cells.toml");
    } catch (const SceneError& e) {
        err = e.what();
    }
    EXPECT_NE(
        err.find("cells.toml:10: edmd.cell_grid: 'mortn' is not allowed (did you mean 'morton'?); allowed: "
                 "auto, morton, free"),
        std::string::npos)
        << err;
    // A target that makes 2^31 cells or more (3e5 particles x 1e4 at nu = 1e-5, where the
    // diameter would allow 1.6e10 cells).
    err =
        errorOf(gasScene(3,
                         "count = 300000\nvolume_fraction = 1e-5\ncells_per_particle = 10000.0\ncell_grid = "
                         "\"free\""));
    EXPECT_NE(err.find("edmd.cells_per_particle: 1e+04 cells per particle x 300000 particles makes"),
              std::string::npos)
        << err;
    EXPECT_NE(err.find("allowed fewer than 2^31"), std::string::npos) << err;
}

TEST(EdmdSceneCells, MortonGivesPowersOfTwoAndFreeTheNearestCount) {
    // 2D: 400 disks at nu = 0.3, L = 64.7, target edge sqrt(L^2 / (1.5 N)) = 2.64: free 24
    // cells per axis, morton 32 (the power of two nearest in ratio).
    const std::string base = "count = 400\nvolume_fraction = 0.3\n";
    const auto morton = gridOf(resolve(gasScene(2, base + "cell_grid = \"morton\"")));
    const auto free = gridOf(resolve(gasScene(2, base + "cell_grid = \"free\"")));
    const auto automatic = gridOf(resolve(gasScene(2, base)));  // one process: free
    EXPECT_EQ(automatic, free);
    EXPECT_EQ(morton[0], 32);
    EXPECT_EQ(morton[1], 32);
    EXPECT_EQ(free[0], 24);
    EXPECT_EQ(free[1], 24);
    // 3D, non-cubic box, several targets: every axis a power of two with "morton".
    for (const char* cpp : {"0", "0.5", "3", "8", "40"}) {
        const auto g = gridOf(resolve(gasScene(
            3, fmt::format("box = [60.0, 40.0, 25.0]\ncount = 2000\ncells_per_particle = {}\ncell_grid = "
                           "\"morton\"",
                           cpp))));
        for (int d = 0; d < 3; ++d) EXPECT_TRUE(powerOfTwo(g[d])) << cpp << " axis " << d << ": " << g[d];
    }
}

TEST(EdmdSceneCells, CellsPerParticleMovesTheGridBothWays) {
    // Dilute gases (the diameter does not limit the cells): the automatic C/N is 1.5 (2D) and 8 (3D).
    struct Case {
        int dim;
        const char* scene;
        double fewer, automatic, more;
    };
    const Case cases[] = {{2, "count = 4000\nvolume_fraction = 0.02\n", 0.25, 1.5, 8},
                          {3, "count = 4000\nvolume_fraction = 0.002\n", 1, 8, 64}};
    for (const auto& c : cases)
        for (const char* grid : {"free", "morton"}) {
            const std::string base = std::string(c.scene) + "cell_grid = \"" + grid + "\"\n";
            const double automatic = cellCount(resolve(gasScene(c.dim, base)));
            const double fewer =
                cellCount(resolve(gasScene(c.dim, base + fmt::format("cells_per_particle = {}", c.fewer))));
            const double more =
                cellCount(resolve(gasScene(c.dim, base + fmt::format("cells_per_particle = {}", c.more))));
            const double explicitAuto = cellCount(
                resolve(gasScene(c.dim, base + fmt::format("cells_per_particle = {}", c.automatic))));
            EXPECT_LT(fewer, automatic) << c.dim << "D " << grid;
            EXPECT_GT(more, automatic) << c.dim << "D " << grid;
            EXPECT_EQ(explicitAuto, automatic) << c.dim << "D " << grid;
            if (std::string(grid) ==
                "free") {  // the nearest count: C/N within the rounding of 4000 particles
                EXPECT_NEAR(fewer / 4000, c.fewer, 0.3 * c.fewer) << c.dim << "D";
                EXPECT_NEAR(more / 4000, c.more, 0.3 * c.more) << c.dim << "D";
                EXPECT_NEAR(automatic / 4000, c.automatic, 0.3 * c.automatic) << c.dim << "D";
            }
        }
}

TEST(EdmdSceneCells, SmallPeriodicBoxFallsBackFromMortonToFree) {
    // 7 m edges with disks of radius 1: 3 cells of one diameter fit, 4 do not, so no power of
    // two of at least 3 cells: the run uses 3 free cells per axis and says so.
    const auto s = resolve(gasScene(2, "box = [7.0, 7.0]\ncount = 2\ncell_grid = \"morton\""));
    EXPECT_FALSE(s.config.powerOfTwoCells);
    EXPECT_EQ(gridOf(s)[0], 3);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("edmd.cell_grid = \"morton\""), std::string::npos) << s.warnings[0];
    // A box of 8.5 m holds 4 cells: morton stays, no warning.
    const auto fits = resolve(gasScene(2, "box = [8.5, 8.5]\ncount = 2\ncell_grid = \"morton\""));
    EXPECT_TRUE(fits.config.powerOfTwoCells);
    EXPECT_EQ(gridOf(fits)[0], 4);
    EXPECT_TRUE(fits.warnings.empty());
    // Growing spheres: the grid at the end of the growth decides (2 a = 2 + 2 * 0.2 = 2.4 m at
    // t = 1: 10 m holds 4 cells at the start, 4.17 at the end, fine; 9 m holds only 3 at the end).
    EXPECT_TRUE(
        resolve(gasScene(2, "box = [10.0, 10.0]\ncount = 2\ngrowth_rate = 0.2\ncell_grid = \"morton\""))
            .config.powerOfTwoCells);
    EXPECT_FALSE(
        resolve(gasScene(2, "box = [9.0, 9.0]\ncount = 2\ngrowth_rate = 0.2\ncell_grid = \"morton\""))
            .config.powerOfTwoCells);
}
