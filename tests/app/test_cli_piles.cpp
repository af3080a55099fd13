// SPDX-License-Identifier: MIT
// The ordered pile of gc2d spec 8.4 end to end (examples/studies/piles/ordered_columns.toml):
// squares stacked in separate columns on a floor. Each column rests on its own floor contact, so
// the floor pressure in a window is the weight of the columns whose foot lies in it (p is
// proportional to the local column height, forces vertical, no load passed between columns),
// the profile is a tent (linear flanks of slope rho_A g a tan(psi) / pitch), and every grain
// with a grain above and below has exactly two contacts (coordination 2 inside, no contacts
// between columns). Run and analysis as a user would, through the binary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "../support.hpp"

using namespace granulab;

namespace {

/// An analysis table (granulab analyze): the rows after the `# ` notes and the header.
std::vector<std::vector<double>> readTable(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::string line;
    std::vector<std::vector<double>> rows;
    bool header = false;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (!header) {
            header = true;
            continue;
        }
        std::vector<double> row;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
        rows.push_back(row);
    }
    return rows;
}

struct Line {
    double slope = 0, intercept = 0, r2 = 0;
};

Line fit(const std::vector<double>& x, const std::vector<double>& y) {
    const double n = static_cast<double>(x.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t k = 0; k < x.size(); ++k) {
        sx += x[k];
        sy += y[k];
        sxx += x[k] * x[k];
        sxy += x[k] * y[k];
    }
    Line l;
    l.slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    l.intercept = (sy - l.slope * sx) / n;
    double ssRes = 0, ssTot = 0;
    for (std::size_t k = 0; k < x.size(); ++k) {
        const double r = y[k] - (l.slope * x[k] + l.intercept);
        ssRes += r * r;
        ssTot += (y[k] - sy / n) * (y[k] - sy / n);
    }
    l.r2 = 1 - ssRes / ssTot;
    return l;
}

}  // namespace

TEST(Cli, PileColumnsOfSquaresTent) {
    test::ScratchDir dir;
    const std::string scene =
        std::string(GRANULAB_SOURCE_DIR) + "/examples/studies/piles/ordered_columns.toml";
    // 0.05 s: the stacks settle within a few ms (the full scene runs 0.1 s).
    auto r = test::runGranulab("run '" + scene + "' -q --out out --set run.end_time=0.05", dir.path, 300);
    ASSERT_EQ(r.status, 0) << r.output;
    const double b = 0.007;  // window half width: 1.4 column pitches
    r = test::runGranulab("analyze out pressure coordination -q --half-width 0.007", dir.path, 120);
    ASSERT_EQ(r.status, 0) << r.output;

    // The scene: squares a = 4 mm, columns 5 mm apart (1 mm gaps), flanks psi = 0.5 rad.
    const double a = 0.004, pitch = 0.005, psi = 0.5, g = 9.81, rhoA = 5000;
    std::vector<std::string> header;
    const auto grains = test::readCsv(dir.path / "out/final.csv", header);
    ASSERT_GT(grains.size(), 200u);
    std::map<long, int> count;      // grains per column (column index = round(x / pitch))
    std::map<long, double> weight;  // [N per m depth]
    for (const auto& row : grains) {
        const double x = std::stod(row.at("x"));
        const long c = std::lround(x / pitch);
        ASSERT_NEAR(x, c * pitch, 0.1 * a) << "a grain left its column";
        ++count[c];
        weight[c] += std::stod(row.at("mass")) * g;
    }

    const auto snapshots = dir.path / "out/analysis";
    std::filesystem::path snap;
    for (const auto& e : std::filesystem::directory_iterator(snapshots))
        if (e.path().filename().string() > snap.filename().string()) snap = e.path();
    const auto profile = readTable(snap / "floor_pressure.csv");
    ASSERT_GT(profile.size(), 20u);

    // 1. p(x) = (1/2b) x the weight of the columns in the window, i.e. proportional to the local
    // column height: every column stands on its own floor contact and passes no load sideways.
    // Windows with a column foot within 0.2 mm of an edge are skipped (the contact point decides).
    double pMax = 0;
    for (const auto& [c, w] : weight) pMax = std::max(pMax, w);
    std::vector<double> xs, ps;
    for (const auto& row : profile) {
        const double x = row.at(0), p = row.at(1);
        bool edge = false;
        double expected = 0;
        for (const auto& [c, w] : weight) {
            const double dx = std::abs(c * pitch - x);
            edge = edge || std::abs(dx - b) < 2e-4;
            if (dx <= b) expected += w / (2 * b);
        }
        if (edge) continue;
        // 1 % of the weight of the tallest column per window: far below one grain's weight
        // (1/14 of the tallest column), so a lost or shared square fails.
        EXPECT_NEAR(p, expected, 0.01 * pMax / (2 * b)) << "window at x = " << x;
        xs.push_back(x);
        ps.push_back(p);
    }
    ASSERT_GT(xs.size(), 20u);

    // 2. The tent: linear flanks, slope rho_A g a^2 per grain x tan(psi)/a grains per m of run,
    // per pitch of floor. Fitted between the foot and the apex, a window away from both. Column
    // heights are whole numbers of squares, so the profile is a staircase about the line: R^2 of
    // a 3-column window is ~0.92-0.96, hence 0.85; the slope to 15 %.
    const double xFoot = count.begin()->first * pitch, xEnd = count.rbegin()->first * pitch;
    const double tent = rhoA * g * a * std::tan(psi) / pitch;  // [N/m^2]
    for (const int side : {-1, 1}) {
        std::vector<double> fx, fp;
        for (std::size_t k = 0; k < xs.size(); ++k) {
            const bool left = xs[k] > xFoot + b && xs[k] < -b - pitch;
            const bool right = xs[k] < xEnd - b && xs[k] > b + pitch;
            if ((side < 0 && left) || (side > 0 && right)) {
                fx.push_back(xs[k]);
                fp.push_back(ps[k]);
            }
        }
        ASSERT_GT(fx.size(), 8u);
        const Line l = fit(fx, fp);
        EXPECT_GT(l.r2, 0.85) << "side " << side;
        EXPECT_NEAR(l.slope, -side * tent, 0.15 * tent) << "side " << side;
    }

    // 3. Coordination (the analysis counts the floor's contacts, spec 7 item 4): a grain with one
    // above and one below has K = 2, so has the bottom of a column standing on the floor with a
    // square above; the top of a column has K = 1, a lone square 1 (the floor); nothing more.
    long interior = 0;
    for (const auto& [c, n] : count) interior += n >= 2 ? n - 1 : 0;
    const auto coord = readTable(snap / "coordination.csv");  // K, P, grains
    long twos = 0, more = 0;
    for (const auto& row : coord) {
        if (row.at(0) == 2) twos = std::lround(row.at(2));
        if (row.at(0) > 2) more += std::lround(row.at(2));
    }
    EXPECT_EQ(more, 0) << "contacts between columns";
    EXPECT_EQ(twos, interior);
}

