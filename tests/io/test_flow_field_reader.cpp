// SPDX-License-Identifier: MIT
// CFD flow-field import (cfddem spec 5.5): io::readFlowField on files written by hand (the Tab. 4.6
// foamToVTK layout) and by VTK's own writers (legacy ASCII / big-endian binary, XML, multiblock),
// its error messages on bad files, and io::listFieldFiles on collections and folders.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSetWriter.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../support.hpp"
#include "io/flow_field_reader.hpp"

namespace granulab::io {
namespace {

namespace fs = std::filesystem;

// The test velocity field U = (a + b x + c y, d + e x y, 0) [m/s] and pressure p = 3 x - y.
constexpr double kA = 0.5, kB = 1.5, kC = -0.75, kD = 0.25, kE = 2.0;
double fieldUx(double x, double y) {
    return kA + kB * x + kC * y;
}
double fieldUy(double x, double y) {
    return kD + kE * x * y;
}
double fieldP(double x, double y) {
    return 3 * x - y;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void writeBytes(const fs::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
}

// ---------------------------------------------------------------------------------------------
// The cfddem Tab. 4.6 layout, by hand: 21 x 21 points in [0, 1]^2 at z = 0 and z = 0.1 (882), 400
// hexahedra, cell data cellID/p/U, point data p/U (U last, as foamToVTK writes it).

int tab46Point(int layer, int i, int j) {
    return layer * 441 + j * 21 + i;
}

/// `timeValue`: a FIELD FieldData block with TimeValue 0.25 before POINTS; `pointTuples`: the tuple
/// count of the point array U (882 in a whole file).
std::string tab46Text(bool timeValue = false, int pointTuples = 882) {
    std::ostringstream s;
    s << std::setprecision(9);
    s << "# vtk DataFile Version 2.0\nnoname\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    if (timeValue) s << "FIELD FieldData 1\nTimeValue 1 1 double\n0.25\n";
    s << "POINTS 882 float\n";
    for (int layer = 0; layer < 2; ++layer)
        for (int j = 0; j <= 20; ++j)
            for (int i = 0; i <= 20; ++i) s << 0.05 * i << ' ' << 0.05 * j << ' ' << 0.1 * layer << '\n';
    s << "CELLS 400 3600\n";
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i) {
            s << 8;
            for (int layer = 0; layer < 2; ++layer)
                s << ' ' << tab46Point(layer, i, j) << ' ' << tab46Point(layer, i + 1, j) << ' '
                  << tab46Point(layer, i + 1, j + 1) << ' ' << tab46Point(layer, i, j + 1);
            s << '\n';
        }
    s << "CELL_TYPES 400\n";
    for (int c = 0; c < 400; ++c) s << "12\n";
    s << "CELL_DATA 400\nFIELD attributes 3\ncellID 1 400 int\n";
    for (int c = 0; c < 400; ++c) s << c << '\n';
    s << "p 1 400 float\n";
    for (int c = 0; c < 400; ++c) s << 0.5 * c << '\n';
    s << "U 3 400 float\n";
    for (int c = 0; c < 400; ++c) s << c << " 0 0\n";
    s << "POINT_DATA 882\nFIELD attributes 2\np 1 882 float\n";
    for (int k = 0; k < 882; ++k) s << fieldP(0.05 * (k % 21), 0.05 * (k % 441 / 21)) << '\n';
    s << "U 3 " << pointTuples << " float\n";
    for (int k = 0; k < pointTuples; ++k) {
        const double x = 0.05 * (k % 21), y = 0.05 * (k % 441 / 21);
        s << fieldUx(x, y) << ' ' << fieldUy(x, y) << " 0\n";
    }
    return s.str();
}

/// Signed area of cell c (> 0: counter-clockwise).
double cellArea(const fluid::FlowField& f, std::size_t c) {
    double twice = 0;
    const std::uint32_t begin = f.cellOffsets[c], end = f.cellOffsets[c + 1];
    for (std::uint32_t k = begin; k < end; ++k) {
        const std::uint32_t a = f.cellNodes[k], b = f.cellNodes[k + 1 < end ? k + 1 : begin];
        twice += f.x[a] * f.y[b] - f.x[b] * f.y[a];
    }
    return 0.5 * twice;
}

/// Every node carries the test field at its (x, y), to `tol`.
void expectTestField(const fluid::FlowField& f, double tol) {
    for (std::size_t k = 0; k < f.size(); ++k) {
        ASSERT_NEAR(f.ux[k], fieldUx(f.x[k], f.y[k]), tol) << "node " << k;
        ASSERT_NEAR(f.uy[k], fieldUy(f.x[k], f.y[k]), tol) << "node " << k;
        if (f.hasPressure()) {
            ASSERT_NEAR(f.p[k], fieldP(f.x[k], f.y[k]), tol) << "node " << k;
        }
    }
}

/// `fn` throws a FieldFileError whose message contains each of `parts`; returns the message.
std::string expectFieldError(const std::function<void()>& fn, const std::vector<std::string>& parts) {
    try {
        fn();
    } catch (const FieldFileError& e) {
        for (const std::string& part : parts)
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
                << "'" << part << "' not in: " << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no FieldFileError";
    return "";
}

FieldReadOptions withPressure() {
    FieldReadOptions o;
    o.readPressure = true;
    return o;
}

// ---------------------------------------------------------------------------------------------
// Datasets built with VTK, carrying the test field as point data U (3 components) and p

void addTestField(vtkDataSet* ds) {
    vtkNew<vtkDoubleArray> u, p;
    u->SetName("U");
    u->SetNumberOfComponents(3);
    u->SetNumberOfTuples(ds->GetNumberOfPoints());
    p->SetName("p");
    p->SetNumberOfTuples(ds->GetNumberOfPoints());
    double q[3];
    for (vtkIdType i = 0; i < ds->GetNumberOfPoints(); ++i) {
        ds->GetPoint(i, q);
        u->SetTuple3(i, fieldUx(q[0], q[1]), fieldUy(q[0], q[1]), 0.0);
        p->SetValue(i, fieldP(q[0], q[1]));
    }
    ds->GetPointData()->AddArray(u);
    ds->GetPointData()->AddArray(p);
}

/// 5 x 4 x 1 points, origin (0.1, -0.2), spacing (0.25, 0.5).
vtkSmartPointer<vtkImageData> makeImage() {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(5, 4, 1);
    image->SetOrigin(0.1, -0.2, 0.0);
    image->SetSpacing(0.25, 0.5, 1.0);
    addTestField(image);
    return image;
}

/// 4 x 3 x nz points of a sheared grid, z = 0.1 k.
vtkSmartPointer<vtkStructuredGrid> makeStructured(int nz) {
    auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
    grid->SetDimensions(4, 3, nz);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 4; ++i) points->InsertNextPoint(0.3 * i + 0.05 * j, 0.2 * j, 0.1 * k);
    grid->SetPoints(points);
    addTestField(grid);
    return grid;
}

/// x {0, 0.1, 0.3, 0.6}, y {0, 0.5, 1}, z {0, 0.02}: 24 points, 12 nodes, depth 0.02.
vtkSmartPointer<vtkRectilinearGrid> makeRectilinear() {
    auto grid = vtkSmartPointer<vtkRectilinearGrid>::New();
    const auto coordinates = [](std::vector<double> values) {
        auto a = vtkSmartPointer<vtkDoubleArray>::New();
        for (double v : values) a->InsertNextValue(v);
        return a;
    };
    grid->SetDimensions(4, 3, 2);
    grid->SetXCoordinates(coordinates({0, 0.1, 0.3, 0.6}));
    grid->SetYCoordinates(coordinates({0, 0.5, 1}));
    grid->SetZCoordinates(coordinates({0, 0.02}));
    addTestField(grid);
    return grid;
}

/// nx x ny quads of side h at z = 0 ((nx + 1)(ny + 1) points, row by row), no arrays.
vtkSmartPointer<vtkUnstructuredGrid> makeQuadMesh(int nx, int ny, double h) {
    auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) points->InsertNextPoint(h * i, h * j, 0.0);
    mesh->SetPoints(points);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const vtkIdType a = j * (nx + 1) + i;
            const vtkIdType ids[4] = {a, a + 1, a + nx + 2, a + nx + 1};
            mesh->InsertNextCell(VTK_QUAD, 4, ids);
        }
    return mesh;
}

