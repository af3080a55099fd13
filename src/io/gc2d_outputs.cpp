// SPDX-License-Identifier: MIT
// gc2d's legacy data files (io/gc2d_outputs.hpp; gc2d spec 9.1, 9.5, 2.1).
#include "io/gc2d_outputs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "io/atomic_file.hpp"

namespace granulab::io {

namespace {

/// A counter-clockwise quantity in gc2d's clockwise convention; 0.0 - x also turns -0 into +0.
double clockwise(double ccw) noexcept {
    return 0.0 - ccw;
}

/// Slot of every grain id of `g`.
std::unordered_map<std::int64_t, std::size_t> indexOf(const analysis::GrainFrame& g) {
    std::unordered_map<std::int64_t, std::size_t> at;
    at.reserve(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) at.emplace(g.id[i], i);
    return at;
}

/// The complete lines of `text` ('\n'-terminated); a last line without '\n' is left out.
std::vector<std::string_view> completeLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t from = 0;
    for (std::size_t nl = text.find('\n'); nl != std::string_view::npos; nl = text.find('\n', from)) {
        lines.push_back(text.substr(from, nl - from));
        from = nl + 1;
    }
    return lines;
}

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

std::string gc2dFileName(const std::string& basename, std::string_view ext) {
    return fmt::format("{}.{}", basename, ext);
}

std::string gc2dFileName(const std::string& basename, std::int64_t number, std::string_view ext) {
    return fmt::format("{}.{:04d}.{}", basename, number, ext);
}

std::size_t gc2dOutlineWidth(std::size_t widest) noexcept {
    return std::max(kGc2dMaxCorners, widest);
}

std::string ggfLine(std::int64_t id, int type, std::span<const Vec2> bodyCorners, std::size_t width) {
    if (bodyCorners.size() > width)
        throw std::invalid_argument(
            fmt::format("gc2d ggf: body {} has {} corners, more than the file's N_max = {}", id,
                        bodyCorners.size(), width));
    fmt::memory_buffer out;
    fmt::format_to(std::back_inserter(out), "{} {} {}", id, type, bodyCorners.size());
    for (const Vec2& c : bodyCorners) fmt::format_to(std::back_inserter(out), " {}", c.x);
    for (std::size_t k = bodyCorners.size(); k < width; ++k) fmt::format_to(std::back_inserter(out), " 0");
    for (const Vec2& c : bodyCorners) fmt::format_to(std::back_inserter(out), " {}", c.y);
    for (std::size_t k = bodyCorners.size(); k < width; ++k) fmt::format_to(std::back_inserter(out), " 0");
    out.push_back('\n');
    return fmt::to_string(out);
}

Vec2 outlineCentroid(std::span<const Vec2> corners, bool closed) noexcept {
    if (corners.empty()) return {};
    Vec2 mean{0, 0};
    for (const Vec2& c : corners) mean = mean + c;
    mean = mean / static_cast<Real>(corners.size());
    if (!closed || corners.size() < 3) return mean;
    // Shoelace about the mean (less cancellation far from the origin).
    Real twiceArea = 0;
    Vec2 moment{0, 0};
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const Vec2 p = corners[k] - mean, q = corners[(k + 1) % corners.size()] - mean;
        const Real w = cross(p, q);
        twiceArea += w;
        moment = moment + (p + q) * w;
    }
    Real extent = 0;
    for (const Vec2& c : corners) extent = std::max(extent, norm2(c - mean));
    if (!(std::abs(twiceArea) > 1e-12 * extent)) return mean;  // a degenerate ring
    return mean + moment / (3 * twiceArea);
}

std::string gpfText(const Gc2dIds& ids, const Gc2dWalls& walls, const analysis::GrainFrame& grains,
                    const GrainAccelerations& acc) {
    fmt::memory_buffer out;
    for (std::size_t w = 0; w < walls.size(); ++w)
        fmt::format_to(std::back_inserter(out), "{} {} {} {} {} {} {} 0 0 0\n",
                       ids.wall(static_cast<std::int64_t>(w)), walls.centroid[w].x, walls.centroid[w].y,
                       clockwise(walls.angle[w]), walls.velocity[w].x, walls.velocity[w].y,
                       clockwise(walls.omega[w]));
    for (std::size_t i = 0; i < grains.size(); ++i)
        fmt::format_to(std::back_inserter(out), "{} {} {} {} {} {} {} {} {} {}\n", ids.grain(grains.id[i]),
                       grains.x[i], grains.y[i], clockwise(grains.angle[i]), grains.vx[i], grains.vy[i],
                       clockwise(grains.omega[i]), acc.ax[i], acc.ay[i], clockwise(acc.alpha[i]));
    return fmt::to_string(out);
}

