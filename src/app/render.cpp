// SPDX-License-Identifier: MIT
// `granulab render`: option parsing, the scan pass and the frame loop. The scan pass reads ALL
// snapshots of the run (also with --every) for the world box, the colour range (lo and hi), the
// largest contact force and a typical grain radius, so every frame has the same view, colour
// scale and force line widths whatever frames are drawn; the draw pass holds one frame at a time.
// Drawing: app/render_scene.cpp, app/render_colors.cpp, app/render_forces.cpp.
#include "app/render.hpp"

#include <cairo.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "app/render_colors.hpp"
#include "app/render_forces.hpp"
#include "app/render_scene.hpp"
#include "io/contact_file.hpp"
#include "io/vtk_reader.hpp"

namespace granulab::app {

namespace {
namespace fs = std::filesystem;
using namespace render;

constexpr int kMinWidth = 64, kMaxWidth = 16384;
constexpr double kMaxSceneHeight = 16384;  // [px] cairo surfaces stay below 32767 px
constexpr double kMargin = 0.03;           // fraction of the box size added on each side
constexpr double kStrokePad = 4;           // [px] room for the widest stroke (walls: 3 px)
constexpr double kPaleUnderForces = 0.55;  // fills mixed with white under the force network
constexpr double kForceWidth = 0.6;        // strongest force line: this fraction of a radius

/// One snapshot: particle file, wall file and contact file (both may be absent) of one time.
struct Snapshot {
    double time = 0;
    int index = 0;
    fs::path particles, walls, contacts;
};

/// Snapshot index from "…_NNNNNN.vtp", else `fallback`.
int indexFromName(const std::string& file, int fallback) {
    const std::string stem = fs::path(file).stem().string();
    const auto us = stem.rfind('_');
    if (us == std::string::npos) return fallback;
    int v = 0;
    const auto r = std::from_chars(stem.data() + us + 1, stem.data() + stem.size(), v);
    return (r.ec == std::errc() && r.ptr == stem.data() + stem.size() && v >= 0) ? v : fallback;
}

std::vector<Snapshot> collectSnapshots(const fs::path& dir, const std::vector<io::PvdEntry>& entries) {
    std::vector<Snapshot> out;
    std::error_code ec;
    for (const io::PvdEntry& e : entries) {
        if (e.part != 0) continue;
        Snapshot s{e.time, indexFromName(e.file, static_cast<int>(out.size())), dir / e.file, {}, {}};
        for (const io::PvdEntry& w : entries)
            if (w.part == 1 && w.time == e.time) {
                s.walls = dir / w.file;
                break;
            }
        const fs::path contacts = dir / io::contactFileName(s.index);
        if (fs::is_regular_file(contacts, ec)) s.contacts = contacts;
        out.push_back(std::move(s));
    }
    return out;
}

/// The box of an edmd run from OUTDIR/summary.json ("box", "periodic"); none for DEM runs.
std::optional<BoxOutline> readBox(const fs::path& dir) {
    std::ifstream in(dir / "summary.json");
    if (!in) return std::nullopt;
    try {
        const nlohmann::json js = nlohmann::json::parse(in);
        if (!js.contains("box")) return std::nullopt;
        const auto box = js.at("box").get<std::vector<double>>();
        if (box.size() < 2 || !(box[0] > 0) || !(box[1] > 0)) return std::nullopt;
        const auto periodic = js.value("periodic", std::vector<bool>(box.size(), false));
        BoxOutline b{
            {0, 0}, {box[0], box[1]}, periodic.size() > 0 && periodic[0], periodic.size() > 1 && periodic[1]};
        return b;
    } catch (const std::exception&) {
        return std::nullopt;  // an unreadable summary only loses the outline
    }
}

/// Per-grain value of the colour mode (pressure and coordination from `sums`).
double grainValue(ColorMode mode, const analysis::GrainFrame& g, const GrainContactSums* sums,
                  std::size_t i) {
    switch (mode) {
        case ColorMode::Id:
            return static_cast<double>(g.id[i]);
        case ColorMode::Speed:
            return g.speed[i];
        case ColorMode::Pressure:
            return sums ? sums->pressure[i] : 0.0;
        case ColorMode::Coordination:
            return sums ? sums->coordination[i] : 0.0;
        case ColorMode::Material:
            return g.material[i];
    }
    return 0;
}

/// What the scan pass finds over all snapshots.
struct Scan {
    Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Vec2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    double valueLo = std::numeric_limits<double>::infinity();
    double valueHi = -std::numeric_limits<double>::infinity();
    double maxForce = 0;       // [N]
    double typicalRadius = 0;  // [m] median radius of the first non-empty frame