template <class Writer>
void writeXml(vtkDataObject* data, const fs::path& path) {
    vtkNew<Writer> w;
    w->SetInputData(data);
    w->SetFileName(path.string().c_str());
    ASSERT_EQ(w->Write(), 1) << path;
}

void writeLegacy(vtkDataSet* data, const fs::path& path, bool binary) {
    vtkNew<vtkDataSetWriter> w;  // binary: big endian, as VTK's legacy format defines it
    w->SetInputData(data);
    w->SetFileName(path.string().c_str());
    if (binary)
        w->SetFileTypeToBinary();
    else
        w->SetFileTypeToASCII();
    ASSERT_EQ(w->Write(), 1) << path;
}

// ---------------------------------------------------------------------------------------------
// 1-2: the Tab. 4.6 layout

TEST(FlowFieldReader, Tab46LegacyAsciiCollapsesTwoLayers) {
    const test::ScratchDir scratch;
    const fs::path file = scratch.path / "case_1.vtk";
    test::writeText(file, tab46Text());
    const fluid::FlowField f = readFlowField(file.string(), withPressure());

    EXPECT_EQ(f.source, file.string());
    EXPECT_TRUE(std::isnan(f.time));
    ASSERT_EQ(f.size(), 441u);
    EXPECT_NEAR(f.depth, 0.1, 1e-7);  // float coordinates
    expectTestField(f, 1e-5);
    ASSERT_EQ(f.cellOffsets.size(), 401u);
    for (std::size_t c = 0; c < 400; ++c) {
        ASSERT_EQ(f.cellOffsets[c + 1] - f.cellOffsets[c], 4u) << "cell " << c;
        EXPECT_NEAR(cellArea(f, c), 0.0025, 1e-8) << "cell " << c;  // counter-clockwise quads
    }
    for (std::size_t k = 0; k < f.size(); ++k) {
        EXPECT_GE(f.x[k], -1e-7);
        EXPECT_LE(f.x[k], 1 + 1e-7);
    }
}