std::string gffText(const Gc2dIds& ids, const Gc2dWalls& walls, const analysis::GrainFrame& grains,
                    const analysis::ContactFrame& contacts, const std::vector<OneBodyForce>& oneBody) {
    const auto at = indexOf(grains);
    const auto centre = [&](std::int64_t grain) {
        const auto it = at.find(grain);
        if (it == at.end())
            throw std::invalid_argument(
                fmt::format("gc2d gff: grain {} of a force is not in the frame", grain));
        return Vec2{grains.x[it->second], grains.y[it->second]};
    };
    fmt::memory_buffer out;
    const auto line = [&](std::int64_t id1, std::int64_t id2, Vec2 s, Vec2 p, Vec2 f) {
        fmt::format_to(std::back_inserter(out), "{} {} {} {} {} {} {} {}\n", id1, id2, s.x, s.y, p.x, p.y,
                       f.x, f.y);
    };
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const Vec2 p{contacts.px[k], contacts.py[k]};
        const Vec2 f{contacts.fx[k], contacts.fy[k]};
        const Vec2 minusF{0.0 - f.x, 0.0 - f.y};
        const std::int64_t a = ids.grain(contacts.a[k]);
        if (contacts.atWall(k)) {
            const auto w = static_cast<std::size_t>(contacts.wall[k]);
            if (w >= walls.size())
                throw std::invalid_argument(fmt::format("gc2d gff: wall {} of a contact does not exist", w));
            const std::int64_t b = ids.wall(contacts.wall[k]);
            line(a, b, centre(contacts.a[k]), p, f);
            line(b, a, walls.centroid[w], p, minusF);
        } else {
            const std::int64_t b = ids.grain(contacts.b[k]);
            line(a, b, centre(contacts.a[k]), p, f);
            line(b, a, centre(contacts.b[k]), p, minusF);
        }
    }
    for (const OneBodyForce& o : oneBody) line(ids.grain(o.grain), -1, centre(o.grain), o.point, o.force);
    return fmt::to_string(out);
}

std::string gtfLine(std::int64_t fileNumber, double time, double g, double scale) {
    return fmt::format("{} {} {} 0.0 {}\n", fileNumber, time, g, scale);
}

std::string gplLine(const Gc2dIds& ids, double time, double g, const Gc2dWalls& walls,
                    const analysis::GrainFrame& grains) {
    fmt::memory_buffer out;
    fmt::format_to(std::back_inserter(out), "{} {}", time, g);
    for (std::size_t w = 0; w < walls.size(); ++w)
        fmt::format_to(std::back_inserter(out), " {} {} {} {} {} {}", ids.wall(static_cast<std::int64_t>(w)),
                       kGc2dWall, walls.centroid[w].x, walls.centroid[w].y, walls.velocity[w].x,
                       walls.velocity[w].y);
    for (std::size_t i = 0; i < grains.size(); ++i)
        fmt::format_to(std::back_inserter(out), " {} {} {} {} {} {}", ids.grain(grains.id[i]), kGc2dParticle,
                       grains.x[i], grains.y[i], grains.vx[i], grains.vy[i]);
    out.push_back('\n');
    return fmt::to_string(out);
}

std::vector<double> gc2dFields(std::string_view line) {
    std::vector<double> fields;
    std::size_t k = 0;
    std::string token;
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (k < line.size()) {
        while (k < line.size() && space(line[k])) ++k;
        const std::size_t from = k;
        while (k < line.size() && !space(line[k])) ++k;
        if (k == from) break;
        token.assign(line.substr(from, k - from));
        char* end = nullptr;
        const double v = std::strtod(token.c_str(), &end);
        fields.push_back(end == token.c_str() + token.size() ? v : std::numeric_limits<double>::quiet_NaN());
    }
    return fields;
}

void keepGc2dLines(const std::string& path, const std::function<bool(std::string_view line)>& keep) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return;
    const std::string text = readAll(path);
    std::string kept;
    kept.reserve(text.size());
    for (const std::string_view line : completeLines(text))
        if (keep(line)) {
            kept.append(line);
            kept.push_back('\n');
        }
    if (kept != text) writeFileAtomically(path, kept);
}

GgfContents readGgfContents(const std::string& path, const Gc2dIds& ids) {
    GgfContents c;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return c;
    c.exists = true;
    const std::string text = readAll(path);
    for (const std::string_view line : completeLines(text)) {
        const std::vector<double> f = gc2dFields(line);
        if (f.size() < 3) continue;
        if (c.width == 0) c.width = (f.size() - 3) / 2;
        const auto id = static_cast<std::int64_t>(f[0]);
        if (ids.isWall(id))
            c.walls = true;
        else if (id >= ids.wallCount)
            c.nextGrainId = std::max(c.nextGrainId, ids.granulabGrain(id) + 1);
    }
    return c;
}

Gc2dAppender::Gc2dAppender(const std::string& path, bool append)
    : m_file(std::fopen(path.c_str(), append ? "ab" : "wb")), m_path(path) {
    if (!m_file) throw std::runtime_error(fmt::format("cannot open {}: {}", path, std::strerror(errno)));
}

Gc2dAppender::~Gc2dAppender() {
    if (m_file) std::fclose(m_file);
}

Gc2dAppender::Gc2dAppender(Gc2dAppender&& o) noexcept : m_file(o.m_file), m_path(std::move(o.m_path)) {
    o.m_file = nullptr;
}

Gc2dAppender& Gc2dAppender::operator=(Gc2dAppender&& o) noexcept {
    if (this != &o) {
        if (m_file) std::fclose(m_file);
        m_file = o.m_file;
        m_path = std::move(o.m_path);
        o.m_file = nullptr;
    }
    return *this;
}

void Gc2dAppender::write(std::string_view text) {
    if (!m_file) throw std::runtime_error("gc2d file written before it was opened");
    if (std::fwrite(text.data(), 1, text.size(), m_file) != text.size() || std::fflush(m_file) != 0)
        throw std::runtime_error(fmt::format("cannot write {}: {}", m_path, std::strerror(errno)));
}

}  // namespace granulab::io