    void add(Vec2 p, double r) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(r)) return;
        lo = {std::min(lo.x, p.x - r), std::min(lo.y, p.y - r)};
        hi = {std::max(hi.x, p.x + r), std::max(hi.y, p.y + r)};
    }
};

Scan scanAll(const std::vector<Snapshot>& snaps, const RenderOptions& opt,
             const std::optional<BoxOutline>& box) {
    Scan scan;
    const bool contacts = needsContacts(opt.color) || opt.forces;
    for (const Snapshot& s : snaps) {
        const io::ParticleFrame f = io::readParticlesVtp(s.particles.string());
        if (scan.typicalRadius == 0 && f.size() > 0) {
            std::vector<double> r = f.radius;
            std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2), r.end());
            scan.typicalRadius = r[r.size() / 2];
        }
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (f.isPolygon(i))
                for (std::size_t c = f.cornerStart[i]; c < f.cornerStart[i + 1]; ++c)
                    scan.add(f.corners[c], 0);
            else
                scan.add({f.x[i], f.y[i]}, f.radius[i]);
        }
        std::optional<GrainContactSums> sums;
        if (contacts && !s.contacts.empty()) {
            const analysis::ContactFrame c = io::readContactsNpy(s.contacts.string());
            scan.maxForce = std::max(scan.maxForce, maxForce(c));
            if (needsContacts(opt.color)) sums = grainContactSums(f, c, GrainIndex(f));
        }
        // Continuous quantities (speed, pressure) span the 0.5-99.5 % quantiles of each frame, so
        // that one impact or one squeezed grain does not darken every other grain of the run; the
        // discrete ones (id, material, coordination) their whole range.
        std::vector<double> values;
        values.reserve(f.size());
        for (std::size_t i = 0; i < f.size(); ++i) {
            const double v = grainValue(opt.color, f, sums ? &*sums : nullptr, i);
            if (std::isfinite(v)) values.push_back(v);
        }
        if (!values.empty()) {
            const bool continuous = opt.color == ColorMode::Speed || opt.color == ColorMode::Pressure;
            const std::size_t cut = continuous ? values.size() / 200 : 0;
            std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(cut), values.end());
            scan.valueLo = std::min(scan.valueLo, values[cut]);
            const std::size_t top = values.size() - 1 - cut;
            std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(top), values.end());
            scan.valueHi = std::max(scan.valueHi, values[top]);
        }
        if (s.walls.empty()) continue;
        const io::WallFrame w = io::readWallsVtp(s.walls.string());
        for (std::size_t k = 0; k < w.a.size(); ++k) {
            scan.add(w.a[k], 0);
            scan.add(w.b[k], 0);
        }
    }
    if (box) {
        scan.add(box->lo, 0);
        scan.add(box->hi, 0);
    }
    if (!(scan.valueHi >= scan.valueLo)) scan.valueLo = scan.valueHi = 0;
    if (opt.color == ColorMode::Id) scan.valueHi += 1;  // ids are integers: [lo, hi + 1)
    return scan;
}

