// SPDX-License-Identifier: MIT
// Test helper: a dem scene built in code, without scene text or io/ (docs/architecture.md
// "Tests"): materials, one contact law per material pair, disks and walls, then the engine's own
// set-up (dem::prepareScene: laws, start overlaps, time step) and the World.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "dem/scene_setup.hpp"
#include "dem/setup.hpp"
#include "model/scene_def.hpp"

namespace granulab::test {

class DemSceneBuilder {
public:
    DemSceneBuilder(Real dt, Real endTime) {
        m_scene.path = "<built in code>";
        m_scene.dem.dt = dt;
        m_scene.run.endTime = endTime;
    }
    DemSceneBuilder& gravity(Vec2 g) {
        m_scene.dem.gravity = g;
        return *this;
    }
    DemSceneBuilder& material(const std::string& name, Real density) {
        model::MaterialDef m;
        m.name = name;
        m.density = density;
        m_scene.materials.push_back(m);
        return *this;
    }
    /// A law between materials a and b ("*" matches any); `params` by scene key (kn, e, mu, ...).
    DemSceneBuilder& contact(const std::string& a, const std::string& b, const std::string& normal,
                             const std::string& damping, const std::map<std::string, Real>& params) {
        model::ContactDef c;
        c.materialA = a;
        c.materialB = b;
        c.normal = normal;
        c.damping = damping;
        for (const auto& [key, value] : params) c.params[key].value = value;
        m_scene.contacts.push_back(c);
        return *this;
    }
    DemSceneBuilder& disk(Vec2 position, Vec2 velocity, Real radius, const std::string& material) {
        model::ParticleDef p;
        p.position = position;
        p.velocity = velocity;
        p.radius = radius;
        p.material = material;
        m_scene.particles.push_back(p);
        return *this;
    }
    DemSceneBuilder& wall(const std::vector<Vec2>& points, const std::string& material) {
        model::WallDef w;
        w.points = points;
        w.material = material;
        m_scene.walls.push_back(w);
        return *this;
    }

    const model::SceneDef& scene() const { return m_scene; }

    /// The initialized World (SceneError if the engine's set-up finds a problem).
    dem::World world() const {
        Diagnostics diags;
        const dem::PreparedScene prepared = dem::prepareScene(m_scene, diags);
        dem::World w = dem::makeWorld(m_scene, prepared.initial);
        w.initialize();
        return w;
    }

private:
    model::SceneDef m_scene;
};

}  // namespace granulab::test