TEST(FlowFieldReader, Tab46TimeValueBeforePoints) {
    const test::ScratchDir scratch;
    const fs::path file = scratch.path / "timed.vtk";
    test::writeText(file, tab46Text(true));
    const fluid::FlowField f = readFlowField(file.string(), {});
    EXPECT_EQ(f.time, 0.25);
    EXPECT_EQ(f.size(), 441u);
    EXPECT_FALSE(f.hasPressure());
    expectTestField(f, 1e-5);
}

// ---------------------------------------------------------------------------------------------
// 3: structured and XML formats

TEST(FlowFieldReader, LegacyStructuredAsciiAndBigEndianBinary) {
    const test::ScratchDir scratch;
    for (const bool binary : {false, true}) {
        SCOPED_TRACE(binary ? "binary" : "ascii");
        const std::string tag = binary ? "_bin" : "_ascii";
        const fs::path points = scratch.path / ("points" + tag + ".vtk");
        const fs::path grid = scratch.path / ("grid" + tag + ".vtk");
        const fs::path rect = scratch.path / ("rect" + tag + ".vtk");
        writeLegacy(makeImage(), points, binary);
        writeLegacy(makeStructured(2), grid, binary);
        writeLegacy(makeRectilinear(), rect, binary);
        EXPECT_NE(slurp(points).find("STRUCTURED_POINTS"), std::string::npos);
        EXPECT_NE(slurp(grid).find("STRUCTURED_GRID"), std::string::npos);
        EXPECT_NE(slurp(rect).find("RECTILINEAR_GRID"), std::string::npos);

        const fluid::FlowField fp = readFlowField(points.string(), withPressure());
        EXPECT_EQ(fp.size(), 20u);
        EXPECT_EQ(fp.depth, 0.0);
        EXPECT_EQ(fp.cellOffsets.size(), 13u);  // 4 x 3 pixels
        expectTestField(fp, 1e-9);

        const fluid::FlowField fg = readFlowField(grid.string(), withPressure());
        EXPECT_EQ(fg.size(), 12u);
        EXPECT_NEAR(fg.depth, 0.1, 1e-12);
        EXPECT_EQ(fg.cellOffsets.size(), 7u);  // 3 x 2 hexahedra -> their bottom quads
        expectTestField(fg, 1e-9);

        const fluid::FlowField fr = readFlowField(rect.string(), withPressure());
        EXPECT_EQ(fr.size(), 12u);
        EXPECT_NEAR(fr.depth, 0.02, 1e-12);
        expectTestField(fr, 1e-9);
    }
}

