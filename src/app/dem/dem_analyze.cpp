// SPDX-License-Identifier: MIT
// `granulab analyze DIR [what...]` of a dem run (gc2d spec section 7; docs/analysis.md): picks
// snapshots from snapshots.pvd, reads their particles, walls and contact files, runs the chosen
// analyses of analysis/ and writes DIR/analysis/snapshot_NNNNNN/<table>.csv with a line of key
// results per analysis on the terminal. Defaults follow the thesis' rules of thumb: test areas of
// about 150 grains (100-200), pressure windows of 10 grain diameters (10-20 contacts), surface
// bins of one diameter.
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "analysis/dem_analyses.hpp"
#include "analysis/dem_coarse_grain.hpp"
#include "analysis/dem_coordination.hpp"
#include "analysis/dem_force_stats.hpp"
#include "analysis/dem_grid.hpp"
#include "analysis/dem_packing.hpp"
#include "analysis/dem_persistence.hpp"
#include "analysis/dem_pressure.hpp"
#include "analysis/dem_roughness.hpp"
#include "analysis/dem_strain.hpp"
#include "analysis/dem_stress.hpp"
#include "analysis/dem_surface.hpp"
#include "analysis/janssen.hpp"
#include "app/dem/dem_engine.hpp"
#include "app/exit_codes.hpp"
#include "core/error.hpp"
#include "io/analysis_table.hpp"
#include "io/contact_file.hpp"
#include "io/vtk_reader.hpp"

namespace granulab::app {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void badOption(const std::string& option, const std::string& what) {
    throw SceneError(makeDiagnostic("granulab analyze " + option, 0, "", what));
}

/// One snapshot of the run: its index, time and files.
struct SnapshotFiles {
    int index = 0;
    double time = 0;
    fs::path particles, walls, contacts;
};

int indexOf(const std::string& file) {
    const std::string stem = fs::path(file).stem().string();
    const auto us = stem.rfind('_');
    int v = -1;
    if (us != std::string::npos) std::from_chars(stem.data() + us + 1, stem.data() + stem.size(), v);
    return v;
}

std::vector<SnapshotFiles> listSnapshots(const fs::path& dir) {
    const fs::path pvd = dir / "snapshots.pvd";
    if (!fs::is_regular_file(pvd))
        badOption(dir.string(), "no snapshots.pvd: the run wrote no snapshots (output.vtk = false?)");
    std::map<int, SnapshotFiles> byIndex;
    for (const io::PvdEntry& e : io::readPvd(pvd.string())) {
        const int index = indexOf(e.file);
        if (index < 0) continue;
        SnapshotFiles& s = byIndex[index];
        s.index = index;
        s.time = e.time;
        if (e.part == 0) s.particles = dir / e.file;
        if (e.part == 1) s.walls = dir / e.file;
    }
    std::vector<SnapshotFiles> out;
    for (auto& [index, s] : byIndex) {
        if (s.particles.empty()) continue;
        const fs::path npy = dir / io::contactFileName(index);
        if (fs::is_regular_file(npy)) s.contacts = npy;
        out.push_back(s);
    }
    if (out.empty()) badOption(pvd.string(), "lists no particle snapshots");
    return out;
}

const SnapshotFiles& nearest(const std::vector<SnapshotFiles>& snaps, double time) {
    const SnapshotFiles* best = &snaps.front();
    for (const SnapshotFiles& s : snaps)
        if (std::abs(s.time - time) < std::abs(best->time - time)) best = &s;
    return *best;
}

double parseNumber(const std::string& option, const std::string& text) {
    double v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v))
        badOption(option, fmt::format("'{}' is not a finite number", text));
    return v;
}

