// SPDX-License-Identifier: MIT
// VTK XML PolyData writer. Why raw appended binary: exact doubles (restart-grade, no text
// round-off), no base64 and no zlib dependency, and ParaView reads it directly. Layout of the
// appended block: "_" then, per array, a UInt64 byte count followed by the little-endian values;
// each DataArray's `offset` points at its byte count, counted from the first byte after "_".
#include "io/vtk_writer.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace granulab::io {

namespace {
static_assert(std::endian::native == std::endian::little, "the VTK writer assumes a little-endian host");

/// Shortest text that reads back to the same double.
std::string exactText(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

/// Collects the XML header and the appended binary block of one .vtp file.
class VtpBuilder {
public:
    void line(const std::string& text) { m_xml += text + "\n"; }

    template <class T>
    void array(const std::string& indent, const char* type, const std::string& name, int components,
               const std::vector<T>& values, const std::string& extra = "") {
        m_xml += fmt::format(
            "{}<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"{} format=\"appended\" "
            "offset=\"{}\"/>\n",
            indent, type, name, components, extra, m_blob.size());
        const std::uint64_t bytes = values.size() * sizeof(T);
        m_blob.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
        m_blob.append(reinterpret_cast<const char*>(values.data()), bytes);
    }

    void timeValue(double time) {
        line("    <FieldData>");
        array("      ", "Float64", "TimeValue", 1, std::vector<double>{time}, " NumberOfTuples=\"1\"");
        line("    </FieldData>");
    }

    void save(const std::string& path) const {
        const std::filesystem::path p(path);
        if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
        std::ofstream os(path, std::ios::binary | std::ios::trunc);
        os << "<?xml version=\"1.0\"?>\n"
           << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
              "header_type=\"UInt64\">\n  <PolyData>\n"
           << m_xml << "  </PolyData>\n  <AppendedData encoding=\"raw\">\n_";
        os.write(m_blob.data(), static_cast<std::streamsize>(m_blob.size()));
        os << "\n  </AppendedData>\n</VTKFile>\n";
        if (!os) throw std::runtime_error("cannot write " + path);
    }

private:
    std::string m_xml;
    std::string m_blob;
};

std::string pieceTag(std::size_t points, std::size_t verts, std::size_t lines) {
    return fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"{}\" "
                       "NumberOfStrips=\"0\" NumberOfPolys=\"0\">",
                       points, verts, lines);
}
}  // namespace

void writeParticlesVtp(const std::string& path, const model::ParticleStore& s, double time) {
    const std::size_t n = s.size();
    std::vector<double> points(3 * n, 0.0), velocity(3 * n, 0.0), speed(n);
    std::vector<std::int64_t> id(n), connectivity(n), offsets(n);
    std::vector<std::int32_t> material(n);
    for (std::size_t i = 0; i < n; ++i) {
        points[3 * i] = s.x[i];
        points[3 * i + 1] = s.y[i];
        velocity[3 * i] = s.vx[i];
        velocity[3 * i + 1] = s.vy[i];
        speed[i] = std::hypot(s.vx[i], s.vy[i]);
        id[i] = s.id[i];
        material[i] = static_cast<std::int32_t>(s.material[i]);
        connectivity[i] = static_cast<std::int64_t>(i);
        offsets[i] = static_cast<std::int64_t>(i + 1);  // end offset of each cell (VTK XML 1.0)
    }
    VtpBuilder b;
    b.timeValue(time);
    b.line(pieceTag(n, n, 0));
    const std::string in = "        ";
    b.line("      <PointData Scalars=\"speed\" Vectors=\"velocity\">");
    b.array(in, "Int64", "id", 1, id);
    b.array(in, "Float64", "radius", 1, s.radius);
    b.array(in, "Float64", "velocity", 3, velocity);
    b.array(in, "Float64", "speed", 1, speed);
    b.array(in, "Float64", "omega", 1, s.omega);
    b.array(in, "Float64", "angle", 1, s.angle);
    b.array(in, "Float64", "mass", 1, s.mass);
    b.array(in, "Int32", "material", 1, material);
    b.line("      </PointData>");
    b.line("      <Points>");
    b.array(in, "Float64", "Points", 3, points);
    b.line("      </Points>");
    b.line("      <Verts>");
    b.array(in, "Int64", "connectivity", 1, connectivity);
    b.array(in, "Int64", "offsets", 1, offsets);
    b.line("      </Verts>");
    b.line("    </Piece>");
    b.save(path);
}