TEST(FlowFieldReader, XmlFormats) {
    const test::ScratchDir scratch;
    vtkSmartPointer<vtkUnstructuredGrid> quads = makeQuadMesh(4, 3, 0.25);
    addTestField(quads);
    vtkNew<vtkDoubleArray> time;
    time->SetName("TimeValue");
    time->InsertNextValue(1.5);
    quads->GetFieldData()->AddArray(time);
    writeXml<vtkXMLUnstructuredGridWriter>(quads, scratch.path / "f.vtu");
    writeXml<vtkXMLRectilinearGridWriter>(makeRectilinear(), scratch.path / "f.vtr");
    writeXml<vtkXMLStructuredGridWriter>(makeStructured(1), scratch.path / "f.vts");
    writeXml<vtkXMLImageDataWriter>(makeImage(), scratch.path / "f.vti");

    const fluid::FlowField u = readFlowField((scratch.path / "f.vtu").string(), withPressure());
    EXPECT_EQ(u.size(), 20u);
    EXPECT_EQ(u.time, 1.5);
    EXPECT_EQ(u.cellOffsets.size(), 13u);
    for (std::size_t c = 0; c < 12; ++c) EXPECT_NEAR(cellArea(u, c), 0.0625, 1e-12);
    expectTestField(u, 0);  // binary doubles: exact

    const fluid::FlowField r = readFlowField((scratch.path / "f.vtr").string(), withPressure());
    EXPECT_EQ(r.size(), 12u);
    EXPECT_EQ(r.depth, 0.02);
    EXPECT_TRUE(std::isnan(r.time));
    expectTestField(r, 0);

    const fluid::FlowField s = readFlowField((scratch.path / "f.vts").string(), withPressure());
    EXPECT_EQ(s.size(), 12u);
    EXPECT_EQ(s.depth, 0.0);
    expectTestField(s, 0);

    const fluid::FlowField i = readFlowField((scratch.path / "f.vti").string(), withPressure());
    EXPECT_EQ(i.size(), 20u);
    expectTestField(i, 0);
}

/// A boundary patch (2 points, U = 99) that must not be taken for the mesh.
vtkSmartPointer<vtkPolyData> makePatch() {
    auto patch = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1, 0, 0);
    patch->SetPoints(points);
    vtkNew<vtkDoubleArray> u;
    u->SetName("U");
    u->SetNumberOfComponents(3);
    u->InsertNextTuple3(99, 99, 0);
    u->InsertNextTuple3(99, 99, 0);
    patch->GetPointData()->AddArray(u);
    return patch;
}

void setBlock(vtkMultiBlockDataSet* mb, unsigned index, vtkDataObject* block, const char* name) {
    mb->SetBlock(index, block);
    mb->GetMetaData(index)->Set(vtkCompositeDataSet::NAME(), name);
}

TEST(FlowFieldReader, MultiblockTakesInternalBlock) {
    const test::ScratchDir scratch;
    vtkSmartPointer<vtkUnstructuredGrid> internal = makeQuadMesh(3, 3, 0.5);
    addTestField(internal);
    vtkNew<vtkMultiBlockDataSet> boundary;
    setBlock(boundary, 0, makePatch(), "inlet");
    vtkNew<vtkMultiBlockDataSet> root;  // the boundary first: the choice must go by name
    setBlock(root, 0, boundary, "boundary");
    setBlock(root, 1, internal, "internal");
    writeXml<vtkXMLMultiBlockDataWriter>(root, scratch.path / "case.vtm");

    const fluid::FlowField f = readFlowField((scratch.path / "case.vtm").string(), withPressure());
    EXPECT_EQ(f.size(), 16u);
    EXPECT_EQ(f.cellOffsets.size(), 10u);
    expectTestField(f, 0);

    // Without an "internal" block: the first non-empty dataset that has U.
    vtkNew<vtkMultiBlockDataSet> other;
    vtkSmartPointer<vtkUnstructuredGrid> noU = makeQuadMesh(1, 1, 1.0);
    setBlock(other, 0, vtkSmartPointer<vtkPolyData>::New(), "empty");
    setBlock(other, 1, noU, "walls");
    setBlock(other, 2, internal, "fluid");
    writeXml<vtkXMLMultiBlockDataWriter>(other, scratch.path / "other.vtm");
    EXPECT_EQ(readFlowField((scratch.path / "other.vtm").string(), {}).size(), 16u);
}

// ---------------------------------------------------------------------------------------------
// 4: velocity only as cell data