std::vector<double> parseList(const std::string& option, const std::string& text, char sep) {
    std::vector<double> out;
    std::size_t start = 0;
    while (true) {
        const auto end = text.find(sep, start);
        out.push_back(parseNumber(option, text.substr(start, end - start)));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return out;
}

/// "A:B" with A < B.
std::pair<double, double> parseRange(const std::string& option, const std::string& text) {
    const auto v = parseList(option, text, ':');
    if (v.size() != 2 || !(v[0] < v[1]))
        badOption(option, fmt::format("'{}': expected LO:HI with LO < HI", text));
    return {v[0], v[1]};
}

/// "W[:H]" (both > 0); H defaults to W.
std::pair<double, double> parseSize(const std::string& option, const std::string& text) {
    const auto v = parseList(option, text, ':');
    if (v.empty() || v.size() > 2 || v[0] <= 0 || (v.size() == 2 && v[1] <= 0))
        badOption(option, fmt::format("'{}': expected W or W:H in metres, both > 0", text));
    return {v[0], v.size() == 2 ? v[1] : v[0]};
}

analysis::SiloShape parseSilo(const std::string& text) {
    const auto colon = text.find(':');
    const std::string kind = text.substr(0, colon);
    const auto p =
        colon == std::string::npos ? std::vector<double>{} : parseList("--silo", text.substr(colon + 1), ',');
    const auto need = [&](std::size_t n, const char* form) {
        if (p.size() != n) badOption("--silo", fmt::format("'{}': expected {}", text, form));
    };
    try {
        if (kind == "straight") {
            need(1, "straight:R (half width [m])");
            return analysis::straightSilo(p[0]);
        }
        if (kind == "stepped") {
            need(3, "stepped:R1,R2,H0 [m]");
            return analysis::steppedSilo(p[0], p[1], p[2]);
        }
        if (kind == "slanted") {
            need(2, "slanted:A,B (r = A z + B, A [1], B [m])");
            return analysis::slantedSilo(p[0], p[1]);
        }
        if (kind == "parabolic") {
            need(2, "parabolic:A,B (r = sqrt((B - z)/A), A [1/m], B [m])");
            return analysis::parabolicSilo(p[0], p[1]);
        }
    } catch (const std::invalid_argument& e) {
        badOption("--silo", e.what());
    }
    badOption("--silo", fmt::format("'{}': the shape is one of straight, stepped, slanted, parabolic", kind));
}

/// Wall index of a name or a number, using summary.json's "walls" (names in index order).
std::int32_t wallIndex(const std::string& text, const std::vector<std::string>& names) {
    for (std::size_t k = 0; k < names.size(); ++k)
        if (names[k] == text) return static_cast<std::int32_t>(k);
    int v = -1;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec == std::errc() && r.ptr == text.data() + text.size() && v >= 0 &&
        (names.empty() || static_cast<std::size_t>(v) < names.size()))
        return v;
    std::string known;
    for (std::size_t k = 0; k < names.size(); ++k)
        known += fmt::format("{}{} ({})", k ? ", " : "", names[k], k);
    badOption("--wall", fmt::format("no wall '{}'; the walls are: {}", text, known.empty() ? "none" : known));
}

/// What one snapshot holds, with the contacts of grains that are in the frame.
struct Frame {
    analysis::GrainFrame grains;
    analysis::WallSegments walls;
    analysis::ContactFrame contacts;
    bool hasContacts = false;
    double meanDiameter = 0;     ///< [m] of the equal-area disks
    double meanArea = 0;         ///< [m^2]
    double materialDensity = 0;  ///< [kg/m^2] total mass / total grain area
    Vec2 lo, hi;                 ///< [m] bounding box of the grains
};

Frame loadFrame(const SnapshotFiles& s) {
    Frame f;
    try {  // a missing or damaged snapshot file is bad input (exit status 2), named by the reader
        f.grains = io::readParticlesVtp(s.particles.string());
        if (!s.walls.empty()) f.walls = io::readWallsVtp(s.walls.string());
        if (!s.contacts.empty()) {
            f.contacts = io::readContactsNpy(s.contacts.string());
            f.contacts.time = f.grains.time;
            f.hasContacts = true;
        }
    } catch (const std::runtime_error& e) {
        badOption(fmt::format("snapshot {}", s.index), e.what());
    }
    const std::size_t n = f.grains.size();
    double area = 0, mass = 0, diameter = 0;
    f.lo = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    f.hi = -f.lo;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = f.grains.area(i);
        area += a;
        mass += f.grains.mass[i];
        diameter += 2 * std::sqrt(a / kPi);
        const double r = f.grains.radius[i];
        f.lo = {std::min(f.lo.x, f.grains.x[i] - r), std::min(f.lo.y, f.grains.y[i] - r)};
        f.hi = {std::max(f.hi.x, f.grains.x[i] + r), std::max(f.hi.y, f.grains.y[i] + r)};
    }
    if (n > 0) {
        f.meanArea = area / static_cast<double>(n);
        f.meanDiameter = diameter / static_cast<double>(n);
        f.materialDensity = area > 0 ? mass / area : 0;
    }
    return f;
}