/// Decimals of the time stamp: 3, more if snapshots are closer than 1 ms.
int timeDecimals(const std::vector<Snapshot>& snaps) {
    int decimals = 3;
    for (std::size_t k = 1; k < snaps.size(); ++k) {
        const double dt = std::abs(snaps[k].time - snaps[k - 1].time);
        if (dt > 0) decimals = std::max(decimals, static_cast<int>(std::ceil(-std::log10(dt))));
    }
    return std::min(decimals, 9);
}

/// Everything fixed for the run that a frame needs.
struct FrameSetup {
    RenderLayout layout;
    ColorScale scale{ColorMode::Speed, 0, 1};
    StrokeStyle strokes;
    ForceStyle forces;
    std::optional<BoxOutline> box;
    bool drawForces = false;
    int decimals = 3;
};

/// Draws one frame and writes it; false if the PNG cannot be written.
bool renderFrame(const FrameSetup& setup, const Snapshot& s, const fs::path& png) {
    const RenderLayout& L = setup.layout;
    const io::ParticleFrame f = io::readParticlesVtp(s.particles.string());
    std::optional<analysis::ContactFrame> contacts;
    if (!s.contacts.empty() && (setup.drawForces || needsContacts(setup.scale.mode())))
        contacts = io::readContactsNpy(s.contacts.string());
    const GrainIndex index(f);
    std::optional<GrainContactSums> sums;
    if (contacts && needsContacts(setup.scale.mode())) sums = grainContactSums(f, *contacts, index);
    std::vector<Rgb> fill(f.size());
    for (std::size_t i = 0; i < f.size(); ++i)
        fill[i] = setup.scale.colour(grainValue(setup.scale.mode(), f, sums ? &*sums : nullptr, i));

    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, L.width, L.height);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_save(cr);
    clipToScene(cr, L);
    if (setup.box) drawBox(cr, L, *setup.box);
    drawGrains(cr, L, f, fill, !setup.drawForces);
    if (!s.walls.empty()) drawWalls(cr, L, io::readWallsVtp(s.walls.string()), setup.strokes);
    if (setup.drawForces && contacts) drawForces(cr, L, f, *contacts, index, setup.forces);
    cairo_restore(cr);
    drawHeader(cr, L, fmt::format("t = {:.{}f} s", f.time, setup.decimals), setup.scale);
    cairo_destroy(cr);
    const bool ok = cairo_surface_write_to_png(surface, png.c_str()) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(surface);
    return ok;
}

/// `ffmpeg` on PATH, or empty.
fs::path findOnPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return {};
    std::string_view rest(path);
    while (!rest.empty()) {
        const auto colon = rest.find(':');
        const std::string_view entry = rest.substr(0, colon);
        const fs::path candidate = fs::path(entry.empty() ? "." : std::string(entry)) / program;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
        if (colon == std::string_view::npos) break;
        rest.remove_prefix(colon + 1);
    }
    return {};
}

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

/// DIR/png/movie.mp4 from the frames just written (ffmpeg's concat list png/frames.txt).
/// Without ffmpeg: says how to get it and returns 0.
int assembleMovie(const fs::path& pngDir, const std::vector<fs::path>& frames, int fps, bool quiet) {
    const fs::path ffmpeg = findOnPath("ffmpeg");
    const fs::path movie = pngDir / "movie.mp4";
    if (ffmpeg.empty()) {
        fmt::print(
            "granulab render: --movie needs ffmpeg, which is not on PATH; install it (apt-get install "
            "ffmpeg) and run `granulab render {} --png --movie` again. The PNG frames are written.\n",
            pngDir.parent_path().string());
        return 0;
    }
    const fs::path list = pngDir / "frames.txt";
    {
        std::ofstream out(list);
        for (const fs::path& p : frames)
            out << "file '" << p.filename().string() << "'\nduration " << 1.0 / fps << "\n";
        if (!frames.empty())
            out << "file '" << frames.back().filename().string() << "'\n";  // concat: last twice
        if (!out) {
            fmt::print(stderr, "granulab render: cannot write {}\n", list.string());
            return 1;
        }
    }
    const std::string cmd = fmt::format(
        "{} -y -loglevel error -f concat -safe 0 -i {} -vf "
        "'fps={},pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white,format=yuv420p' {}",
        shellQuote(ffmpeg.string()), shellQuote(list.string()), fps, shellQuote(movie.string()));
    if (std::system(cmd.c_str()) != 0) {
        fmt::print(stderr, "granulab render: ffmpeg failed: {}\n", cmd);
        return 1;
    }
    if (!quiet)
        fmt::print("granulab render: movie {} ({} frames, {} fps)\n", movie.string(), frames.size(), fps);
    return 0;
}

