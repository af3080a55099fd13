// SPDX-License-Identifier: MIT
// VTK XML PolyData writer. Why raw appended binary: exact doubles (restart-grade, no text
// round-off), no base64 and no zlib dependency, and ParaView reads it directly. Layout of the
// appended block: "_" then, per array, a UInt64 byte count followed by the little-endian values;
// each DataArray's `offset` points at its byte count, counted from the first byte after "_".
#include "io/vtk_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "geom/rotation.hpp"
#include "io/atomic_file.hpp"

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

    /// The Points and Lines blocks of a line-set piece, and the end of the piece.
    void pointsAndLines(const std::vector<double>& points, const std::vector<std::int64_t>& connectivity,
                        const std::vector<std::int64_t>& offsets) {
        const std::string in = "        ";
        line("      <Points>");
        array(in, "Float64", "Points", 3, points);
        line("      </Points>");
        line("      <Lines>");
        array(in, "Int64", "connectivity", 1, connectivity);
        array(in, "Int64", "offsets", 1, offsets);
        line("      </Lines>");
        line("    </Piece>");
    }

    void save(const std::string& path) const {
        AtomicFile file(path);
        file.write(
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
            "header_type=\"UInt64\">\n  <PolyData>\n" +
            m_xml + "  </PolyData>\n  <AppendedData encoding=\"raw\">\n_");
        file.write(m_blob);
        file.write("\n  </AppendedData>\n</VTKFile>\n");
        file.commit();
    }

private:
    std::string m_xml;
    std::string m_blob;
};

std::string pieceTag(std::size_t points, std::size_t verts, std::size_t lines, std::size_t polys = 0) {
    return fmt::format(
        "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"{}\" "
        "NumberOfStrips=\"0\" NumberOfPolys=\"{}\">",
        points, verts, lines, polys);
}

/// Per-particle arrays of the particle file, one entry per point or per cell.
struct ParticleArrays {
    std::vector<std::int64_t> id;
    std::vector<double> radius, velocity, speed, omega, angle, mass;
    std::vector<std::int32_t> material;
    std::vector<double> acceleration, angularAcceleration, diameter;
    std::vector<double> fluidVelocity, fluidPressure;  ///< only with a FluidAtParticles

    void reserve(std::size_t n) {
        id.reserve(n);
        radius.reserve(n);
        velocity.reserve(3 * n);
        speed.reserve(n);
        omega.reserve(n);
        angle.reserve(n);
        mass.reserve(n);
        material.reserve(n);
        acceleration.reserve(3 * n);
        angularAcceleration.reserve(n);
        diameter.reserve(n);
    }

    /// Appends particle i of `s`, with `radius` given (0 at polygon corners), and the flow at it
    /// when `fluid` is given.
    void add(const model::ParticleStore& s, std::size_t i, double r, const FluidAtParticles* fluid) {
        id.push_back(static_cast<std::int64_t>(s.id[i]));
        radius.push_back(r);
        velocity.insert(velocity.end(), {s.vx[i], s.vy[i], 0.0});
        speed.push_back(std::hypot(s.vx[i], s.vy[i]));
        omega.push_back(s.omega[i]);
        angle.push_back(s.angle[i]);
        mass.push_back(s.mass[i]);
        material.push_back(static_cast<std::int32_t>(s.material[i]));
        // The force and torque of the last evaluation, so a = F / m of the state written.
        acceleration.insert(acceleration.end(), {s.fx[i] * s.invMass[i], s.fy[i] * s.invMass[i], 0.0});
        angularAcceleration.push_back(s.torque[i] * s.invInertia[i]);
        diameter.push_back(2 * r);
        if (fluid) {
            fluidVelocity.insert(fluidVelocity.end(),
                                 {fluid->velocity[2 * i], fluid->velocity[2 * i + 1], 0.0});
            fluidPressure.push_back(fluid->pressure[i]);
        }
    }

    /// Appends every entry of `other` (the polygon cells after the disk cells).
    void append(const ParticleArrays& other) {
        const auto tail = [](auto& a, const auto& b) { a.insert(a.end(), b.begin(), b.end()); };
        tail(id, other.id);
        tail(radius, other.radius);
        tail(velocity, other.velocity);
        tail(speed, other.speed);
        tail(omega, other.omega);
        tail(angle, other.angle);
        tail(mass, other.mass);
        tail(material, other.material);
        tail(acceleration, other.acceleration);
        tail(angularAcceleration, other.angularAcceleration);
        tail(diameter, other.diameter);
        tail(fluidVelocity, other.fluidVelocity);
        tail(fluidPressure, other.fluidPressure);
    }