/// Test areas over the grains: --window/--step or about 150 grains per area, half overlapping.
analysis::TestAreaGrid areaGrid(const AnalyzeOptions& opt, const Frame& f) {
    double w, h;
    if (!opt.window.empty()) {
        std::tie(w, h) = parseSize("--window", opt.window);
    } else {
        w = h = std::sqrt(150 * f.meanArea / 0.8);  // spec 7 item 7: 100-200 grains per area
    }
    double sx = 0.5 * w, sy = 0.5 * h;
    if (!opt.step.empty()) std::tie(sx, sy) = parseSize("--step", opt.step);
    const double xmax = std::max(f.hi.x, f.lo.x + w), ymax = std::max(f.hi.y, f.lo.y + h);
    return analysis::coveringGrid(f.lo.x, f.lo.y, xmax, ymax, w, h, sx, sy);
}

/// Writes the tables of one snapshot and prints the key results.
class SnapshotAnalysis {
public:
    SnapshotAnalysis(const AnalyzeOptions& opt, const nlohmann::json& summary, const SnapshotFiles& snap,
                     const std::vector<SnapshotFiles>& all)
        : m_opt(opt),
          m_snap(snap),
          m_all(all),
          m_frame(loadFrame(snap)),
          m_outDir(fs::path(opt.dir) / "analysis" / fmt::format("snapshot_{:06d}", snap.index)) {
        if (summary.contains("walls") && summary["walls"].is_array())
            for (const auto& n : summary["walls"]) m_wallNames.push_back(n.get<std::string>());
        const double g = summary.value("gravity_magnitude", 0.0);
        m_g = g > 0 ? g : 9.81;
    }

    void run(const std::string& what) {
        if (what == "pressure") return pressure();
        if (what == "forces") return forces();
        if (what == "coordination") return coordinationNumbers();
        if (what == "repose") return repose();
        if (what == "packing") return packing();
        if (what == "stress") return stress();
        if (what == "coarse") return coarse();
        if (what == "janssen") return janssen();
        if (what == "strain") return strain();
        if (what == "persistence") return persistence();
        if (what == "roughness") return roughness();
    }

    std::size_t tablesWritten() const noexcept { return m_tables; }

private:
    void write(const analysis::Table& table) {
        io::writeTableCsv((m_outDir / (table.name + ".csv")).string(), table);
        ++m_tables;
    }
    void say(const std::string& line) const {
        if (!m_opt.quiet) fmt::print("  {}\n", line);
    }
    void needContacts(const char* what) const {
        if (!m_frame.hasContacts)
            badOption(what,
                      fmt::format("snapshot {} has no contact file {}; rerun with output.contacts = true",
                                  m_snap.index, io::contactFileName(m_snap.index)));
    }
    std::vector<std::int32_t> selectedWalls() const {
        std::vector<std::int32_t> out;
        for (const std::string& w : m_opt.walls) out.push_back(wallIndex(w, m_wallNames));
        if (out.empty()) {
            std::set<std::int32_t> present(m_frame.walls.wall.begin(), m_frame.walls.wall.end());
            out.assign(present.begin(), present.end());
        }
        return out;
    }
    std::string wallName(std::int32_t w) const {
        return static_cast<std::size_t>(w) < m_wallNames.size() ? m_wallNames[static_cast<std::size_t>(w)]
                                                                : fmt::format("wall{}", w);
    }

