// SPDX-License-Identifier: MIT
// `granulab info` of an event-driven gas scene: the resolved set-up and the kinetic-theory
// scales and thresholds of edmd spec 4.3-4.6.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/edmd/edmd_engine.hpp"
#include "edmd/kinetic_theory.hpp"

namespace granulab::app {

int edmdInfo(const std::string& scenePath, const model::SceneDef& scene) {
    const edmd::Setup s = checkAndResolveEdmd(scene);
    const auto& e = scene.edmd;
    const int D = s.dim;
    fmt::print("scene        {}\n", scenePath);
    if (!scene.run.title.empty()) fmt::print("title        {}\n", scene.run.title);
    fmt::print("engine       edmd ({}D event-driven hard {}), queue {}\n", D, D == 2 ? "disks" : "spheres",
               e.queue);
    fmt::print("particles    {}  radius {} m{}, mass {} kg, placement {}\n", s.init.count, e.radius,
               e.radiusMax > e.radius ? fmt::format(" .. {} m", e.radiusMax) : std::string(), e.mass,
               e.placement);
    fmt::print(
        "box          {}  ({}), volume fraction {:.5f}\n",
        D == 2 ? fmt::format("{:.6g} x {:.6g} m", s.config.box[0], s.config.box[1])
               : fmt::format("{:.6g} x {:.6g} x {:.6g} m", s.config.box[0], s.config.box[1], s.config.box[2]),
        e.periodic.empty() ? "periodic" : "per-axis boundaries as given", s.volumeFraction);
    fmt::print("collisions   eps {} ({}), walls {}, phi {}, TC t_c = {:.4g} s\n", e.restitution,
               e.restitutionModel, e.wallRestitution, e.tangentialRestitution, s.config.tc);
    fmt::print("start        T0 = {} J, elastic pre-run of {} collisions per particle\n", e.temperature,
               e.equilibrate);
    fmt::print("kinetics     t_E = {:.6g} s (Enskog, Eq. 4.33), end t = {:.6g} s{}\n", s.tE, s.endTime,
               s.lambda > 0 && std::isfinite(s.endTime)
                   ? fmt::format(" = tau {:.4g}", s.lambda * s.endTime / (2 * D * s.tE))
                   : std::string());
    const Real nu = std::min(s.volumeFraction, D == 2 ? 0.69 : 0.49);
    const Real lOpt = edmd::opticalDepth(D, static_cast<Real>(s.init.count), nu);
    fmt::print(
        "thresholds   g_2a {:.4f}, l_opt {:.4g}, lambda {:.4g}, lambda_cl {:.4g} (clusters above), lambda_sh "
        "{:.4g}, "
        "eps_ic {:.4f}\n",
        edmd::contactValue(D, nu), lOpt, s.lambda, edmd::clusteringLambda(D, lOpt),
        edmd::shearLambda(D, lOpt), edmd::collapseRestitution(lOpt));
    for (const auto& w : s.warnings) fmt::print("warning      {}\n", w);
    return 0;
}

}  // namespace granulab::app