int badInput(const std::string& message) {
    fmt::print(stderr, "granulab render: {}\n", message);
    return 2;
}
}  // namespace

std::optional<ColorMode> parseColorMode(const std::string& name) {
    if (name == "id") return ColorMode::Id;
    if (name == "speed") return ColorMode::Speed;
    if (name == "pressure") return ColorMode::Pressure;
    if (name == "coordination") return ColorMode::Coordination;
    if (name == "material") return ColorMode::Material;
    return std::nullopt;
}

bool needsContacts(ColorMode mode) noexcept {
    return mode == ColorMode::Pressure || mode == ColorMode::Coordination;
}

std::optional<Interval> parseRange(const std::string& text) {
    const auto colon = text.find(':');
    if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos) return std::nullopt;
    const auto number = [](std::string_view s) -> std::optional<double> {
        double v = 0;
        const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v))
            return std::nullopt;
        return v;
    };
    const std::string_view all(text);
    const auto lo = number(all.substr(0, colon)), hi = number(all.substr(colon + 1));
    if (!lo || !hi || !(*hi > *lo)) return std::nullopt;
    return Interval{*lo, *hi};
}

std::optional<ViewBox> parseView(const std::string& text) {
    const auto comma = text.find(',');
    if (comma == std::string::npos) return std::nullopt;
    const auto x = parseRange(text.substr(0, comma)), y = parseRange(text.substr(comma + 1));
    if (!x || !y) return std::nullopt;
    return ViewBox{{x->lo, y->lo}, {x->hi, y->hi}};
}

RenderLayout makeLayout(Vec2 lo, Vec2 hi, int widthPixels, bool exact) {
    if (!(hi.x >= lo.x && hi.y >= lo.y)) {  // nothing to show
        lo = {0, 0};
        hi = {1, 1};
    }
    const double span = std::max(hi.x - lo.x, hi.y - lo.y);
    const double big = span > 0 ? span : 1.0;
    const auto widen = [big](double& a, double& b) {  // a degenerate axis gets 10 % of the other
        if (b - a >= 1e-6 * big) return;
        const double c = 0.5 * (a + b);
        a = c - 0.05 * big;
        b = c + 0.05 * big;
    };
    widen(lo.x, hi.x);
    widen(lo.y, hi.y);
    const double m = exact ? 0.0 : kMargin;
    const Vec2 margin{m * (hi.x - lo.x), m * (hi.y - lo.y)};
    RenderLayout L;
    L.lo = lo - margin;
    L.hi = hi + margin;
    L.width = widthPixels;
    L.fontSize = std::clamp(0.016 * widthPixels, 10.0, 26.0);
    L.headerHeight = static_cast<int>(std::ceil(4.4 * L.fontSize));
    const double pad = exact ? 0.0 : kStrokePad;  // [px] room for strokes
    const double w = L.hi.x - L.lo.x, h = L.hi.y - L.lo.y;
    L.scale = std::min((widthPixels - 2 * pad) / w, kMaxSceneHeight / h);
    L.height = L.headerHeight + static_cast<int>(std::ceil(h * L.scale + 2 * pad));
    L.originX = 0.5 * (widthPixels - w * L.scale);
    L.originY = L.headerHeight + pad;
    return L;
}

