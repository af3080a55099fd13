// SPDX-License-Identifier: MIT
// Minimal reader for our own .vtp/.pvd files: the XML header is scanned tag by tag (no XML
// library), each DataArray's section, Name, type, NumberOfComponents and offset are recorded,
// and the values are copied out of the raw appended block (UInt64 byte count + data).
// Particle files: disks are vertex cells read through their point's PointData, polygons are
// polygon cells read through CellData (layout: io/vtk_writer.hpp).
#include "io/vtk_reader.hpp"

#include <bit>
#include <charconv>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace granulab::io {

namespace {
static_assert(std::endian::native == std::endian::little, "the VTK reader assumes a little-endian host");

std::string readWholeFile(const std::string& path) {
    std::ifstream is(path, std::ios::binary);
    if (!is) throw std::runtime_error("cannot open " + path);
    std::ostringstream ss;
    ss << is.rdbuf();
    return ss.str();
}

/// Copies the value of attribute `key` of one tag's text into `out`; false if it is absent.
bool attribute(std::string_view tag, std::string_view key, std::string& out) {
    std::string needle(1, ' ');  // appended piecewise: GCC 12 warns (-Wrestrict) on a + chain
    needle.append(key).append("=\"");
    const auto p = tag.find(needle);
    if (p == std::string_view::npos) return false;
    const auto start = p + needle.size();
    const auto end = tag.find('"', start);
    if (end == std::string_view::npos) return false;
    out.assign(tag.substr(start, end - start));
    return true;
}

template <class T>
T parseNumber(const std::string& text, const std::string& path, const char* what) {
    T v{};
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size())
        throw std::runtime_error(path + ": malformed " + what + " \"" + text + "\"");
    return v;
}

/// Calls fn(tagName, tagText) for every tag `<...>` of `xml`.
template <class Fn>
void forEachTag(std::string_view xml, const std::string& path, Fn&& fn) {
    std::size_t pos = 0;
    while ((pos = xml.find('<', pos)) != std::string_view::npos) {
        const auto end = xml.find('>', pos);
        if (end == std::string_view::npos) throw std::runtime_error(path + ": unterminated XML tag");
        const std::string_view tag = xml.substr(pos + 1, end - pos - 1);
        fn(tag.substr(0, tag.find_first_of(" /\n")), tag);
        pos = end + 1;
    }
}

struct ArrayInfo {
    std::string section, name, type;
    int components = 1;
    std::uint64_t offset = 0;
};

/// One parsed .vtp file: array directory plus the appended bytes.
class VtpFile {
public:
    explicit VtpFile(const std::string& path) : m_path(path), m_text(readWholeFile(path)) {
        const auto appended = m_text.find("<AppendedData");
        if (appended == std::string::npos) fail("no <AppendedData> block");
        const std::string_view header(m_text.data(), appended);
        if (header.find("type=\"PolyData\"") == std::string_view::npos ||
            header.find("byte_order=\"LittleEndian\"") == std::string_view::npos ||
            header.find("header_type=\"UInt64\"") == std::string_view::npos)
            fail("not a little-endian UInt64-header VTK PolyData file");
        const auto tagEnd = m_text.find('>', appended);
        if (tagEnd == std::string::npos ||
            std::string_view(m_text).substr(appended, tagEnd - appended).find("encoding=\"raw\"") ==
                std::string_view::npos)
            fail("appended data is not raw binary");
        const auto marker = m_text.find('_', tagEnd);
        if (marker == std::string::npos) fail("no '_' marker in <AppendedData>");
        m_dataStart = marker + 1;

        std::string section;
        forEachTag(header, path, [&](std::string_view name, std::string_view tag) {
            if (name == "DataArray") {
                ArrayInfo a;
                a.section = section;
                std::string comps = "1", offset;
                if (!attribute(tag, "Name", a.name) || !attribute(tag, "type", a.type) ||
                    !attribute(tag, "offset", offset))
                    fail("DataArray without Name, type or offset");
                attribute(tag, "NumberOfComponents", comps);
                a.components = parseNumber<int>(comps, path, "NumberOfComponents");
                a.offset = parseNumber<std::uint64_t>(offset, path, "offset");
                m_arrays.push_back(std::move(a));
            } else if (name == "FieldData" || name == "PointData" || name == "CellData" || name == "Points" ||
                       name == "Verts" || name == "Lines" || name == "Polys") {
                section = std::string(name);
            }
        });
    }

    /// Values of array `name` in `section`; checks the type and the component count.
    template <class T>
    std::vector<T> read(const std::string& section, const std::string& name, const char* type,
                        int components) const {
        const ArrayInfo& a = find(section, name);
        if (a.type != type || a.components != components)
            fail("array " + name + " has type " + a.type + " x" + std::to_string(a.components) +
                 ", expected " + type + " x" + std::to_string(components));
        const std::uint64_t at = m_dataStart + a.offset;
        std::uint64_t bytes = 0;
        if (at + sizeof bytes > m_text.size()) fail("array " + name + " lies past the end of the file");
        std::memcpy(&bytes, m_text.data() + at, sizeof bytes);
        if (bytes > m_text.size() - at - sizeof bytes) fail("array " + name + " is truncated");
        if (bytes % (sizeof(T) * components) != 0) fail("array " + name + " has a partial tuple");
        std::vector<T> v(bytes / sizeof(T));
        if (bytes > 0) std::memcpy(v.data(), m_text.data() + at + sizeof bytes, bytes);  // data() may be null
        return v;
    }