    void pressure() {
        needContacts("pressure");
        analysis::Table table;
        table.name = "wall_mean_pressure";
        auto& cols = table.columns;
        table.add("wall", "1");
        table.add("Fx", "N");
        table.add("Fy", "N");
        table.add("l", "m");
        table.add("p", "N/m");
        table.add("p_n", "N/m");
        table.add("contacts", "1");
        // Straight horizontal walls with contacts and their level [m]: floor candidates.
        std::vector<std::pair<std::int32_t, double>> horizontalWalls;
        for (const std::int32_t w : selectedWalls()) {
            analysis::WallPressure r;
            try {
                r = analysis::wallPressure(m_frame.contacts, m_frame.walls, {{w}, {}});
            } catch (const std::invalid_argument& e) {
                table.notes.push_back(fmt::format("wall {} ({}): {}", w, wallName(w), e.what()));
                continue;
            }
            cols[0].values.push_back(w);
            cols[1].values.push_back(r.force.x);
            cols[2].values.push_back(r.force.y);
            cols[3].values.push_back(r.length);
            cols[4].values.push_back(r.pressure);
            cols[5].values.push_back(r.normalPressure);
            cols[6].values.push_back(static_cast<double>(r.contacts));
            table.notes.push_back(fmt::format("wall {} = {}", w, wallName(w)));
            say(fmt::format(
                "wall {:>12}: {} = {:.5g} N/m over l = {:.4g} m ({} contacts), F = ({:.5g}, {:.5g}) N",
                wallName(w), r.straight ? "p" : "p_n (bent wall)", r.straight ? r.pressure : r.normalPressure,
                r.length, r.contacts, r.force.x, r.force.y));
            if (r.straight && std::abs(r.normal.y) > 0.99 && r.contacts > 0) {
                double level = 0;
                std::size_t segs = 0;
                for (std::size_t k = 0; k < m_frame.walls.size(); ++k)
                    if (m_frame.walls.wall[k] == w) {
                        level += 0.5 * (m_frame.walls.a[k].y + m_frame.walls.b[k].y);
                        ++segs;
                    }
                horizontalWalls.emplace_back(w, level / static_cast<double>(std::max<std::size_t>(segs, 1)));
            }
        }
        write(table);
        const std::vector<std::int32_t> floorWalls = floorOf(horizontalWalls);
        // Without a straight horizontal wall (a box drawn as one polyline), the floor is the lowest
        // horizontal segment and every segment on its line, with the wall contacts on that line.
        const analysis::ContactFrame* contacts = &m_frame.contacts;
        const analysis::WallSegments* segments = &m_frame.walls;
        analysis::ContactFrame floorContacts;
        analysis::WallSegments floorSegments;
        analysis::PressureProfileParams pp;
        pp.walls = floorWalls;
        std::string floorName;
        for (const std::int32_t w : floorWalls) floorName += (floorName.empty() ? "" : " + ") + wallName(w);
        if (floorWalls.empty()) {
            if (!floorFromSegments(floorContacts, floorSegments)) {
                say("no horizontal wall segment with contacts: no floor pressure profile");
                return;
            }
            pp.walls = {kFloorIndex};
            contacts = &floorContacts;
            segments = &floorSegments;
            floorName = "the lowest horizontal segments";
        }
        pp.halfWidth = m_opt.halfWidth > 0 ? m_opt.halfWidth : 5 * m_frame.meanDiameter;
        pp.step = 0.5 * pp.halfWidth;
        const analysis::PileScale scale = analysis::measurePileScale(m_frame.grains, *contacts, *segments,
                                                                     pp.walls, m_frame.materialDensity, m_g);
        if (std::isfinite(scale.h) && std::isfinite(scale.x0) && scale.x1 > scale.x0 && scale.h > 0)
            pp.scale = scale;
        const analysis::PressureProfile profile = analysis::pressureProfile(*contacts, *segments, pp);
        analysis::Table t = analysis::toTable(profile, "floor_pressure");
        t.notes.push_back(fmt::format("floor = {}", floorName));
        t.notes.push_back(
            fmt::format("rho = {:.6g} kg/m^2 (grain material, not bulk)", m_frame.materialDensity));
        write(t);
        say(fmt::format("floor profile ({}): {} windows of 2b = {:.4g} m{}", floorName, profile.x.size(),
                        2 * pp.halfWidth,
                        profile.sparseWindows ? fmt::format(", {} with < 10 contacts", profile.sparseWindows)
                                              : std::string()));
    }

    static constexpr std::int32_t kFloorIndex = 1 << 30;  ///< the synthetic wall of floorFromSegments

    /// The floor among the straight horizontal walls with contacts (wall, level [m]): the wall named
    /// `floor`, else the lowest one together with every other within half a grain diameter of its
    /// level (a floor drawn in pieces: two plates and a stamp between them, gc2d 4.3.2).
    std::vector<std::int32_t> floorOf(const std::vector<std::pair<std::int32_t, double>>& horizontal) const {
        for (const auto& [w, level] : horizontal)
            if (wallName(w) == "floor") return {w};
        double lowest = std::numeric_limits<double>::infinity();
        for (const auto& [w, level] : horizontal) lowest = std::min(lowest, level);
        std::vector<std::int32_t> out;
        for (const auto& [w, level] : horizontal)
            if (level <= lowest + 0.5 * m_frame.meanDiameter) out.push_back(w);
        return out;
    }