int renderCommand(const RenderOptions& opt) {
    const fs::path dir(opt.outDir), pvd = dir / "snapshots.pvd";
    if (opt.width < kMinWidth || opt.width > kMaxWidth)
        return badInput(
            fmt::format("width must be in [{}, {}] pixels, got {}", kMinWidth, kMaxWidth, opt.width));
    if (opt.every < 1) return badInput(fmt::format("--every must be at least 1, got {}", opt.every));
    if (opt.fps < 1 || opt.fps > 240)
        return badInput(fmt::format("--fps must be in [1, 240], got {}", opt.fps));
    std::error_code ec;
    if (!fs::is_regular_file(pvd, ec))
        return badInput(fmt::format("no snapshots.pvd in {}; run `granulab run` first", opt.outDir));
    const fs::path pngDir = dir / "png";
    try {
        const std::vector<Snapshot> snaps = collectSnapshots(dir, io::readPvd(pvd.string()));
        if (snaps.empty()) return badInput(pvd.string() + " lists no particle snapshots");
        const bool anyContacts =
            std::any_of(snaps.begin(), snaps.end(), [](const Snapshot& s) { return !s.contacts.empty(); });
        if ((needsContacts(opt.color) || opt.forces) && !anyContacts)
            return badInput(fmt::format(
                "{} needs contact files ({}) and {} has none; DEM runs write them beside the snapshots "
                "(edmd gases have no contact forces). Use --color id, speed or material without --forces.",
                opt.forces ? "--forces"
                           : "--color " +
                                 std::string(opt.color == ColorMode::Pressure ? "pressure" : "coordination"),
                io::contactFileName(0), opt.outDir));

        const std::optional<BoxOutline> box = readBox(dir);
        const Scan scan = scanAll(snaps, opt, box);
        FrameSetup setup;
        setup.layout = opt.view ? makeLayout(opt.view->lo, opt.view->hi, opt.width, true)
                                : makeLayout(scan.lo, scan.hi, opt.width);
        setup.scale = opt.range ? ColorScale(opt.color, opt.range->lo, opt.range->hi)
                                : ColorScale(opt.color, scan.valueLo, scan.valueHi);
        setup.strokes = makeStrokeStyle(setup.layout, scan.typicalRadius);
        setup.box = box;
        setup.drawForces = opt.forces;
        setup.forces.maxForce = scan.maxForce;
        setup.forces.maxWidth =
            std::max(kForceWidth * scan.typicalRadius * setup.layout.scale, setup.forces.minWidth);
        if (opt.forces) setup.scale.setPale(kPaleUnderForces);
        setup.decimals = timeDecimals(snaps);

        fs::create_directories(pngDir, ec);
        std::vector<fs::path> written;
        std::size_t withoutContacts = 0;
        for (std::size_t k = 0; k < snaps.size(); k += static_cast<std::size_t>(opt.every)) {
            const Snapshot& s = snaps[k];
            withoutContacts += (needsContacts(opt.color) || opt.forces) && s.contacts.empty();
            const fs::path png = pngDir / fmt::format("frame_{:06d}.png", s.index);
            if (!renderFrame(setup, s, png)) {
                fmt::print(stderr, "granulab render: cannot write {}\n", png.string());
                return 1;
            }
            written.push_back(png);
        }
        if (withoutContacts > 0)
            fmt::print(stderr,
                       "granulab render: {} of {} frames have no contact file (drawn without contacts)\n",
                       withoutContacts, written.size());
        if (!opt.quiet)
            fmt::print("granulab render: {} frames ({} x {} px) in {}\n", written.size(), setup.layout.width,
                       setup.layout.height, pngDir.string());
        if (opt.movie) return assembleMovie(pngDir, written, opt.fps, opt.quiet);
    } catch (const std::exception& e) {
        return badInput(e.what());
    }
    return 0;
}

}  // namespace granulab::app