    /// The eight arrays of the disk-only format, then the accelerations and the diameter, then the
    /// flow at the particles when there is one.
    void write(VtpBuilder& b, const std::string& in) const {
        b.array(in, "Int64", "id", 1, id);
        b.array(in, "Float64", "radius", 1, radius);
        b.array(in, "Float64", "velocity", 3, velocity);
        b.array(in, "Float64", "speed", 1, speed);
        b.array(in, "Float64", "omega", 1, omega);
        b.array(in, "Float64", "angle", 1, angle);
        b.array(in, "Float64", "mass", 1, mass);
        b.array(in, "Int32", "material", 1, material);
        b.array(in, "Float64", "acceleration", 3, acceleration);
        b.array(in, "Float64", "angular_acceleration", 1, angularAcceleration);
        b.array(in, "Float64", "diameter", 1, diameter);
        if (fluidPressure.size() == id.size() && !id.empty()) {
            b.array(in, "Float64", "fluid_velocity", 3, fluidVelocity);
            b.array(in, "Float64", "fluid_pressure", 1, fluidPressure);
        }
    }
};

/// Writes the particle file; `shapes` == nullptr treats every particle as a disk.
void writeParticles(const std::string& path, const model::ParticleStore& s, const model::ShapePool* shapes,
                    double time, const FluidAtParticles* fluid) {
    const std::size_t n = s.size();
    if (fluid && (fluid->velocity.size() != 2 * n || fluid->pressure.size() != n))
        throw std::invalid_argument(
            fmt::format("the flow at the particles has {} velocities and {} pressures "
                        "for {} particles",
                        fluid->velocity.size() / 2, fluid->pressure.size(), n));
    const auto polygonShape = [&](std::size_t i) -> std::uint32_t {  // kDiskShape for disks
        if (shapes == nullptr || s.shape.size() != n || s.shape[i] == model::kDiskShape)
            return model::kDiskShape;
        if (s.shape[i] >= shapes->size())
            throw std::invalid_argument(fmt::format("{}: particle {} refers to shape {}, the pool holds {}",
                                                    path, s.id[i], s.shape[i], shapes->size()));
        return s.shape[i];
    };
    std::size_t disks = 0, polygons = 0, polyPoints = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t k = polygonShape(i);
        if (k == model::kDiskShape) {
            ++disks;
        } else {
            ++polygons;
            polyPoints += shapes->count[k];
        }
    }
    const std::size_t nPoints = disks + polyPoints;
    std::vector<double> points;
    points.reserve(3 * nPoints);
    ParticleArrays pointData, diskCells, polyCells;
    pointData.reserve(nPoints);
    std::vector<std::int64_t> vertConnectivity, vertOffsets, polyConnectivity, polyOffsets;
    std::vector<double> diskPosition, polyPosition;
    std::vector<std::int32_t> polyCorners;
    vertConnectivity.reserve(disks);
    vertOffsets.reserve(disks);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t k = polygonShape(i);
        const auto first = static_cast<std::int64_t>(points.size() / 3);
        if (k == model::kDiskShape) {
            points.insert(points.end(), {s.x[i], s.y[i], 0.0});
            pointData.add(s, i, s.radius[i], fluid);
            vertConnectivity.push_back(first);
            vertOffsets.push_back(
                static_cast<std::int64_t>(vertConnectivity.size()));  // end offsets (VTK XML 1.0)
            if (polygons > 0) {
                diskCells.add(s, i, s.radius[i], fluid);
                diskPosition.insert(diskPosition.end(), {s.x[i], s.y[i], 0.0});
            }
            continue;
        }
        const auto [cs, sn] = geom::rotationOf(s.angle[i]);  // as the force kernel's corners
        const std::uint32_t count = shapes->count[k];
        for (std::uint32_t c = 0; c < count; ++c) {
            const Vec2 body = shapes->corners[shapes->start[k] + c];
            points.insert(points.end(),
                          {s.x[i] + (cs * body.x - sn * body.y), s.y[i] + (sn * body.x + cs * body.y), 0.0});
            pointData.add(s, i, 0.0, fluid);
            polyConnectivity.push_back(first + c);
        }
        polyOffsets.push_back(static_cast<std::int64_t>(polyConnectivity.size()));
        polyCells.add(s, i, s.radius[i], fluid);
        polyPosition.insert(polyPosition.end(), {s.x[i], s.y[i], 0.0});
        polyCorners.push_back(static_cast<std::int32_t>(count));
    }

    VtpBuilder b;
    b.timeValue(time);
    b.line(pieceTag(nPoints, disks, 0, polygons));
    const std::string in = "        ";
    b.line("      <PointData Scalars=\"speed\" Vectors=\"velocity\">");
    pointData.write(b, in);
    b.line("      </PointData>");
    if (polygons > 0) {  // cell order: verts (disks), then polys
        const auto join = [](auto a, const auto& tail) {
            a.insert(a.end(), tail.begin(), tail.end());
            return a;
        };
        ParticleArrays cells = diskCells;
        cells.append(polyCells);
        std::vector<std::int32_t> kind(disks, 0), corners(disks, 0);
        kind.resize(disks + polygons, 1);
        corners.insert(corners.end(), polyCorners.begin(), polyCorners.end());
        b.line("      <CellData Scalars=\"speed\" Vectors=\"velocity\">");
        cells.write(b, in);
        b.array(in, "Int32", "shape_kind", 1, kind);
        b.array(in, "Int32", "corners", 1, corners);
        b.array(in, "Float64", "position", 3, join(diskPosition, polyPosition));
        b.line("      </CellData>");
    }
    b.line("      <Points>");
    b.array(in, "Float64", "Points", 3, points);
    b.line("      </Points>");
    b.line("      <Verts>");
    b.array(in, "Int64", "connectivity", 1, vertConnectivity);
    b.array(in, "Int64", "offsets", 1, vertOffsets);
    b.line("      </Verts>");
    if (polygons > 0) {
        b.line("      <Polys>");
        b.array(in, "Int64", "connectivity", 1, polyConnectivity);
        b.array(in, "Int64", "offsets", 1, polyOffsets);
        b.line("      </Polys>");
    }
    b.line("    </Piece>");
    b.save(path);
}
}  // namespace