TEST(FlowFieldReader, CellDataIsAveragedToNodes) {
    const test::ScratchDir scratch;
    vtkSmartPointer<vtkUnstructuredGrid> mesh = makeQuadMesh(3, 3, 0.1);
    vtkNew<vtkDoubleArray> u;
    u->SetName("U");
    u->SetNumberOfComponents(2);
    for (int c = 0; c < 9; ++c) u->InsertNextTuple2(c, 2.0 * c);
    mesh->GetCellData()->AddArray(u);
    const fs::path file = scratch.path / "cells.vtk";
    vtkNew<vtkUnstructuredGridWriter> w;
    w->SetInputData(mesh);
    w->SetFileName(file.string().c_str());
    w->SetFileTypeToBinary();
    ASSERT_EQ(w->Write(), 1);

    const fluid::FlowField f = readFlowField(file.string(), {});
    ASSERT_EQ(f.size(), 16u);
    std::size_t interior = f.size();  // the node at (0.1, 0.1): cells 0, 1, 3, 4 around it
    for (std::size_t k = 0; k < f.size(); ++k)
        if (std::abs(f.x[k] - 0.1) < 1e-12 && std::abs(f.y[k] - 0.1) < 1e-12) interior = k;
    ASSERT_LT(interior, f.size());
    EXPECT_DOUBLE_EQ(f.ux[interior], (0 + 1 + 3 + 4) / 4.0);
    EXPECT_DOUBLE_EQ(f.uy[interior], 2 * (0 + 1 + 3 + 4) / 4.0);

    FieldReadOptions cell;
    cell.data = "cell";
    EXPECT_EQ(readFlowField(file.string(), cell).ux[interior], f.ux[interior]);
    FieldReadOptions point;
    point.data = "point";
    expectFieldError([&] { readFlowField(file.string(), point); }, {file.string(), "'U'", "cell arrays: U"});
}

// ---------------------------------------------------------------------------------------------
// 5: errors

TEST(FlowFieldReader, MissingFileAndArrays) {
    const test::ScratchDir scratch;
    const fs::path missing = scratch.path / "nothing_here.vtk";
    expectFieldError([&] { readFlowField(missing.string(), {}); }, {missing.string()});

    const fs::path file = scratch.path / "tab.vtk";
    test::writeText(file, tab46Text());
    FieldReadOptions v;
    v.velocityArray = "V";
    expectFieldError([&] { readFlowField(file.string(), v); },
                     {file.string(), "'V'", "point arrays: p, U", "cell arrays: cellID, p, U"});
    FieldReadOptions k = withPressure();
    k.pressureArray = "k";
    expectFieldError([&] { readFlowField(file.string(), k); }, {file.string(), "'k'"});
    FieldReadOptions pAsVelocity;
    pAsVelocity.velocityArray = "p";  // one component
    expectFieldError([&] { readFlowField(file.string(), pAsVelocity); }, {file.string(), "'p'", "component"});

    const fs::path shortU = scratch.path / "short.vtk";  // 800 tuples of U for 882 points
    test::writeText(shortU, tab46Text(false, 800));
    expectFieldError([&] { readFlowField(shortU.string(), {}); }, {shortU.string()});

    const fs::path unknown = scratch.path / "field.csv";
    test::writeText(unknown, "x,y\n");
    expectFieldError([&] { readFlowField(unknown.string(), {}); }, {unknown.string(), ".csv"});
}

