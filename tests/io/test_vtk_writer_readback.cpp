// SPDX-License-Identifier: MIT
// The project's own snapshot files (io/vtk_writer) read back with VTK's readers: what ParaView
// sees (point count, arrays, values, walls, the .pvd collection), independent of io/vtk_reader.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUtilities.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support.hpp"
#include "io/flow_field_reader.hpp"
#include "io/vtk_writer.hpp"

namespace granulab::io {
namespace {

namespace fs = std::filesystem;

/// Three disks and a two-segment floor.
struct Scene {
    model::ParticleStore store;
    model::WallSet walls;
    Scene() {
        store.add(7, {0.1, 0.2}, {3.0, -4.0}, 0.25, -1.5, 0.01, 2e-3, 1e-7, 0);
        store.add(8, {0.3, 0.2}, {0.0, 1.0}, 0.0, 2.0, 0.02, 4e-3, 2e-7, 1);
        store.add(9, {0.2, 0.4}, {-1.0, 0.5}, 1.0, 0.0, 0.015, 3e-3, 1.5e-7, 2);
        walls.addPolyline("floor", {{0.0, 0.0}, {0.5, 0.0}, {1.0, 0.1}}, false, 0, {});
    }
};

vtkSmartPointer<vtkPolyData> readVtp(const fs::path& path) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.string().c_str());
    reader->Update();
    EXPECT_EQ(reader->GetErrorCode(), 0) << path;
    return reader->GetOutput();
}

double value(vtkDataArray* a, vtkIdType tuple, int component = 0) {
    return a->GetComponent(tuple, component);
}

TEST(VtkWriterReadback, ParticlesWallsAndCollection) {
    const test::ScratchDir scratch;
    const Scene scene;
    PvdWriter pvd((scratch.path / "snapshots.pvd").string());
    writeSnapshot(scratch.path.string(), 0, scene.store, model::ShapePool{}, scene.walls, 0.0, pvd);
    writeSnapshot(scratch.path.string(), 1, scene.store, model::ShapePool{}, scene.walls, 0.5, pvd);

    const fs::path particles = scratch.path / "vtk" / "particles_000001.vtp";
    vtkSmartPointer<vtkPolyData> p = readVtp(particles);
    ASSERT_EQ(p->GetNumberOfPoints(), 3);
    EXPECT_EQ(p->GetNumberOfVerts(), 3);
    vtkPointData* pd = p->GetPointData();
    for (const char* name : {"id", "radius", "velocity", "speed", "omega", "angle", "mass", "material"})
        ASSERT_NE(pd->GetArray(name), nullptr) << name;
    EXPECT_EQ(pd->GetArray("velocity")->GetNumberOfComponents(), 3);
    const model::ParticleStore& s = scene.store;
    for (vtkIdType i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        double q[3];
        p->GetPoint(i, q);
        EXPECT_EQ(q[0], s.x[k]);
        EXPECT_EQ(q[1], s.y[k]);
        EXPECT_EQ(q[2], 0.0);
        EXPECT_EQ(value(pd->GetArray("id"), i), static_cast<double>(s.id[k]));
        EXPECT_EQ(value(pd->GetArray("radius"), i), s.radius[k]);
        EXPECT_EQ(value(pd->GetArray("velocity"), i, 0), s.vx[k]);
        EXPECT_EQ(value(pd->GetArray("velocity"), i, 1), s.vy[k]);
        EXPECT_EQ(value(pd->GetArray("speed"), i), std::hypot(s.vx[k], s.vy[k]));
        EXPECT_EQ(value(pd->GetArray("omega"), i), s.omega[k]);
        EXPECT_EQ(value(pd->GetArray("angle"), i), s.angle[k]);
        EXPECT_EQ(value(pd->GetArray("mass"), i), s.mass[k]);
        EXPECT_EQ(value(pd->GetArray("material"), i), static_cast<double>(s.material[k]));
    }
    vtkDataArray* time = p->GetFieldData()->GetArray("TimeValue");
    ASSERT_NE(time, nullptr);
    EXPECT_EQ(value(time, 0), 0.5);

    vtkSmartPointer<vtkPolyData> w = readVtp(scratch.path / "vtk" / "walls_000001.vtp");
    EXPECT_EQ(w->GetNumberOfLines(), 2);
    ASSERT_NE(w->GetCellData()->GetArray("wall"), nullptr);
    EXPECT_EQ(value(w->GetCellData()->GetArray("wall"), 1), 0.0);

    // The particle file as a "flow field" (its velocity array at the disk centres), and the .pvd.
    FieldReadOptions velocity;
    velocity.velocityArray = "velocity";
    const fluid::FlowField f = readFlowField(particles.string(), velocity);
    ASSERT_EQ(f.size(), 3u);
    EXPECT_EQ(f.time, 0.5);
    EXPECT_EQ(f.ux[2], s.vx[2]);
    EXPECT_FALSE(f.hasCells());  // vertex cells have fewer than 3 nodes

    const std::vector<FieldFile> entries = listFieldFiles((scratch.path / "snapshots.pvd").string());
    ASSERT_EQ(entries.size(), 4u);
    EXPECT_EQ(entries[2].path, particles.string());
    EXPECT_EQ(entries[2].time, 0.5);
    EXPECT_EQ(fs::path(entries[3].path).filename(), "walls_000001.vtp");

    vtkSmartPointer<vtkXMLDataElement> root;
    root.TakeReference(
        vtkXMLUtilities::ReadElementFromFile((scratch.path / "snapshots.pvd").string().c_str()));
    ASSERT_NE(root, nullptr);
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    ASSERT_NE(collection, nullptr);
    ASSERT_EQ(collection->GetNumberOfNestedElements(), 4);
    EXPECT_STREQ(collection->GetNestedElement(3)->GetAttribute("part"), "1");
    EXPECT_STREQ(collection->GetNestedElement(0)->GetAttribute("file"), "vtk/particles_000000.vtp");
}

