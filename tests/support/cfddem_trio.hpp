// SPDX-License-Identifier: MIT
// A small set of the cfddem seed's three input files (io/cfddem_files.hpp) for the tests: three
// balls falling into a box whose boundary has wall edges, an outlet edge in the floor and an
// inlet edge at the top that emits 20 balls per second, in still air.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>

namespace granulab::test {

struct CfddemTrio {
    std::string start = R"(Datei mit Startwerten der Partikel
// three balls, one line per key
#RX 0.05 0.10 0.15
#RY 0.20 0.22 0.18
#VX 0 0.1 0
#VY 0 0 -0.2
#PH 0 0 0.5
#OM 0 0 1
#RA 0.01 0.01 0.012
#RH 1000 1000 1000
#EM 1e7 1e7 1e7
#NU 0.3 0.3 0.3
)";
    // Clockwise box: top edge inlet, floor with an outlet between x = 0.08 and 0.12; #PX one value
    // per line.
    std::string boundary = R"(Datei mit Randbedingungen
#PX 0
#PX 0.2
#PX 0.2
#PX 0.12
#PX 0.08
#PX 0
#PY 0.3 0.3 0 0 0 0
#PZ 0 0 0 0 0 0
#PB 3 3 1 2 2 1
#E1 1 2 3 4 5 6
#E2 2 3 4 5 6 1
#EB 3 1 1 2 1 1
#WE 1e8
#WN 0.3
#WM 0.4
// the inlet's balls
#VX 0
#VY -1.5
#PH 0
#OM 0
#RA 0.008
#RH 1000
#EM 1e7
#NU 0.25
)";
    std::string conditions = R"(Datei mit Bedingungen
#PS 20
#DT 2e-5
#TE 0.1
#EP 1e-3
#PK 4
#CO 0.5
#Dn 0.3
#Dt 0.2
#Dr 0.1
#KR 0.001
#RF 1.25
#MU 0.5
#Fg 1
#FA 1
#Fw 1
#FG 0
#FP 1
#FB 1
#SC 250
#SV 2500
#PI 0
)";
    std::string startName = "startvalue.txt";

    /// Writes the three files into `dir` (created).
    void write(const std::filesystem::path& dir) const {
        std::filesystem::create_directories(dir);
        const auto put = [&](const char* name, const std::string& text) {
            std::ofstream out(dir / name);
            out << text;
        };
        put("conditions.txt", conditions);
        put("boundary.txt", boundary);
        std::ofstream(dir / startName) << start;
    }
};

/// `text` with the first occurrence of `from` replaced by `to` (the test fails loudly if absent).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto k = text.find(from);
    if (k == std::string::npos) return "<" + from + " not found>";
    return text.replace(k, from.size(), to);
}

}  // namespace granulab::test
