// SPDX-License-Identifier: MIT
// Energies of the gas view and the rank-count-independent checkpoint (app/edmd/gas_view.hpp).
#include "app/edmd/gas_view.hpp"

#include <cstring>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>

#include "core/binary_io.hpp"

namespace granulab::app {

namespace {
constexpr char kFormat[8] = {'g', 'a', 's', 'r', 'e', 'c', '0', '1'};  ///< records, version 1
}

template <int D>
GasEnergies gasEnergies(const GasView<D>& view, const edmd::EngineConfig& config) {
    GasEnergies e;
    const bool rough = config.rough();
    bool gravity = false;
    for (int d = 0; d < D; ++d) gravity = gravity || config.gravity[d] != 0;
    for (std::uint32_t i = 0; i < view.size(); ++i) {
        const Real m = view.mass[i];
        e.kinetic += 0.5 * m * dot(view.v[i], view.v[i]);
        if (rough) {
            const Real a = view.radius[i];
            e.rotational += 0.5 * config.inertiaFactor * m * a * a * dot(view.omega[i], view.omega[i]);
        }
        if (gravity)
            for (int d = 0; d < D; ++d) e.potential -= m * config.gravity[d] * view.x[i][d];
        for (int d = 0; d < D; ++d) e.momentum[d] += view.v[i][d] * m;
    }
    return e;
}

template GasEnergies gasEnergies<2>(const GasView<2>&, const edmd::EngineConfig&);
template GasEnergies gasEnergies<3>(const GasView<3>&, const edmd::EngineConfig&);

void writeGasCheckpoint(std::ostream& out, int dimension, const GasCheckpoint& state) {
    out.write(kFormat, sizeof kFormat);
    writePod<std::uint32_t>(out, static_cast<std::uint32_t>(dimension));
    writePod(out, state.globals);
    writePod(out, state.cells);
    writeVector(out, state.records);
}

GasCheckpoint readGasCheckpoint(std::istream& in, int dimension) {
    char format[sizeof kFormat] = {};
    in.read(format, sizeof format);
    if (!in || std::memcmp(format, kFormat, sizeof kFormat) != 0)
        throw std::runtime_error(
            "the checkpoint holds the edmd engine state in the format of an earlier granulab; "
            "run the scene again from the start");
    if (readPod<std::uint32_t>(in) != static_cast<std::uint32_t>(dimension))
        throw std::runtime_error("the checkpoint belongs to a run of another dimension");
    GasCheckpoint state;
    state.globals = readPod<edmd::EngineGlobals>(in);
    state.cells = readPod<std::array<int, 3>>(in);
    readVector(in, state.records);
    for (std::size_t i = 0; i < state.records.size(); ++i)
        if (state.records[i].id != i)
            throw std::runtime_error("the checkpoint's particle records are not the ids 0 .. N-1 in order");
    return state;
}

}  // namespace granulab::app