// The seed cfddem's particle set (acceleration, angular acceleration, diameter) and the flow at
// the particles: a = F / m and alpha = T / I of the last force evaluation (gravity and fluid
// forces are in F), d = 2 r; the flow arrays only when the scene has a field, NaN outside it.
TEST(VtkWriterReadback, AccelerationsDiameterAndTheFlowAtTheParticles) {
    const test::ScratchDir scratch;
    Scene scene;
    model::ParticleStore& s = scene.store;
    for (std::size_t k = 0; k < 3; ++k) {
        s.fx[k] = 1e-3 * static_cast<double>(k + 1);
        s.fy[k] = -2e-2;
        s.torque[k] = 3e-9 * static_cast<double>(k + 1);
    }
    FluidAtParticles fluid;
    fluid.velocity = {0.5, -0.25, 1.0, 0.0, std::nan(""), std::nan("")};
    fluid.pressure = {10.0, 20.0, std::nan("")};  // the third particle lies outside the mesh
    const fs::path withFlow = scratch.path / "with_flow.vtp";
    writeParticlesVtp(withFlow.string(), s, model::ShapePool{}, 0.25, &fluid);
    vtkSmartPointer<vtkPolyData> p = readVtp(withFlow);
    vtkPointData* pd = p->GetPointData();
    for (const char* name :
         {"acceleration", "angular_acceleration", "diameter", "fluid_velocity", "fluid_pressure"})
        ASSERT_NE(pd->GetArray(name), nullptr) << name;
    EXPECT_EQ(pd->GetArray("acceleration")->GetNumberOfComponents(), 3);
    EXPECT_EQ(pd->GetArray("fluid_velocity")->GetNumberOfComponents(), 3);
    for (vtkIdType i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        EXPECT_EQ(value(pd->GetArray("acceleration"), i, 0), s.fx[k] * s.invMass[k]);
        EXPECT_EQ(value(pd->GetArray("acceleration"), i, 1), s.fy[k] * s.invMass[k]);
        EXPECT_EQ(value(pd->GetArray("acceleration"), i, 2), 0.0);
        EXPECT_DOUBLE_EQ(value(pd->GetArray("acceleration"), i, 0), s.fx[k] / s.mass[k]);
        EXPECT_EQ(value(pd->GetArray("angular_acceleration"), i), s.torque[k] * s.invInertia[k]);
        EXPECT_EQ(value(pd->GetArray("diameter"), i), 2 * s.radius[k]);
    }
    EXPECT_EQ(value(pd->GetArray("fluid_velocity"), 0, 0), 0.5);
    EXPECT_EQ(value(pd->GetArray("fluid_velocity"), 0, 1), -0.25);
    EXPECT_EQ(value(pd->GetArray("fluid_velocity"), 1, 0), 1.0);
    EXPECT_EQ(value(pd->GetArray("fluid_pressure"), 1), 20.0);
    EXPECT_TRUE(std::isnan(value(pd->GetArray("fluid_velocity"), 2, 0)));
    EXPECT_TRUE(std::isnan(value(pd->GetArray("fluid_pressure"), 2)));

    // Without a field: no flow arrays; a flow of the wrong length is refused.
    const fs::path dry = scratch.path / "dry.vtp";
    writeParticlesVtp(dry.string(), s, model::ShapePool{}, 0.25);
    EXPECT_EQ(readVtp(dry)->GetPointData()->GetArray("fluid_velocity"), nullptr);
    fluid.pressure.pop_back();
    EXPECT_THROW(writeParticlesVtp(dry.string(), s, model::ShapePool{}, 0.25, &fluid), std::invalid_argument);
}

}  // namespace
}  // namespace granulab::io
