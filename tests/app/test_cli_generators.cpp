// SPDX-License-Identifier: MIT
// The gc2d generators from the command line (gc2d spec section 6.5): a scene with a [[heap]] and
// an fcc [[block]] with jitter and velocity ranges runs; bad generator keys give exit status 2
// with file:line and the allowed range.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support.hpp"

using namespace granulab;

namespace {
// 18 lines; appended tables start at line 19.
const char* kBase = R"([run]
end_time = 0.01
[dem]
dt = 5e-6
[[material]]
name = "g"
density = 1.0
[[contact]]
materials = ["g", "*"]
kn = 1e4
[[particle]]
position = [0.0, 1.0]
radius = 0.01
material = "g"
[[particle]]
position = [0.05, 1.0]
radius = 0.01
material = "g"
)";

const char* kHeap = R"([[heap]]
x_range = [0.0, 0.2]
slope = 0.5
radius = 0.01
material = "g"
)";
}  // namespace

TEST(Cli, HeapAndGc2dBlockSceneRuns) {
    const test::ScratchDir scratch;
    // Heap: radius 0.01 m, x_range [0, 0.2], tan(0.5) = 0.546, rows 0.0173 m apart: the allowed
    // |x - 0.1| is 0.0817, 0.04999, 0.0183 m: rows of 9, 4 and 1 disks (14).
    // fcc block: rows y = 0.315, 0.345, 0.375 of 7 sites each (21); ids: the block (0..20), then
    // the heap (21..34), whatever the order of the tables.
    const std::string scene = std::string(R"([run]
end_time = 0.01
[dem]
dt = 5e-6
gravity = [0.0, -9.81]
[[material]]
name = "g"
density = 1.0
[[contact]]
materials = ["g", "*"]
kn = 1e4
damping = "restitution"
e = 0.5
)") + kHeap + R"([[block]]
lattice = "fcc"
grid = [0.03, 0.03]
jitter = "gauss"
jitter_fraction = 0.5
direction_range = [0.0, 3.14159]
speed_range = [0.0, 0.1]
region = [0.0, 0.3, 0.2, 0.4]
radius = 0.005
material = "g"
[[wall]]
points = [[-0.05, 1.5], [-0.05, 0.0], [0.25, 0.0], [0.25, 1.5]]
material = "g"
)";
    test::writeText(scratch.path / "heap.toml", scene);
    const auto r = test::runGranulab("run heap.toml --quiet --out out", scratch.path, 120);
    ASSERT_EQ(r.status, 0) << r.output;
    std::vector<std::string> header;
    const auto rows = test::readCsv(scratch.path / "out/final.csv", header);
    ASSERT_EQ(rows.size(), 21u + 14u);
    // The heap's first disk (id 21) rests on the floor at x = 0.02 m.
    ASSERT_EQ(rows[21].at("id"), "21");
    EXPECT_NEAR(std::stod(rows[21].at("x")), 0.02, 1e-3);
    EXPECT_NEAR(std::stod(rows[21].at("y")), 0.01, 1e-3);
}

TEST(Cli, Gc2dGeneratorBadInput) {
    const test::ScratchDir scratch;
    const std::string block = "[[block]]\nregion = [1.0, 1.0, 2.0, 2.0]\nradius = 0.01\nmaterial = \"g\"\n";
    struct Case {
        const char* name;
        std::string scene;
        std::vector<std::string> expect;
    };
    const Case cases[] = {
        {"steep_heap",
         std::string(kBase) +
             "[[heap]]\nx_range = [0.0, 0.2]\nslope = 1.2\nradius = 0.01\nmaterial = \"g\"\n",
         {"bad.toml:19", "heap[0].slope", "allowed (0, 1.10715) rad", "arctan 2"}},
        {"steep_rectangles",
         std::string(kBase) +
             "[[heap]]\nx_range = [0.0, 0.2]\nslope = 0.8\nsize = [0.02, 0.01]\nmaterial = \"g\"\n",
         {"bad.toml:19", "heap[0].slope", "allowed (0, 0.785398) rad", "arctan(2b/a)"}},
        {"flat_heap",
         std::string(kBase) +
             "[[heap]]\nx_range = [0.0, 0.2]\nslope = 0.0\nradius = 0.01\nmaterial = \"g\"\n",
         {"bad.toml:19", "heap[0].slope", "allowed (0,"}},
        {"heap_unknown_key",
         std::string(kBase) + kHeap + "slop = 0.4\n",
         {"bad.toml:24", "heap[0].slop", "did you mean 'slope'"}},
        {"heap_missing_range",
         std::string(kBase) + "[[heap]]\nslope = 0.4\nradius = 0.01\nmaterial = \"g\"\n",
         {"bad.toml:19", "heap[0].x_range", "missing"}},
        {"heap_wide_gap",
         std::string(kBase) + kHeap + "spacing = [0.02, 0.0]\n",
         {"bad.toml:19", "heap[0].spacing", "allowed [0, 0.0146"}},
        {"zero_grid",
         std::string(kBase) + block + "lattice = \"rect\"\ngrid = [0.0, 0.02]\n",
         {"bad.toml:19", "block[0].grid", "allowed (0, inf)"}},
        {"grid_too_small",
         std::string(kBase) + block + "lattice = \"fcc\"\ngrid = [0.03, 0.005]\n",
         {"bad.toml:19", "block[0].grid", "neighbours would overlap"}},
        {"unknown_jitter",
         std::string(kBase) + block + "lattice = \"rect\"\ngrid = [0.03, 0.03]\njitter = \"uniform\"\n",
         {"bad.toml:25", "block[0].jitter", "'uniform' is not allowed", "gauss"}},
        {"jitter_fraction",
         std::string(kBase) + block +
             "lattice = \"rect\"\ngrid = [0.03, 0.03]\njitter = \"equal\"\n"
             "jitter_fraction = 1.5\n",
         {"bad.toml:19", "block[0].jitter_fraction", "(0, 1]"}},
        {"jitter_on_hexagonal",
         std::string(kBase) + block + "spacing = 0.03\njitter = \"equal\"\n",
         {"bad.toml:19", "block[0].jitter", "rect"}},
        {"negative_speed",
         std::string(kBase) + block + "spacing = 0.03\nspeed_range = [-1.0, 1.0]\n",
         {"bad.toml:19", "block[0].speed_range", "0 <= v1 <= v2"}},
        {"reversed_directions",
         std::string(kBase) + block +
             "spacing = 0.03\nspeed_range = [0.0, 1.0]\ndirection_range = [1.0, 0.5]\n",
         {"bad.toml:19", "block[0].direction_range", "a2 >= a1"}},
        {"spacing_on_rect",
         std::string(kBase) + block + "lattice = \"rect\"\ngrid = [0.03, 0.03]\nspacing = 0.03\n",
         {"bad.toml:19", "block[0].spacing", "uses grid"}},
        {"jitter_overlap",  // f = 1 lets neighbours 0.021 m apart come closer than 0.02 m
         std::string(kBase) + block + "lattice = \"rect\"\ngrid = [0.021, 0.021]\njitter = \"equal\"\n",
         {"overlap by", "bad.toml:19"}},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        test::writeText(scratch.path / "bad.toml", c.scene);
        const auto r =
            test::runGranulab(fmt::format("run bad.toml --quiet --out out_{}", c.name), scratch.path);
        EXPECT_EQ(r.status, 2) << r.output;
        for (const auto& e : c.expect)
            EXPECT_NE(r.output.find(e), std::string::npos) << "missing '" << e << "' in:\n" << r.output;
    }
}