TEST(FlowFieldReader, TruncatedFilesFail) {
    const test::ScratchDir scratch;
    const std::string ascii = tab46Text();
    for (const double fraction : {0.02, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
        const fs::path cut =
            scratch.path / ("cut_" + std::to_string(static_cast<int>(fraction * 100)) + ".vtk");
        writeBytes(cut,
                   ascii.substr(0, static_cast<std::size_t>(fraction * static_cast<double>(ascii.size()))));
        SCOPED_TRACE(cut.string());
        const std::string msg = expectFieldError([&] { readFlowField(cut.string(), {}); }, {cut.string()});
        // Cut inside the point arrays, VTK only warns and keeps the declared size: still an error.
        if (fraction >= 0.9) {
            EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
        }
    }

    vtkSmartPointer<vtkUnstructuredGrid> mesh = makeQuadMesh(30, 30, 0.01);
    addTestField(mesh);
    const fs::path binary = scratch.path / "binary.vtk";
    writeLegacy(mesh, binary, true);
    writeXml<vtkXMLUnstructuredGridWriter>(mesh, scratch.path / "whole.vtu");
    const std::string bin = slurp(binary), xml = slurp(scratch.path / "whole.vtu");
    for (const double fraction : {0.1, 0.5, 0.95}) {
        const std::string tag = std::to_string(static_cast<int>(fraction * 100));
        const fs::path cutBin = scratch.path / ("cut_bin_" + tag + ".vtk");
        const fs::path cutXml = scratch.path / ("cut_xml_" + tag + ".vtu");
        writeBytes(cutBin,
                   bin.substr(0, static_cast<std::size_t>(fraction * static_cast<double>(bin.size()))));
        writeBytes(cutXml,
                   xml.substr(0, static_cast<std::size_t>(fraction * static_cast<double>(xml.size()))));
        expectFieldError([&] { readFlowField(cutBin.string(), {}); }, {cutBin.string()});
        expectFieldError([&] { readFlowField(cutXml.string(), {}); }, {cutXml.string()});
    }
    EXPECT_EQ(readFlowField(binary.string(), {}).size(), 961u);  // the uncut files are fine
    EXPECT_EQ(readFlowField((scratch.path / "whole.vtu").string(), {}).size(), 961u);
}

TEST(FlowFieldReader, GarbageFilesFail) {
    const test::ScratchDir scratch;
    std::mt19937 rng(12345);
    std::string bytes(8192, '\0');
    for (char& c : bytes) c = static_cast<char>(rng() & 0xff);
    for (const char* name : {"garbage.vtk", "garbage.vtu", "garbage.vtm", "garbage.vtr"}) {
        writeBytes(scratch.path / name, bytes);
        const std::string path = (scratch.path / name).string();
        expectFieldError([&] { readFlowField(path, {}); }, {path});
    }
    const fs::path text = scratch.path / "text.vtk";
    test::writeText(text, "hello, this is not VTK\n");
    expectFieldError([&] { readFlowField(text.string(), {}); }, {text.string()});
    const fs::path header = scratch.path / "header_only.vtk";  // a valid header and nothing else
    test::writeText(header, "# vtk DataFile Version 2.0\nnoname\nASCII\nDATASET UNSTRUCTURED_GRID\n");
    expectFieldError([&] { readFlowField(header.string(), {}); }, {header.string()});
}

TEST(FlowFieldReader, NonFiniteValuesNamed) {
    const test::ScratchDir scratch;
    vtkSmartPointer<vtkUnstructuredGrid> mesh = makeQuadMesh(3, 3, 0.5);
    addTestField(mesh);
    vtkDataArray* u = mesh->GetPointData()->GetArray("U");
    u->SetComponent(5, 1, std::numeric_limits<double>::quiet_NaN());  // point 5 at (0.5, 0.5)
    const fs::path nanFile = scratch.path / "nan.vtu";
    writeXml<vtkXMLUnstructuredGridWriter>(mesh, nanFile);
    expectFieldError([&] { readFlowField(nanFile.string(), {}); },
                     {nanFile.string(), "'U'", "node 5", "x = 0.5", "y = 0.5"});

    u->SetComponent(5, 1, 0.0);
    mesh->GetPointData()->GetArray("p")->SetComponent(7, 0, std::numeric_limits<double>::infinity());
    const fs::path infFile = scratch.path / "inf.vtu";
    writeXml<vtkXMLUnstructuredGridWriter>(mesh, infFile);
    EXPECT_EQ(readFlowField(infFile.string(), {}).size(), 16u);  // p not asked for
    expectFieldError([&] { readFlowField(infFile.string(), withPressure()); },
                     {infFile.string(), "'p'", "node 7"});
}

TEST(FlowFieldReader, ThreeZLevelsIsA3DField) {
    const test::ScratchDir scratch;
    const fs::path file = scratch.path / "deep.vts";
    writeXml<vtkXMLStructuredGridWriter>(makeStructured(3), file);
    expectFieldError([&] { readFlowField(file.string(), {}); }, {file.string(), "3 z levels", "2D"});
}

// ---------------------------------------------------------------------------------------------
// 6: listFieldFiles

void touch(const fs::path& p) {
    test::writeText(p, "");
}

TEST(FlowFieldReader, ListPvdAndSeries) {
    const test::ScratchDir scratch;
    fs::create_directories(scratch.path / "data");
    for (const char* name : {"a_0.vtu", "a_1.vtu", "a_2.vtu"}) touch(scratch.path / "data" / name);
    const fs::path pvd = scratch.path / "run.pvd";
    test::writeText(pvd,
                    "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n"
                    "  <DataSet timestep=\"0\" part=\"0\" file=\"data/a_0.vtu\"/>\n"
                    "  <DataSet timestep=\"0.5\" part=\"0\" file=\"data/a_1.vtu\"/>\n"
                    "  <DataSet timestep=\"1.25\" part=\"0\" file=\"data/a_2.vtu\"/>\n"
                    "</Collection>\n</VTKFile>\n");
    const std::vector<FieldFile> fromPvd = listFieldFiles(pvd.string());
    ASSERT_EQ(fromPvd.size(), 3u);
    EXPECT_EQ(fromPvd[1].path, (scratch.path / "data" / "a_1.vtu").string());
    EXPECT_EQ(fromPvd[1].time, 0.5);
    EXPECT_EQ(fromPvd[2].time, 1.25);

    const fs::path series = scratch.path / "data" / "a.vtu.series";
    test::writeText(series,
                    "{\"file-series-version\": \"1.0\", \"files\": [{\"name\": \"a_0.vtu\", \"time\": 0},"
                    " {\"name\": \"a_2.vtu\", \"time\": 2.5}]}");
    const std::vector<FieldFile> fromSeries = listFieldFiles(series.string());
    ASSERT_EQ(fromSeries.size(), 2u);
    EXPECT_EQ(fromSeries[1].path, (scratch.path / "data" / "a_2.vtu").string());
    EXPECT_EQ(fromSeries[1].time, 2.5);

    // A folder with one collection in it lists that collection.
    const std::vector<FieldFile> fromFolder = listFieldFiles((scratch.path / "data").string());
    ASSERT_EQ(fromFolder.size(), 2u);
    EXPECT_EQ(fromFolder[1].time, 2.5);

    // Malformed collections and missing listed files.
    const fs::path badPvd = scratch.path / "bad.pvd";
    test::writeText(badPvd, "<VTKFile type=\"Collection\"><Collection><DataSet file=\"x");
    expectFieldError([&] { listFieldFiles(badPvd.string()); }, {badPvd.string()});
    const fs::path badTime = scratch.path / "badtime.pvd";
    test::writeText(
        badTime,
        "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"x1\" file=\"data/a_0.vtu\"/>"
        "</Collection></VTKFile>");
    expectFieldError([&] { listFieldFiles(badTime.string()); }, {badTime.string(), "x1"});
    const fs::path gone = scratch.path / "gone.pvd";
    test::writeText(
        gone,
        "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"0\" file=\"data/none.vtu\"/>"
        "</Collection></VTKFile>");
    expectFieldError([&] { listFieldFiles(gone.string()); }, {gone.string(), "none.vtu"});
    const fs::path badSeries = scratch.path / "bad.series";
    test::writeText(badSeries, "{\"files\": [{\"time\": 1}]}");
    expectFieldError([&] { listFieldFiles(badSeries.string()); }, {badSeries.string()});
    test::writeText(badSeries, "{\"files\": [");
    expectFieldError([&] { listFieldFiles(badSeries.string()); }, {badSeries.string()});
}

TEST(FlowFieldReader, ListFolderSortsNumerically) {
    const test::ScratchDir scratch;
    for (const char* name : {"case_10.vtk", "case_2.vtk", "case_0.vtk", "notes.txt"})
        touch(scratch.path / name);
    const std::vector<FieldFile> files = listFieldFiles(scratch.path.string());
    ASSERT_EQ(files.size(), 3u);
    EXPECT_EQ(fs::path(files[0].path).filename(), "case_0.vtk");
    EXPECT_EQ(fs::path(files[1].path).filename(), "case_2.vtk");
    EXPECT_EQ(fs::path(files[2].path).filename(), "case_10.vtk");
    for (const FieldFile& f : files) EXPECT_TRUE(std::isnan(f.time));

    const std::vector<FieldFile> one = listFieldFiles((scratch.path / "case_2.vtk").string());
    ASSERT_EQ(one.size(), 1u);
    EXPECT_TRUE(std::isnan(one[0].time));

    const fs::path missing = scratch.path / "no_such_case";
    expectFieldError([&] { listFieldFiles(missing.string()); }, {missing.string()});
    fs::create_directories(scratch.path / "empty");
    expectFieldError([&] { listFieldFiles((scratch.path / "empty").string()); }, {"empty"});
}

}  // namespace
}  // namespace granulab::io