void writeWallsVtp(const std::string& path, const model::WallSet& w, double time) {
    const std::size_t n = w.segments.size();
    std::vector<double> points(6 * n, 0.0);
    std::vector<std::int64_t> connectivity(2 * n), offsets(n);
    std::vector<std::int32_t> wall(n);
    for (std::size_t k = 0; k < n; ++k) {
        const model::WallSegment& seg = w.segments[k];
        points[6 * k] = seg.a.x;
        points[6 * k + 1] = seg.a.y;
        points[6 * k + 3] = seg.b.x;
        points[6 * k + 4] = seg.b.y;
        connectivity[2 * k] = static_cast<std::int64_t>(2 * k);
        connectivity[2 * k + 1] = static_cast<std::int64_t>(2 * k + 1);
        offsets[k] = static_cast<std::int64_t>(2 * k + 2);
        wall[k] = static_cast<std::int32_t>(seg.wall);
    }
    VtpBuilder b;
    b.timeValue(time);
    b.line(pieceTag(2 * n, 0, n));
    const std::string in = "        ";
    b.line("      <CellData Scalars=\"wall\">");
    b.array(in, "Int32", "wall", 1, wall);
    b.line("      </CellData>");
    b.line("      <Points>");
    b.array(in, "Float64", "Points", 3, points);
    b.line("      </Points>");
    b.line("      <Lines>");
    b.array(in, "Int64", "connectivity", 1, connectivity);
    b.array(in, "Int64", "offsets", 1, offsets);
    b.line("      </Lines>");
    b.line("    </Piece>");
    b.save(path);
}

std::string snapshotFileName(const std::string& stem, int index) {
    return fmt::format("vtk/{}_{:06d}.vtp", stem, index);
}

PvdWriter::PvdWriter(std::string path) : m_path(std::move(path)) {}

void PvdWriter::add(double time, int part, const std::string& relativeFile) {
    m_entries.push_back({time, part, relativeFile});
}

void PvdWriter::write() const {
    const std::string tmp = m_path + ".tmp";
    {
        std::ofstream os(tmp, std::ios::trunc);
        os << "<?xml version=\"1.0\"?>\n"
           << "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\" "
              "header_type=\"UInt64\">\n  <Collection>\n";
        for (const PvdEntry& e : m_entries)
            os << "    <DataSet timestep=\"" << exactText(e.time) << "\" group=\"\" part=\"" << e.part
               << "\" file=\"" << e.file << "\"/>\n";
        os << "  </Collection>\n</VTKFile>\n";
        if (!os) throw std::runtime_error("cannot write " + tmp);
    }
    std::error_code ec;
    std::filesystem::rename(tmp, m_path, ec);
    if (ec) throw std::runtime_error("cannot write " + m_path + ": " + ec.message());
}

void PvdWriter::load() {
    m_entries.clear();
    if (!std::filesystem::exists(m_path)) return;
    m_entries = readPvd(m_path);
}

void PvdWriter::truncateAfter(double time) {
    std::erase_if(m_entries, [time](const PvdEntry& e) { return e.time > time; });
}

void writeSnapshot(const std::string& outDir, int index, const model::ParticleStore& s,
                   const model::WallSet& w, double time, PvdWriter& pvd) {
    const std::filesystem::path dir(outDir);
    const std::string particles = snapshotFileName("particles", index);
    const std::string walls = snapshotFileName("walls", index);
    writeParticlesVtp((dir / particles).string(), s, time);
    writeWallsVtp((dir / walls).string(), w, time);
    pvd.add(time, 0, particles);
    pvd.add(time, 1, walls);
    pvd.write();
}

}  // namespace granulab::io
