// SPDX-License-Identifier: MIT
// gci/gco contact files (io/gci_file.hpp; gc2d spec 9.4).
#include "io/gci_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "core/ascii_case.hpp"
#include "core/suggest.hpp"
#include "io/gsi_writer.hpp"

namespace granulab::io {

namespace {

std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    std::string w;
    while (in >> w) out.push_back(w);
    return out;
}

bool number(const std::string& w, Real& v) {
    const char* b = w.data() + (!w.empty() && w.front() == '+' ? 1 : 0);
    const auto [end, ec] = std::from_chars(b, w.data() + w.size(), v);
    return ec == std::errc{} && end == w.data() + w.size() && std::isfinite(v);
}

}  // namespace

std::string gciPathFor(const std::string& gsiPath) {
    const std::string lower = asciiLower(gsiPath);
    for (const char* tail : {".gsi.gz", ".gsi.pl", ".gsi.m4", ".gsi"})
        if (lower.ends_with(tail))
            return gsiPath.substr(0, gsiPath.size() - std::string(tail).size()) + ".gci";
    return gsiPath + ".gci";
}

GciDocument parseGci(const std::string& text, const std::string& path) {
    Diagnostics diags;
    GciDocument doc;
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    bool ended = false;
    model::RememberedContactDef* open = nullptr;
    std::vector<bool> seen;  // Particles given, per section
    const std::vector<std::string> keywords = {"COLLISION", "PARTICLES", "SUMM_FRICTION", "OLD_AREA",
                                               "END_OF_FILE"};
    while (!ended && std::getline(in, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const SourceLoc loc{path, lineNo, 1};
        if (lineNo == 1) {
            const auto w = words(line);
            if (w.size() < 2 || asciiUpper(w[0]) != "PARAMETER" || w[1] != "v1.4")
                diags.error(loc, "PARAMETER", "a gci starts with the version line `PARAMETER v1.4`");
            continue;
        }
        if (lineNo == 2) {  // verbatim but for trailing blanks, as the gsi's line 2
            while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.pop_back();
            doc.identification = line;
            doc.identificationLoc = loc;
            continue;
        }
        const auto w = words(line);
        if (w.empty() || w[0].front() == '#' || w[0].front() == '$') continue;
        const std::string key = asciiUpper(w[0]);
        const auto numberAt = [&](std::size_t k, Real& v) {
            if (w.size() > k && number(w[k], v)) return true;
            diags.error(loc, key,
                        fmt::format("{} needs a number here, got '{}'", w[0], w.size() > k ? w[k] : ""));
            return false;
        };
        if (key == "END_OF_FILE") {
            ended = true;
        } else if (key == "COLLISION") {
            doc.contacts.emplace_back();
            open = &doc.contacts.back();
            open->loc = loc;
            seen.push_back(false);
        } else if (!open && (key == "PARTICLES" || key == "SUMM_FRICTION" || key == "OLD_AREA")) {
            diags.error(loc, key, fmt::format("{} belongs to a COLLISION section; start one first", w[0]));
        } else if (key == "PARTICLES") {
            Real a = 0, b = 0;
            if (numberAt(1, a) && numberAt(2, b)) {
                if (a != std::floor(a) || b != std::floor(b) || a < 0 || b < 0 || a > 9e15 || b > 9e15)
                    diags.error(loc, key, "Particles takes two ids, whole numbers >= 0");
                open->id1 = static_cast<std::int64_t>(a);
                open->id2 = static_cast<std::int64_t>(b);
                seen.back() = true;
            }
        } else if (key == "SUMM_FRICTION") {
            numberAt(1, open->friction);
        } else if (key == "OLD_AREA") {
            if (numberAt(1, open->oldArea) && open->oldArea < 0)
                diags.error(
                    loc, key,
                    fmt::format("Old_Area is an area in m^2, allowed [0, inf); got {}", open->oldArea));
        } else {
            diags.error(
                loc, w[0],
                fmt::format("unknown gci keyword '{}'{}; allowed: COLLISION, Particles, Summ_Friction, "
                            "Old_Area, END_OF_FILE",
                            w[0], didYouMean(key, keywords)));
        }
    }
    if (lineNo < 2)
        diags.error({path, 1, 1}, "PARAMETER", "a gci has at least the version and identification lines");
    for (std::size_t k = 0; k < doc.contacts.size(); ++k)
        if (!seen[k])
            diags.error(doc.contacts[k].loc, "COLLISION", "a COLLISION section needs `Particles id1 id2`");
    diags.throwIfAny();
    return doc;
}

std::string gcoText(const std::string& identification,
                    const std::vector<model::RememberedContactDef>& contacts) {
    std::string out = "PARAMETER v1.4\n" + identification + "\n";
    for (const auto& c : contacts)
        out += fmt::format("COLLISION\nParticles {} {}\nSumm_Friction {}\nOld_Area {}\n", c.id1, c.id2,
                           gsiNumber(c.friction), gsiNumber(c.oldArea));
    return out + "END_OF_FILE\n";
}

}  // namespace granulab::io
