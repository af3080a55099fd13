// SPDX-License-Identifier: MIT
// *Def structs of the gas-particle part of the dem engine (cfddem spec sections 5 and 6.5;
// docs/scene-format.md "[fluid]" and "[attraction]"; docs/physics/fluid.md): the imported flow
// field(s), the drag law, buoyancy and pressure-gradient force, and the seed's mutual attraction.
// Filled by io/fluid_sections.cpp.
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace granulab::model {

/// [fluid]: one-way coupling to a gas or liquid whose velocity comes from CFD files (or is uniform).
struct FluidDef {
    bool present = false;
    /// Field files, folders, .pvd or .series collections (relative to the scene file); empty: the
    /// uniform `velocity` everywhere.
    std::vector<std::string> fields;
    std::vector<SourceLoc> fieldLocs;
    /// "auto" (the times the files carry, else even), "even" (cfddem Eq. 4.2: n files spread
    /// evenly over run.end_time) or "file" (the files' times; an error if they carry none)
    std::string timing = "auto";
    bool timeInterpolation = false;  ///< linear in time between neighbouring fields
    /// "all": every file is read once at set-up to check it (bad input: exit status 2 before the
    /// run); "first": only the first (and those without a known time), the others when they are
    /// due (a bad one stops the run with exit status 3, the last checkpoint kept)
    std::string check = "all";
    std::string velocityArray = "U";
    std::string pressureArray = "p";
    std::string data = "auto";           ///< auto (point data, else cell data) | point | cell
    std::string interpolation = "auto";  ///< auto | bilinear | shepard | cell
    std::string outside = "zero";        ///< zero | nearest: the velocity outside the field's domain
    int shepardNodes = 4;                ///< cfddem nop
    Real shepardPower = 2;               ///< cfddem p
    Vec2 velocity;                       ///< [m/s] uniform velocity when `fields` is empty
    Real density = 0;                    ///< [kg/m^3] rho_f (required)
    Real viscosity = 1.8e-5;             ///< [Pa s] dynamic viscosity mu (air at 20 C)
    std::string drag = "quadratic";      ///< none | quadratic | stokes | schiller_naumann | di_felice
    Real cw = 0.47;                      ///< quadratic: drag coefficient c_w (cfddem 5.3)
    bool buoyancy = true;                ///< static buoyancy -rho_f V g (cfddem Eq. 3.63)
    bool pressureGradient = false;       ///< -V grad p from the field's pressure
    std::string pressure =
        "kinematic";  ///< kinematic (p/rho_f [m^2/s^2], incompressible OpenFOAM) | static [Pa]
    Real depth = 0;   ///< [m] di_felice: slab thickness for the voidage (0: the largest diameter)
    Real voidageCell =
        0;  ///< [m] di_felice: edge of the voidage cells (0: max(node spacing, 4 largest diameters))
    Real checkMargin = 0;  ///< [m] how far initial particles and inlets may lie outside the field
    SourceLoc loc;
};

/// [attraction]: Newtonian mutual attraction F = G m1 m2 / d^2 between particle centres (cfddem
/// spec 5.6, a test hook for long-range forces).
struct AttractionDef {
    bool present = false;
    Real constant = 6.674e-11;  ///< [m^3/(kg s^2)] G
    Real cutoff = 0;            ///< [m] pairs farther apart are skipped (0: all pairs)
    SourceLoc loc;
};

}  // namespace granulab::model