    bool has(const std::string& section, const std::string& name) const {
        for (const ArrayInfo& a : m_arrays)
            if (a.section == section && a.name == name) return true;
        return false;
    }

    [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(m_path + ": " + what); }

private:
    const ArrayInfo& find(const std::string& section, const std::string& name) const {
        for (const ArrayInfo& a : m_arrays)
            if (a.section == section && a.name == name) return a;
        fail("no DataArray \"" + name + "\" in <" + section + ">");
    }

    std::string m_path;
    std::string m_text;
    std::size_t m_dataStart = 0;
    std::vector<ArrayInfo> m_arrays;
};

/// Array `name` if the file has it, else `count` zeros (arrays that older or gas files lack).
template <class T>
std::vector<T> optionalArray(const VtpFile& f, const std::string& section, const std::string& name,
                             const char* type, std::size_t count) {
    return f.has(section, name) ? f.read<T>(section, name, type, 1) : std::vector<T>(count, T{});
}

double readTime(const VtpFile& f) {
    const auto t = f.read<double>("FieldData", "TimeValue", "Float64", 1);
    if (t.size() != 1) f.fail("TimeValue must hold one value");
    return t[0];
}
}  // namespace

ParticleFrame readParticlesVtp(const std::string& path) {
    const VtpFile f(path);
    ParticleFrame frame;
    frame.time = readTime(f);
    const auto points = f.read<double>("Points", "Points", "Float64", 3);
    const std::size_t nPoints = points.size() / 3;
    const auto radius = f.read<double>("PointData", "radius", "Float64", 1);
    const auto speed = f.read<double>("PointData", "speed", "Float64", 1);
    // Smooth hard spheres (edmd snapshots) have no orientation: no angle array, angle 0.
    frame.hasAngle = f.has("PointData", "angle");
    const auto angle = f.has("PointData", "angle") ? f.read<double>("PointData", "angle", "Float64", 1)
                                                   : std::vector<double>(nPoints, 0.0);
    const auto id = f.read<std::int64_t>("PointData", "id", "Int64", 1);
    const auto velocity = f.read<double>("PointData", "velocity", "Float64", 3);
    const auto omega = optionalArray<double>(f, "PointData", "omega", "Float64", nPoints);
    const auto mass = optionalArray<double>(f, "PointData", "mass", "Float64", nPoints);
    const auto material = optionalArray<std::int32_t>(f, "PointData", "material", "Int32", nPoints);
    if (radius.size() != nPoints || speed.size() != nPoints || angle.size() != nPoints ||
        id.size() != nPoints || velocity.size() != 3 * nPoints || omega.size() != nPoints ||
        mass.size() != nPoints || material.size() != nPoints)
        f.fail("point data arrays differ in length from Points");
    // The values of one grain, read at point p (disks) or from the cell data (polygons).
    const auto pushGrain = [&frame](Vec2 c, double r, double sp, double ang, std::int64_t gid, Vec2 v,
                                    double w, double m, std::int32_t mat) {
        frame.x.push_back(c.x);
        frame.y.push_back(c.y);
        frame.radius.push_back(r);
        frame.speed.push_back(sp);
        frame.angle.push_back(ang);
        frame.id.push_back(gid);
        frame.vx.push_back(v.x);
        frame.vy.push_back(v.y);
        frame.omega.push_back(w);
        frame.mass.push_back(m);
        frame.material.push_back(mat);
    };
    const auto pointIndex = [&](std::int64_t p) {
        if (p < 0 || static_cast<std::uint64_t>(p) >= nPoints) f.fail("cell point index out of range");
        return static_cast<std::size_t>(p);
    };

    // Disks: one single-point vertex cell each, values from the point data.
    const auto vertConnectivity = f.read<std::int64_t>("Verts", "connectivity", "Int64", 1);
    const auto vertOffsets = f.read<std::int64_t>("Verts", "offsets", "Int64", 1);
    const std::size_t disks = vertOffsets.size();
    for (std::size_t c = 0; c < disks; ++c) {
        if (vertOffsets[c] != static_cast<std::int64_t>(c + 1) || c >= vertConnectivity.size())
            f.fail("vertex cells must hold one point each");
        const std::size_t p = pointIndex(vertConnectivity[c]);
        pushGrain({points[3 * p], points[3 * p + 1]}, radius[p], speed[p], angle[p], id[p],
                  {velocity[3 * p], velocity[3 * p + 1]}, omega[p], mass[p], material[p]);
        frame.cornerStart.push_back(frame.corners.size());
    }
    if (vertConnectivity.size() != disks) f.fail("vertex cells must hold one point each");
    if (!f.has("Polys", "offsets")) return frame;

    // Polygons: one polygon cell each, values from the cell data (cells: verts, then polys).
    const auto polyConnectivity = f.read<std::int64_t>("Polys", "connectivity", "Int64", 1);
    const auto polyOffsets = f.read<std::int64_t>("Polys", "offsets", "Int64", 1);
    const std::size_t cells = disks + polyOffsets.size();
    const auto position = f.read<double>("CellData", "position", "Float64", 3);
    const auto cellRadius = f.read<double>("CellData", "radius", "Float64", 1);
    const auto cellSpeed = f.read<double>("CellData", "speed", "Float64", 1);
    const auto cellAngle = f.read<double>("CellData", "angle", "Float64", 1);
    const auto cellId = f.read<std::int64_t>("CellData", "id", "Int64", 1);
    const auto cellVelocity = f.read<double>("CellData", "velocity", "Float64", 3);
    const auto cellOmega = optionalArray<double>(f, "CellData", "omega", "Float64", cells);
    const auto cellMass = optionalArray<double>(f, "CellData", "mass", "Float64", cells);
    const auto cellMaterial = optionalArray<std::int32_t>(f, "CellData", "material", "Int32", cells);
    if (position.size() != 3 * cells || cellRadius.size() != cells || cellSpeed.size() != cells ||
        cellAngle.size() != cells || cellId.size() != cells || cellVelocity.size() != 3 * cells ||
        cellOmega.size() != cells || cellMass.size() != cells || cellMaterial.size() != cells)
        f.fail("cell data arrays differ in length from the cell count");
    std::int64_t start = 0;
    for (std::size_t k = 0; k < polyOffsets.size(); ++k) {
        const std::int64_t end = polyOffsets[k];
        if (end - start < 3 || end > static_cast<std::int64_t>(polyConnectivity.size()))
            f.fail("polygon cells must have at least 3 points");
        for (std::int64_t q = start; q < end; ++q) {
            const std::size_t p = pointIndex(polyConnectivity[static_cast<std::size_t>(q)]);
            frame.corners.push_back({points[3 * p], points[3 * p + 1]});
        }
        const std::size_t c = disks + k;
        pushGrain({position[3 * c], position[3 * c + 1]}, cellRadius[c], cellSpeed[c], cellAngle[c],
                  cellId[c], {cellVelocity[3 * c], cellVelocity[3 * c + 1]}, cellOmega[c], cellMass[c],
                  cellMaterial[c]);
        frame.cornerStart.push_back(frame.corners.size());
        start = end;
    }
    if (start != static_cast<std::int64_t>(polyConnectivity.size()))
        f.fail("polygon connectivity has unused entries");
    return frame;
}