void writeParticlesVtp(const std::string& path, const model::ParticleStore& s, const model::ShapePool& shapes,
                       double time, const FluidAtParticles* fluid) {
    writeParticles(path, s, &shapes, time, fluid);
}

void writeParticlesVtp(const std::string& path, const model::ParticleStore& s, double time) {
    writeParticles(path, s, nullptr, time, nullptr);
}

void writeWallsVtp(const std::string& path, const model::WallSet& w, double time) {
    std::vector<const model::WallSegment*> drawn;  // a wall that is not solid (an opened lid) is gone
    for (const auto& seg : w.segments)
        if (w.walls[seg.wall].solid) drawn.push_back(&seg);
    const std::size_t n = drawn.size();
    std::vector<double> points(6 * n, 0.0);
    std::vector<std::int64_t> connectivity(2 * n), offsets(n);
    std::vector<std::int32_t> wall(n);
    for (std::size_t k = 0; k < n; ++k) {
        const model::WallSegment& seg = *drawn[k];
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
    b.pointsAndLines(points, connectivity, offsets);
    b.save(path);
}

void writeContactsVtp(const std::string& path, const analysis::ContactFrame& c,
                      const std::vector<Vec2>& centreA, const std::vector<Vec2>& centreB, double time) {
    const std::size_t n = c.size();
    if (centreA.size() != n || centreB.size() != n)
        throw std::invalid_argument(
            fmt::format("{}: {} contacts but {} / {} centres", path, n, centreA.size(), centreB.size()));
    std::vector<double> points, force(3 * n, 0.0), normal(3 * n, 0.0), magnitude(n);
    std::vector<std::int64_t> connectivity, offsets(n);
    points.reserve(9 * n);
    connectivity.reserve(3 * n);
    const auto addPoint = [&](Vec2 p) {
        connectivity.push_back(static_cast<std::int64_t>(points.size() / 3));
        points.insert(points.end(), {p.x, p.y, 0.0});
    };
    for (std::size_t k = 0; k < n; ++k) {
        addPoint(centreA[k]);
        addPoint({c.px[k], c.py[k]});
        if (!c.atWall(k)) addPoint(centreB[k]);
        offsets[k] = static_cast<std::int64_t>(connectivity.size());
        force[3 * k] = c.fx[k];
        force[3 * k + 1] = c.fy[k];
        normal[3 * k] = c.nx[k];
        normal[3 * k + 1] = c.ny[k];
        magnitude[k] = std::hypot(c.fx[k], c.fy[k]);
    }
    VtpBuilder b;
    b.timeValue(time);
    b.line(pieceTag(points.size() / 3, 0, n));
    const std::string in = "        ";
    b.line("      <CellData Scalars=\"force_magnitude\" Vectors=\"force\">");
    b.array(in, "Int64", "a", 1, c.a);
    b.array(in, "Int64", "b", 1, c.b);
    b.array(in, "Int32", "wall", 1, c.wall);
    b.array(in, "Float64", "force", 3, force);
    b.array(in, "Float64", "force_magnitude", 1, magnitude);
    b.array(in, "Float64", "fn", 1, c.fn);
    b.array(in, "Float64", "ft", 1, c.ft);
    b.array(in, "Float64", "normal", 3, normal);
    b.array(in, "Float64", "depth", 1, c.depth);
    b.array(in, "Float64", "area", 1, c.area);
    b.array(in, "Float64", "length", 1, c.length);
    b.line("      </CellData>");
    b.pointsAndLines(points, connectivity, offsets);
    b.save(path);
}

void writeGasVtp(const std::string& path, const analysis::PointSet& g, const std::vector<std::uint64_t>& ids,
                 const std::vector<double>& collisions, double time) {
    const std::size_t n = g.size();
    const auto dim = static_cast<std::size_t>(g.dim);
    std::vector<double> points(3 * n, 0.0), velocity(3 * n, 0.0), speed(n);
    std::vector<std::int64_t> connectivity(n), offsets(n), id(n);
    for (std::size_t i = 0; i < n; ++i) {
        double v2 = 0;
        for (std::size_t d = 0; d < dim; ++d) {
            points[3 * i + d] = g.x[dim * i + d];
            velocity[3 * i + d] = g.v[dim * i + d];
            v2 += g.v[dim * i + d] * g.v[dim * i + d];
        }
        speed[i] = std::sqrt(v2);
        connectivity[i] = static_cast<std::int64_t>(i);
        offsets[i] = static_cast<std::int64_t>(i + 1);
        id[i] = static_cast<std::int64_t>(ids[i]);
    }
    VtpBuilder b;
    b.timeValue(time);
    b.line(pieceTag(n, n, 0));
    const std::string in = "        ";
    b.line("      <PointData Scalars=\"collisions\" Vectors=\"velocity\">");
    b.array(in, "Int64", "id", 1, id);
    b.array(in, "Float64", "radius", 1, g.radius);
    b.array(in, "Float64", "velocity", 3, velocity);
    b.array(in, "Float64", "speed", 1, speed);
    b.array(in, "Float64", "collisions", 1, collisions);
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

std::string snapshotFileName(const std::string& stem, int index) {
    return fmt::format("vtk/{}_{:06d}.vtp", stem, index);
}

PvdWriter::PvdWriter(std::string path) : m_path(std::move(path)) {}

void PvdWriter::add(double time, int part, const std::string& relativeFile) {
    m_entries.push_back({time, part, relativeFile});
}

void PvdWriter::write() const {
    std::string text =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n  <Collection>\n";
    for (const PvdEntry& e : m_entries)
        text += "    <DataSet timestep=\"" + exactText(e.time) + "\" group=\"\" part=\"" +
                std::to_string(e.part) + "\" file=\"" + e.file + "\"/>\n";
    text += "  </Collection>\n</VTKFile>\n";
    writeFileAtomically(m_path, text);
}

void PvdWriter::load() {
    m_entries.clear();
    if (!std::filesystem::exists(m_path)) return;
    m_entries = readPvd(m_path);
}

void PvdWriter::truncateAfter(double time) {
    std::erase_if(m_entries, [time](const PvdEntry& e) { return e.time > time; });
}

namespace {
void snapshot(const std::string& outDir, int index, const model::ParticleStore& s,
              const model::ShapePool* shapes, const model::WallSet& w, double time, PvdWriter& pvd,
              const FluidAtParticles* fluid) {
    const std::filesystem::path dir(outDir);
    const std::string particles = snapshotFileName("particles", index);
    const std::string walls = snapshotFileName("walls", index);
    writeParticles((dir / particles).string(), s, shapes, time, fluid);
    writeWallsVtp((dir / walls).string(), w, time);
    pvd.add(time, 0, particles);
    pvd.add(time, 1, walls);
    pvd.write();
}
}  // namespace

void writeSnapshot(const std::string& outDir, int index, const model::ParticleStore& s,
                   const model::ShapePool& shapes, const model::WallSet& w, double time, PvdWriter& pvd,
                   const FluidAtParticles* fluid) {
    snapshot(outDir, index, s, &shapes, w, time, pvd, fluid);
}

}  // namespace granulab::io