    /// The floor of a scene without a straight horizontal wall: the lowest line of horizontal wall
    /// segments that carries wall contacts (a box drawn as one polyline, or a polygon body whose top
    /// face the grains stand on), as wall kFloorIndex with the contacts on that line (within a tenth
    /// of a grain diameter and inside a segment's x range); false if no such line.
    bool floorFromSegments(analysis::ContactFrame& contacts, analysis::WallSegments& segments) const {
        const auto& w = m_frame.walls;
        const auto horizontal = [&](std::size_t k) {
            const Vec2 d = w.b[k] - w.a[k];
            return norm(d) > 0 && std::abs(d.y) <= 1e-9 * norm(d);
        };
        const double tol = 0.1 * m_frame.meanDiameter;
        std::set<double> levels;
        for (std::size_t k = 0; k < w.size(); ++k)
            if (horizontal(k)) levels.insert(w.a[k].y);
        for (const double level : levels) {
            analysis::WallSegments line;
            for (std::size_t k = 0; k < w.size(); ++k)
                if (horizontal(k) && std::abs(w.a[k].y - level) <= tol) {
                    line.a.push_back(w.a[k]);
                    line.b.push_back(w.b[k]);
                    line.wall.push_back(kFloorIndex);
                }
            const auto onLine = [&](std::size_t c) {
                if (!m_frame.contacts.atWall(c) || std::abs(m_frame.contacts.py[c] - level) > tol)
                    return false;
                for (std::size_t k = 0; k < line.size(); ++k)
                    if (m_frame.contacts.px[c] >= std::min(line.a[k].x, line.b[k].x) - tol &&
                        m_frame.contacts.px[c] <= std::max(line.a[k].x, line.b[k].x) + tol)
                        return true;
                return false;
            };
            analysis::ContactFrame floorContacts = m_frame.contacts;
            std::size_t count = 0;
            for (std::size_t c = 0; c < floorContacts.size(); ++c)
                if (onLine(c)) {
                    floorContacts.wall[c] = kFloorIndex;
                    ++count;
                }
            if (count > 0) {
                contacts = std::move(floorContacts);
                segments = std::move(line);
                return true;
            }
        }
        return false;
    }

    void forces() {
        needContacts("forces");
        const auto dirs = analysis::forceDirections(m_frame.contacts);
        const auto mags = analysis::forceMagnitudes(m_frame.contacts);
        write(analysis::toTable(dirs));
        write(analysis::toTable(mags));
        say(fmt::format("forces: {} contacts, <F> = {:.5g} N", m_frame.contacts.size(), mags.meanForce));
    }

    void coordinationNumbers() {
        needContacts("coordination");
        analysis::CoordinationParams p;
        p.countWalls = true;  // K counts every contact of a grain, the floor's too (spec 7 item 4)
        if (!m_opt.region.empty()) p.region = region();
        const auto c = analysis::coordination(m_frame.grains, m_frame.contacts, p);
        write(analysis::toTable(c));
        say(fmt::format(
            "coordination (walls counted): <K> = {:.4g} over all, {:.4g} without rattlers ({:.1f} % "
            "rattlers)",
            c.meanK, c.meanKNonRattler, 100 * c.rattlerFraction));
    }

    analysis::SurfaceProfile surface() const {
        analysis::SurfaceParams p;
        p.binWidth = m_opt.binWidth > 0 ? m_opt.binWidth : m_frame.meanDiameter;
        return analysis::surfaceProfile(m_frame.grains, p);
    }

    void repose() {
        const analysis::Repose r = analysis::angleOfRepose(surface());
        analysis::Table table = analysis::toTable(r);
        std::vector<std::string> lines;
        // --range: the integral method over a given half-pile (a crater's slopes A and B), as notes.
        for (std::size_t k = 0; k < m_opt.ranges.size(); ++k) {
            const auto [x0, x1] = parseRange("--range", m_opt.ranges[k]);
            const auto ir = analysis::integralRepose(r.profile, x0, x1);
            table.notes.push_back(fmt::format("range_{}_x0 = {:.10g} m", k + 1, x0));
            table.notes.push_back(fmt::format("range_{}_x1 = {:.10g} m", k + 1, x1));
            table.notes.push_back(fmt::format("repose_range_{}_deg = {:.10g} deg", k + 1, ir.angleDeg));
            lines.push_back(fmt::format("repose over [{:.4g}, {:.4g}] m: integral 2a/b^2 {:.2f} deg", x0, x1,
                                        ir.angleDeg));
        }
        write(table);
        say(fmt::format(
            "repose: top-centroid fit {:.2f} / {:.2f} deg (left / right), integral 2a/b^2 {:.2f} / "
            "{:.2f} deg",
            r.left.angleDeg, r.right.angleDeg, r.integralLeft.angleDeg, r.integralRight.angleDeg));
        for (const std::string& line : lines) say(line);
    }

