// SPDX-License-Identifier: MIT
// gc2d's contact files (gc2d spec 9.1, 9.4; docs/coming-from-gc2d.md "Restart files"): a gco is
// written beside every gso, and a gci (normally a renamed gco) is read beside the gsi of a restart:
//   PARAMETER v1.4
//   <identification: must equal line 2 of the gsi>
//   COLLISION
//   Particles <id1> <id2>        (gc2d ids, io/gc2d_ids.hpp)
//   Summ_Friction <float>        [N] tangential spring force k_t xi
//   Old_Area <float>             [m^2] overlap area of the last step
//   ...
//   END_OF_FILE
// Keywords are case-insensitive; # lines are comments. Errors carry file:line (exit status 2).
#pragma once
#include <string>
#include <vector>

#include "model/dem_def.hpp"

namespace granulab::io {

struct GciDocument {
    std::string identification;  ///< line 2
    SourceLoc identificationLoc;
    std::vector<model::RememberedContactDef> contacts;
};

/// Parses gci text; throws SceneError with every error (file:line).
GciDocument parseGci(const std::string& text, const std::string& path);

/// The gci beside a gsi scene: foo.gsi, foo.gsi.gz, foo.gsi.pl -> foo.gci (gc2d's naming).
std::string gciPathFor(const std::string& gsiPath);

/// gco text of `contacts` under `identification`; numbers round-trip exact.
std::string gcoText(const std::string& identification,
                    const std::vector<model::RememberedContactDef>& contacts);

}  // namespace granulab::io