WallFrame readWallsVtp(const std::string& path) {
    const VtpFile f(path);
    const auto points = f.read<double>("Points", "Points", "Float64", 3);
    const auto connectivity = f.read<std::int64_t>("Lines", "connectivity", "Int64", 1);
    const auto offsets = f.read<std::int64_t>("Lines", "offsets", "Int64", 1);
    const auto nPoints = static_cast<std::int64_t>(points.size() / 3);
    const auto wall = f.has("CellData", "wall") ? f.read<std::int32_t>("CellData", "wall", "Int32", 1)
                                                : std::vector<std::int32_t>(offsets.size(), 0);
    if (wall.size() != offsets.size()) f.fail("cell data `wall` differs in length from the line count");
    WallFrame frame;
    std::int64_t start = 0;
    for (const std::int64_t end : offsets) {
        if (end - start != 2 || end > static_cast<std::int64_t>(connectivity.size()))
            f.fail("wall cells must be 2-point lines");
        const std::int64_t ia = connectivity[start], ib = connectivity[start + 1];
        if (ia < 0 || ib < 0 || ia >= nPoints || ib >= nPoints) f.fail("line point index out of range");
        frame.a.push_back({points[3 * ia], points[3 * ia + 1]});
        frame.b.push_back({points[3 * ib], points[3 * ib + 1]});
        frame.wall.push_back(wall[frame.wall.size()]);
        start = end;
    }
    return frame;
}

std::vector<PvdEntry> readPvd(const std::string& path) {
    const std::string text = readWholeFile(path);
    if (text.find("type=\"Collection\"") == std::string::npos)
        throw std::runtime_error(path + ": not a VTK Collection (.pvd) file");
    std::vector<PvdEntry> entries;
    forEachTag(text, path, [&](std::string_view name, std::string_view tag) {
        if (name != "DataSet") return;
        PvdEntry e;
        std::string time, part;
        if (!attribute(tag, "timestep", time) || !attribute(tag, "file", e.file) || e.file.empty())
            throw std::runtime_error(path + ": DataSet without timestep or file");
        e.time = parseNumber<double>(time, path, "timestep");
        if (attribute(tag, "part", part) && !part.empty()) e.part = parseNumber<int>(part, path, "part");
        entries.push_back(std::move(e));
    });
    return entries;
}

}  // namespace granulab::io