    void packing() {
        const analysis::TestAreaGrid grid = areaGrid(m_opt, m_frame);
        const auto p = analysis::packingGrid(m_frame.grains, grid);
        write(analysis::packingTable(p));
        say(fmt::format("packing: {} x {} areas of {:.4g} x {:.4g} m, median rho_rel {:.4f} (hull-corrected)",
                        grid.nx, grid.ny, grid.w, grid.h, median(p.improved)));
    }

    analysis::StressGrid stressOn(const analysis::TestAreaGrid& grid) {
        needContacts("stress");
        return analysis::stressGrid(m_frame.grains, m_frame.contacts, grid);
    }

    void stress() {
        const analysis::TestAreaGrid grid = areaGrid(m_opt, m_frame);
        const auto s = stressOn(grid);
        write(analysis::stressTable(s));
        say(fmt::format("stress: {} x {} areas, median sigma_zz {:.5g} N/m, median sigma_xx {:.5g} N/m",
                        grid.nx, grid.ny, median(s.sigmaZz), median(s.sigmaXx)));
    }

    void coarse() {
        needContacts("coarse");
        analysis::CoarseGrainParams p;
        if (m_opt.kernel == "lucy")
            p.kernel = analysis::CoarseKernel::Lucy;
        else if (m_opt.kernel != "gauss")
            badOption("--kernel", fmt::format("'{}': expected gauss or lucy", m_opt.kernel));
        // Width rule (Weinhart et al. 2012): Gaussian w = d/2, Lucy c = 2d; fields barely change for
        // d/4 <= w <= d, narrower kernels resolve single grains, wider ones smear gradients.
        p.width = m_opt.kernelWidth > 0
                      ? m_opt.kernelWidth
                      : (p.kernel == analysis::CoarseKernel::Lucy ? 2.0 : 0.5) * m_frame.meanDiameter;
        // Grid spacing one mean diameter, over the grains' box widened by the kernel's reach (the
        // fields do not end at the outermost centres).
        const double dx = m_frame.meanDiameter, reach = analysis::kernelCutoff(p);
        const Vec2 origin = m_frame.lo - Vec2{reach, reach};
        const auto nx =
            static_cast<std::size_t>(std::ceil((m_frame.hi.x - m_frame.lo.x + 2 * reach) / dx)) + 1;
        const auto ny =
            static_cast<std::size_t>(std::ceil((m_frame.hi.y - m_frame.lo.y + 2 * reach) / dx)) + 1;
        if (nx * ny > 4'000'000) badOption("coarse", "more than 4e6 grid points; raise --kernel-width");
        const auto points = analysis::gridPoints(origin, dx, dx, nx, ny);
        const auto fields = analysis::coarseGrain(m_frame.grains, m_frame.contacts, points, p);
        write(analysis::coarseGrainTable(fields, p));
        say(fmt::format("coarse: {} x {} points, {} kernel of width {:.4g} m", nx, ny, m_opt.kernel,
                        p.width));
    }