namespace {

/// The notes `# key = value unit` of an analysis table.
std::map<std::string, double> readNotes(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::string line;
    std::map<std::string, double> notes;
    while (std::getline(in, line)) {
        if (line.rfind("# ", 0) != 0) continue;
        const auto eq = line.find(" = ");
        if (eq == std::string::npos) continue;
        try {
            notes[line.substr(2, eq - 2)] = std::stod(line.substr(eq + 3));
        } catch (const std::exception&) {
        }
    }
    return notes;
}

struct Repose {
    double left = 0, right = 0;
};

/// Pours the 300-grain version of a point-source scene (run.sh reduced) and measures its flanks by
/// the integral method tan(phi) = 2a/b^2 (gc2d spec 7.5b): on piles this small the straight-line
/// fit of the top centroids swings by up to 9 deg between the flanks of one pile (a foot or a
/// rounded top pulls it), the area of each half-pile much less.
Repose pour(const std::string& scene, const std::filesystem::path& dir, const std::string& out) {
    const std::string path = std::string(GRANULAB_SOURCE_DIR) + "/examples/studies/piles/" + scene;
    auto r = test::runGranulab(
        "run '" + path + "' -q --out " + out + " --set source[0].to=3.0 run.end_time=3.3 dem.dt=5e-6", dir,
        600);
    EXPECT_EQ(r.status, 0) << r.output;
    r = test::runGranulab("analyze " + out + " repose -q", dir, 120);
    EXPECT_EQ(r.status, 0) << r.output;
    std::filesystem::path snap;
    for (const auto& e : std::filesystem::directory_iterator(dir / out / "analysis"))
        if (e.path().filename().string() > snap.filename().string()) snap = e.path();
    const auto n = readNotes(snap / "repose_profile.csv");
    return {n.count("integral_left_deg") ? n.at("integral_left_deg") : NAN,
            n.count("integral_right_deg") ? n.at("integral_right_deg") : NAN};
}

}  // namespace

// gc2d spec 8.6 (Fig. 4.18): point-source piles of 7- and 13-cornered grains. 300 grains of
// r = 1.5 mm each (the full scenes pour 2,500) build piles whose flanks the repose analysis finds.
// The thesis's trend (rounder grains, flatter piles) is NOT tested: at 300 grains it is within
// the scatter between realizations. Three seeds each gave mean integral angles of 26.5 and 21.7
// deg (7 / 13 corners) before the threaded step's summation order and 29.3 and 28.7 deg after,
// with single piles from 17 to 33 deg (monodisperse 13-gons crystallize, and a lattice facet
// makes one flank as steep as 42 deg); examples/studies/piles/README.md has the table. One pile
// is one realization, so a comparison of two of them passed or failed by chance.
TEST(Cli, PilesPouredFromSevenAndThirteenCornerGrains) {
    test::ScratchDir dir;
    const Repose r7 = pour("pour_mono7.toml", dir.path, "out7");
    const Repose r13 = pour("pour_mono13.toml", dir.path, "out13");
    for (const double a : {r7.left, r7.right, r13.left, r13.right}) {
        ASSERT_TRUE(std::isfinite(a));
        EXPECT_GT(a, 5.0);   // a pile, not a layer
        EXPECT_LT(a, 45.0);  // below any angle a pile of mu = 0.6 grains can hold
    }
}