    void janssen() {
        if (m_opt.silo.empty())
            badOption("janssen",
                      "needs the silo's shape: --silo straight:R | stepped:R1,R2,H0 | slanted:A,B | "
                      "parabolic:A,B (half width r(z) [m], z down from the free surface)");
        const analysis::SiloShape shape = parseSilo(m_opt.silo);
        const analysis::TestAreaGrid grid = areaGrid(m_opt, m_frame);
        const auto s = stressOn(grid);
        const double top = std::isfinite(m_opt.surface) ? m_opt.surface : m_frame.hi.y;
        auto profile = analysis::depthProfile(s, top);
        if (!m_opt.depth.empty()) {  // e.g. the thesis drops the slanted silo below z = 0.35 m
            const auto [z0, z1] = parseRange("--depth", m_opt.depth);
            analysis::DepthProfile kept = profile;
            kept.z.clear();
            kept.sigmaXx.clear();
            kept.sigmaZz.clear();
            kept.areas.clear();
            for (std::size_t k = 0; k < profile.z.size(); ++k)
                if (profile.z[k] >= z0 && profile.z[k] <= z1) {
                    kept.z.push_back(profile.z[k]);
                    kept.sigmaXx.push_back(profile.sigmaXx[k]);
                    kept.sigmaZz.push_back(profile.sigmaZz[k]);
                    kept.areas.push_back(profile.areas[k]);
                }
            profile = std::move(kept);
        }
        // Bulk density: the grains' mass over the silo's area from the surface to the lowest grain.
        double mass = 0;
        for (double m : m_frame.grains.mass) mass += m;
        const double depth = top - m_frame.lo.y;
        double siloArea = 0;
        const int n = 2000;
        for (int k = 0; k < n; ++k) {
            const double z = (k + 0.5) * depth / n;
            const double r = shape.halfWidth(z);
            if (std::isfinite(r) && r > 0) siloArea += 2 * r * depth / n;
        }
        const double rho = siloArea > 0 ? mass / siloArea : m_frame.materialDensity;
        const auto fit = analysis::fitJanssen(shape, profile.z, profile.sigmaXx, profile.sigmaZz, rho, m_g);
        analysis::Table t = analysis::janssenTable(profile, shape, fit, rho, m_g);
        t.notes.push_back(fmt::format("rho_rel = {:.4f}", rho / m_frame.materialDensity));
        write(t);
        say(fmt::format(
            "janssen ({}): k = {:.3f} (areas: {:.3f} +- {:.3f}), mu_j = {:.3f}, rho_rel = {:.3f}{}",
            m_opt.silo, fit.k, profile.kMean, profile.kStd, fit.mu, rho / m_frame.materialDensity,
            fit.converged ? "" : " (fit did not converge)"));
    }

    const SnapshotFiles& referenceSnapshot(const char* what) const {
        if (m_opt.reference < 0) badOption(what, "needs --reference TIME, the time of the other snapshot");
        return nearest(m_all, m_opt.reference);
    }

    void strain() {
        const SnapshotFiles& ref = referenceSnapshot("strain");
        const Frame reference = loadFrame(ref);
        const analysis::TestAreaGrid grid = areaGrid(m_opt, m_frame);
        const auto s = stressOn(grid);
        const auto st = analysis::strainGrid(reference.grains, m_frame.grains, s);
        write(analysis::strainTable(st, s));
        say(fmt::format("strain against t = {:.6g} s: nu_avg = {:.3f}, E_avg = {:.4g} N/m", ref.time,
                        st.nuMean, st.EMean));
    }

    void persistence() {
        const SnapshotFiles& ref = referenceSnapshot("persistence");
        const Frame before = loadFrame(ref);
        if (!before.hasContacts) badOption("persistence", "the --reference snapshot has no contact file");
        needContacts("persistence");
        analysis::PersistenceParams p;
        if (!m_opt.region.empty()) p.region = region();
        const auto r = analysis::contactPersistence(before.contacts, m_frame.contacts, m_frame.grains, p);
        write(analysis::toTable(r));
        say(fmt::format("persistence from t = {:.6g} s: {} of {} contacts kept ({:.3f})", ref.time,
                        r.pairsKept, r.pairsBefore, r.fraction));
    }

    void roughness() {
        const analysis::Repose r = analysis::angleOfRepose(surface());
        analysis::RoughnessParams p;
        for (const std::string& range : m_opt.ranges) p.ranges.push_back(parseRange("--range", range));
        if (p.ranges.empty()) {  // the two flanks, foot to apex
            if (r.left.points > 1) p.ranges.push_back({r.profile.x[r.footLeft], r.profile.x[r.apexFirst]});
            if (r.right.points > 1) p.ranges.push_back({r.profile.x[r.apexLast], r.profile.x[r.footRight]});
        }
        if (p.ranges.empty())
            badOption("roughness", "no flank found; give the surface ranges with --range X0:X1");
        p.baseLength = 0;
        for (const auto& [x0, x1] : p.ranges) p.baseLength = std::max(p.baseLength, x1 - x0);
        const auto spectrum = analysis::roughnessSpectrum(r.profile, p);
        write(analysis::toTable(spectrum));
        say(fmt::format("roughness: {} ranges, base length {:.4g} m, rms deviation {:.4g} m", p.ranges.size(),
                        p.baseLength, spectrum.rmsDeviation));
    }

    analysis::Rect region() const {
        const auto comma = m_opt.region.find(',');
        if (comma == std::string::npos) badOption("--region", "expected X0:X1,Y0:Y1 [m]");
        const auto [x0, x1] = parseRange("--region", m_opt.region.substr(0, comma));
        const auto [y0, y1] = parseRange("--region", m_opt.region.substr(comma + 1));
        return {x0, x1, y0, y1};
    }

    static double median(std::vector<double> v) {
        std::erase_if(v, [](double x) { return !std::isfinite(x); });
        if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
        return v[v.size() / 2];
    }

    const AnalyzeOptions& m_opt;
    const SnapshotFiles& m_snap;
    const std::vector<SnapshotFiles>& m_all;
    Frame m_frame;
    fs::path m_outDir;
    std::vector<std::string> m_wallNames;
    double m_g = 9.81;
    std::size_t m_tables = 0;
};

std::vector<std::string> chosenAnalyses(const AnalyzeOptions& opt) {
    std::vector<std::string> out;
    for (const std::string& w : opt.what) {
        if (!analysis::findDemAnalysis(w)) {
            std::string list;
            for (const auto& a : analysis::kDemAnalyses) list += fmt::format("\n  {:<12} {}", a.name, a.what);
            badOption(w, fmt::format("unknown analysis; the analyses of a dem run are:{}", list));
        }
    }
    for (const auto& a : analysis::kDemAnalyses)
        if (opt.what.empty() ? a.defaultSet
                             : std::find(opt.what.begin(), opt.what.end(), a.name) != opt.what.end())
            out.push_back(a.name);
    return out;
}

}  // namespace

int demAnalyze(const AnalyzeOptions& opt, const nlohmann::json& summary) {
    const std::vector<std::string> what = chosenAnalyses(opt);
    const std::vector<SnapshotFiles> snaps = listSnapshots(opt.dir);
    std::vector<const SnapshotFiles*> chosen;
    if (opt.every > 0) {
        for (std::size_t k = 0; k < snaps.size(); k += static_cast<std::size_t>(opt.every))
            chosen.push_back(&snaps[k]);
        if (chosen.back() != &snaps.back()) chosen.push_back(&snaps.back());
    } else {
        chosen.push_back(opt.at >= 0 ? &nearest(snaps, opt.at) : &snaps.back());
    }
    std::size_t tables = 0;
    for (const SnapshotFiles* s : chosen) {
        if (!opt.quiet)
            fmt::print("snapshot {} (t = {:.6g} s): analysis/snapshot_{:06d}/\n", s->index, s->time,
                       s->index);
        SnapshotAnalysis a(opt, summary, *s, snaps);
        for (const std::string& w : what) {
            try {
                a.run(w);
            } catch (const std::invalid_argument& e) {
                badOption(w, e.what());
            }
        }
        tables += a.tablesWritten();
    }
    if (!opt.quiet)
        fmt::print(
            "{} tables in {}/analysis/; plot them: python3 scripts/plot_analysis.py "
            "{}/analysis/snapshot_{:06d}\n",
            tables, opt.dir, opt.dir, chosen.back()->index);
    return kExitOk;
}

namespace {

/// A diagnostic as one line of the run's warnings: no "error: " tier, no line breaks.
std::string oneLine(std::string text) {
    if (text.rfind("error: ", 0) == 0) text.erase(0, 7);
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

}  // namespace

std::vector<std::string> demAnalyzeSnapshot(const std::string& dir, int index,
                                            const std::vector<std::string>& what,
                                            const nlohmann::json& summary) {
    AnalyzeOptions opt;
    opt.dir = dir;
    opt.what = what;
    opt.quiet = true;
    std::vector<std::string> failed;
    try {
        const std::vector<SnapshotFiles> snaps = listSnapshots(dir);
        const auto it = std::find_if(snaps.begin(), snaps.end(),
                                     [&](const SnapshotFiles& s) { return s.index == index; });
        if (it == snaps.end()) return {fmt::format("snapshot {} is not in snapshots.pvd", index)};
        SnapshotAnalysis a(opt, summary, *it, snaps);
        for (const std::string& w : chosenAnalyses(opt)) {
            try {
                a.run(w);
            } catch (const std::exception& e) {  // SceneError or invalid_argument: no grains yet, ...
                failed.push_back(oneLine(e.what()));
            }
        }
    } catch (const std::exception& e) {
        failed.push_back(oneLine(e.what()));
    }
    return failed;
}

}  // namespace granulab::app
