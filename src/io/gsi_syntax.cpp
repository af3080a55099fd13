// SPDX-License-Identifier: MIT
// gsi syntax (io/gsi_syntax.hpp; gc2d spec 9.2-9.3): lines -> objects -> typed keyword entries.
#include "io/gsi_syntax.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <span>

#include "core/ascii_case.hpp"
#include "core/suggest.hpp"

namespace granulab::io {

namespace {

constexpr std::size_t kMaxLineLength = 1023;  ///< gc2d's line buffer, without the newline
constexpr std::string_view kVersion = "V1.4";

/// How a keyword's parameters are read.
enum class Param {
    Flag,     ///< none (POSITION_ABSOLUT)
    Number,   ///< `count` numbers, missing ones 0
    Whole,    ///< `count` whole numbers (steps, ids, counts)
    Text,     ///< one string, case kept (BASENAME, EMAIL)
    Choice,   ///< one word of `choices`, case-insensitive
    Corners,  ///< a CORNERS ... END block
    Gravity,  ///< G: one number, or two (variable g)
};

struct KeywordSpec {
    std::string_view name;
    Param param;
    int count = 0;
    std::span<const std::string_view> choices = {};
};

constexpr std::string_view kDistribution[] = {"CONST", "EQUAL", "GAUSS"};
constexpr std::string_view kCornerPlacement[] = {"SPECIAL_RECTANGLE", "REGULAR", "RAND1", "RAND2", "FULL"};
constexpr std::string_view kGravityType[] = {"CONSTANT", "LINEAR", "STEP", "SMOOTH_STEP"};
constexpr std::string_view kVibrationType[] = {"COSINUS", "SAWTOOTH", "TAPPING", "TRIANGLE"};
constexpr std::string_view kGridType[] = {"RECT", "RECT_GAUSS", "RECT_EQUAL",
                                          "FCC",  "FCC_GAUSS",  "FCC_EQUAL"};
constexpr std::string_view kSourceType[] = {"ABS", "REL"};

// gc2d spec 9.3, object by object.
const KeywordSpec kGeneral[] = {
    {"DELTA_T", Param::Number, 1},
    {"TIME", Param::Number, 2},
    {"MUE_STATISCH", Param::Number, 1},
    {"MUE_DYNAMISCH", Param::Number, 1},
    {"E_MODUL", Param::Number, 1},
    {"GAMMA", Param::Number, 1},
    {"COHESION", Param::Number, 1},
    {"STEPS_DATA", Param::Whole, 1},
    {"STEPS_CHECKPOINT", Param::Whole, 1},
    {"STEPS_SETUP", Param::Whole, 1},
    {"STEPS_DUMPLINE", Param::Whole, 1},
    {"SEED", Param::Number, 2},
    {"BASENAME", Param::Text, 1},
    {"EMAIL", Param::Text, 1},
    {"NEXT_DATA_FILENUMBER", Param::Whole, 1},
    {"NEXT_SETUP_FILENUMBER", Param::Whole, 1},
    {"G", Param::Gravity, 2},
    {"G_TIME", Param::Number, 2},
    {"G_PARAMETER", Param::Number, 2},
    {"G_TYPE", Param::Choice, 1, kGravityType},
    {"HEAT_TIME", Param::Number, 2},
    {"HEAT_AMPLITUDE", Param::Number, 1},
    {"HEAT_FREQUENCE", Param::Number, 1},
    {"HEAT_SLOPE", Param::Number, 1},
};
const KeywordSpec kDisplay[] = {
    {"X_RANGE", Param::Number, 2}, {"Y_RANGE", Param::Number, 2}, {"SCREEN", Param::Number, 2},
    {"INTERVAL", Param::Whole, 1}, {"MODUS", Param::Whole, 1},
};
const KeywordSpec kParticle[] = {
    {"CORNERS", Param::Corners, 0},
    {"COM", Param::Number, 2},
    {"POSITION_ABSOLUT", Param::Flag, 0},
    {"ANGLE", Param::Number, 1},
    {"OMEGA", Param::Number, 1},
    {"OMEGA_DOT", Param::Number, 1},
    {"VELOCITY", Param::Number, 2},
    {"ACCELERATION", Param::Number, 2},
    {"PC_TRANS3", Param::Number, 2},
    {"PC_TRANS4", Param::Number, 2},
    {"PC_TRANS5", Param::Number, 2},
    {"PC_ROT3", Param::Number, 1},
    {"PC_ROT4", Param::Number, 1},
    {"PC_ROT5", Param::Number, 1},
    {"ID", Param::Whole, 1},
    {"DRAG_ANGLE", Param::Number, 1},
    {"DRAG_VELOCITY", Param::Number, 1},
    {"DRAG_K", Param::Number, 1},
    {"DRAG_TIME", Param::Number, 2},
    {"DRAG_FIXING_POINT", Param::Number, 2},
    {"DRAG_PULLING_POINT", Param::Number, 2},
};
const KeywordSpec kWall[] = {
    {"CORNERS", Param::Corners, 0},
    {"OFFSET", Param::Number, 2},
    {"ANGLE", Param::Number, 1},
    {"VELOCITY", Param::Number, 2},
    {"ID", Param::Whole, 1},
    {"PISTON_ANGLE", Param::Number, 1},
    {"PISTON_FORCE", Param::Number, 1},
    {"PISTON_V_MAX", Param::Number, 1},
    {"VIB_ANGLE", Param::Number, 1},
    {"VIB_TIME", Param::Number, 2},
    {"VIB_WIDTH", Param::Number, 1},
    {"VIB_FREQUENCE", Param::Number, 1},
    {"VIB_TYPE", Param::Choice, 1, kVibrationType},
};
// The shape of generated grains, shared by GENERATE_BLOCK and DROPSOURCE.
const KeywordSpec kGrainShape[] = {
    {"PART_SIZE", Param::Number, 2},
    {"PART_VAR_SIZE", Param::Number, 1},
    {"RANDOM_SIZE", Param::Choice, 1, kDistribution},
    {"PART_NUM_CORNERS", Param::Whole, 1},
    {"PART_VAR_CORNERS", Param::Whole, 1},
    {"RANDOM_NUM_CORNERS", Param::Choice, 1, kDistribution},
    {"PART_RANDOM_POS_CORNERS", Param::Choice, 1, kCornerPlacement},
    {"PART_ROT", Param::Number, 1},
    {"RANDOM_ROT", Param::Choice, 1, kDistribution},
};
const KeywordSpec kGenerateBlock[] = {
    {"X_RANGE", Param::Number, 2},       {"Y_RANGE", Param::Number, 2},
    {"GRID_DISTANCE", Param::Number, 2}, {"GRID_TYPE", Param::Choice, 1, kGridType},
    {"ANGLE_RANGE", Param::Number, 2},   {"VELOCITY_RANGE", Param::Number, 2},
};
const KeywordSpec kDropSource[] = {
    {"POS", Param::Number, 2},  {"WIDTH", Param::Number, 1},   {"TYPE", Param::Choice, 1, kSourceType},
    {"TIME", Param::Number, 2}, {"DELTA_T", Param::Number, 1},
};

struct Alias {
    std::string_view written, canonical;
};
constexpr Alias kAliases[] = {
    {"RANDOM_POS_CORNERS", "PART_RANDOM_POS_CORNERS"},
    {"PART_RANDOM_NUM_CORNERS", "RANDOM_NUM_CORNERS"},
};

struct ObjectSpec {
    GsiObjectKind kind;
    std::string_view name;
    std::span<const KeywordSpec> own;
    std::span<const KeywordSpec> shape;  ///< kGrainShape for the grain generators, else empty

    const KeywordSpec* find(std::string_view key) const noexcept {
        for (const auto part : {own, shape})
            for (const KeywordSpec& k : part)
                if (k.name == key) return &k;
        return nullptr;
    }
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto part : {own, shape})
            for (const KeywordSpec& k : part) out.emplace_back(k.name);
        return out;
    }
};
const std::array<ObjectSpec, 6> kObjects = {{
    {GsiObjectKind::General, "GENERAL", kGeneral, {}},
    {GsiObjectKind::Display, "DISPLAY", kDisplay, {}},
    {GsiObjectKind::Particle, "PARTICLE", kParticle, {}},
    {GsiObjectKind::Wall, "WALL", kWall, {}},
    {GsiObjectKind::GenerateBlock, "GENERATE_BLOCK", kGenerateBlock, kGrainShape},
    {GsiObjectKind::DropSource, "DROPSOURCE", kDropSource, kGrainShape},
}};

const ObjectSpec& specOf(GsiObjectKind kind) noexcept {
    return kObjects[static_cast<std::size_t>(kind)];
}

/// Blank-separated words of a line (spaces and tabs).
std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t k = 0;
    while (k < line.size()) {
        while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) ++k;
        const std::size_t start = k;
        while (k < line.size() && line[k] != ' ' && line[k] != '\t') ++k;
        if (k > start) out.push_back(line.substr(start, k - start));
    }
    return out;
}

/// A number as gc2d's scanf reads one (a leading + allowed); nullopt if the word is none.
std::optional<Real> number(std::string_view w) {
    if (!w.empty() && w.front() == '+') w.remove_prefix(1);
    Real v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc{} || end != w.data() + w.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::string_view trimRight(std::string_view s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

class Parser {
public:
    Parser(std::string_view text, const std::string& path) : m_path(path) {
        std::size_t at = 0;
        while (at <= text.size()) {
            const std::size_t nl = text.find('\n', at);
            const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
            m_lines.push_back(text.substr(at, end - at));
            if (nl == std::string_view::npos) break;
            at = nl + 1;
        }
        m_doc.path = path;
    }

    GsiDocument run() {
        header();
        GsiObject general;
        general.kind = GsiObjectKind::General;
        general.loc = loc(2);  // line 3: the first after the identification
        m_doc.objects.push_back(std::move(general));
        for (m_next = 2; m_next < m_lines.size();) {
            const std::size_t index = m_next++;
            const std::string_view raw = trimRight(m_lines[index]);
            if (tooLong(index)) continue;
            const auto w = words(raw);
            if (w.empty() || w.front().front() == '#') continue;
            if (w.front().front() == '$') {
                const std::string_view t = raw.substr(raw.find('$') + 1);
                m_doc.echoes.emplace_back(t.substr(std::min(t.find_first_not_of(" \t"), t.size())));
                continue;
            }
            const std::string key = asciiUpper(w.front());
            if (key == "END_OF_FILE") break;
            if (startsObject(key, index)) continue;
            entry(key, w, index);
        }
        m_diags.throwIfAny();
        return std::move(m_doc);
    }

private:
    SourceLoc loc(std::size_t index) const { return {m_path, static_cast<int>(index) + 1, 0}; }

    bool tooLong(std::size_t index) {
        const std::size_t n = trimRight(m_lines[index]).size();
        if (n <= kMaxLineLength) return false;
        m_diags.error(loc(index), "line",
                      fmt::format("{} characters: a gsi line holds at most {}", n, kMaxLineLength));
        return true;
    }

    void header() {
        const std::string_view first = m_lines.empty() ? std::string_view{} : trimRight(m_lines[0]);
        const auto w = words(first);
        if (w.size() < 2 || asciiUpper(w[0]) != "PARAMETER" || asciiUpper(w[1]) != kVersion)
            m_diags.error(loc(0), "PARAMETER",
                          fmt::format("the first line of a gsi file is 'PARAMETER v1.4' (the version check); "
                                      "found '{}'",
                                      first.substr(0, 80)));
        if (m_lines.size() > 1) {
            tooLong(1);
            std::string_view id = trimRight(m_lines[1]);
            m_doc.identification = std::string(id);
        }
    }

    bool startsObject(const std::string& key, std::size_t index) {
        for (const ObjectSpec& o : kObjects) {
            if (key != o.name) continue;
            if (o.kind == GsiObjectKind::General) {
                if (m_doc.objects.size() > 1)
                    m_diags.error(loc(index), "GENERAL",
                                  fmt::format("GENERAL cannot be entered again (the general section ends at "
                                              "the first object, line {}): move these keywords before it",
                                              m_doc.objects[1].loc.line));
                return true;  // GENERAL at the start: the implicit section, named
            }
            GsiObject obj;
            obj.kind = o.kind;
            obj.loc = loc(index);
            m_doc.objects.push_back(std::move(obj));
            return true;
        }
        return false;
    }

    void entry(std::string key, const std::vector<std::string_view>& w, std::size_t index) {
        GsiObject& obj = m_doc.objects.back();
        const ObjectSpec& o = specOf(obj.kind);
        for (const Alias& a : kAliases)
            if (key == a.written) key = std::string(a.canonical);
        const KeywordSpec* spec = o.find(key);
        if (!spec) {
            std::vector<std::string> candidates = o.names();
            for (const ObjectSpec& other : kObjects) candidates.emplace_back(other.name);
            candidates.emplace_back("END_OF_FILE");
            m_diags.error(
                loc(index), std::string(w.front()),
                fmt::format("unknown keyword '{}' in {}{}", w.front(), o.name, didYouMean(key, candidates)));
            if (key == "CORNERS") skipBlock();
            return;
        }
        GsiEntry e;
        e.keyword = key;
        e.loc = loc(index);
        switch (spec->param) {
            case Param::Flag:
                break;
            case Param::Number:
            case Param::Whole:
            case Param::Gravity:
                numbers(*spec, w, e);
                break;
            case Param::Text:
                if (w.size() < 2)
                    m_diags.error(e.loc, key, fmt::format("{} needs a value", key));
                else
                    e.text = std::string(w[1]);
                break;
            case Param::Choice: {
                std::vector<std::string> allowed(spec->choices.begin(), spec->choices.end());
                e.text = w.size() > 1 ? asciiUpper(w[1]) : "";
                if (std::find(allowed.begin(), allowed.end(), e.text) == allowed.end())
                    m_diags.error(e.loc, key,
                                  fmt::format("'{}' is not allowed{}; allowed: {}", w.size() > 1 ? w[1] : "",
                                              didYouMean(e.text, allowed), joinList(allowed)));
                break;
            }
            case Param::Corners:
                corners(e);
                break;
        }
        obj.entries.push_back(std::move(e));
    }

    void numbers(const KeywordSpec& spec, const std::vector<std::string_view>& w, GsiEntry& e) {
        e.numbers.assign(static_cast<std::size_t>(spec.count), 0.0);
        for (int k = 0; k < spec.count && k + 1 < static_cast<int>(w.size()); ++k) {
            const auto v = number(w[static_cast<std::size_t>(k) + 1]);
            if (!v) {
                if (k > 0) break;  // trailing text after the first parameter: ignored, the rest 0
                m_diags.error(e.loc, e.keyword,
                              fmt::format("'{}' is not a number", w[static_cast<std::size_t>(k) + 1]));
                return;
            }
            if (spec.param == Param::Whole && *v != std::floor(*v)) {
                m_diags.error(e.loc, e.keyword,
                              fmt::format("{} is not a whole number", w[static_cast<std::size_t>(k) + 1]));
                return;
            }
            e.numbers[static_cast<std::size_t>(k)] = *v;
            e.given = k + 1;
        }
        if (e.given == 0) m_diags.error(e.loc, e.keyword, fmt::format("{} needs a value", e.keyword));
        if (spec.param == Param::Gravity) e.numbers.resize(static_cast<std::size_t>(std::max(e.given, 1)));
    }

    /// The "x y" lines up to END (spec 9.2: nothing else inside, no comments).
    void corners(GsiEntry& e) {
        while (m_next < m_lines.size()) {
            const std::size_t index = m_next++;
            if (tooLong(index)) continue;
            const auto w = words(trimRight(m_lines[index]));
            if (w.empty()) continue;
            if (asciiUpper(w.front()) == "END") {
                e.cornersEnd = loc(index);
                return;
            }
            const auto x = number(w.front());
            const auto y = w.size() > 1 ? number(w[1]) : std::nullopt;
            if (!x || !y) {
                const bool comment = w.front().front() == '#' || w.front().front() == '$';
                m_diags.error(
                    loc(index), "CORNERS",
                    comment ? std::string("a CORNERS block allows no comments (only 'x y' lines up to END)")
                    : x     ? fmt::format("'{}' is not a corner 'x y': two numbers [m]",
                                          trimRight(m_lines[index]).substr(0, 60))
                            : fmt::format("'{}' is not a corner 'x y' (CORNERS at line {} needs END)",
                                          trimRight(m_lines[index]).substr(0, 60), e.loc.line));
                if (!comment && !x) {  // a keyword: the block lacks its END
                    --m_next;
                    return;
                }
                continue;
            }
            e.corners.push_back({*x, *y});
        }
        m_diags.error(e.loc, "CORNERS", "the CORNERS block has no END");
    }

    /// Skips the block of an unknown CORNERS (already reported).
    void skipBlock() {
        while (m_next < m_lines.size())
            if (const auto w = words(m_lines[m_next++]); !w.empty() && asciiUpper(w.front()) == "END") return;
    }

    std::string m_path;
    std::vector<std::string_view> m_lines;
    std::size_t m_next = 0;
    GsiDocument m_doc;
    Diagnostics m_diags;
};

}  // namespace

const char* gsiObjectName(GsiObjectKind kind) noexcept {
    return specOf(kind).name.data();
}

const GsiEntry* GsiObject::find(std::string_view keyword) const noexcept {
    for (auto it = entries.rbegin(); it != entries.rend(); ++it)
        if (it->keyword == keyword) return &*it;
    return nullptr;
}

const GsiObject* GsiDocument::display() const noexcept {
    for (auto it = objects.rbegin(); it != objects.rend(); ++it)
        if (it->kind == GsiObjectKind::Display) return &*it;
    return nullptr;
}

GsiDocument parseGsi(std::string_view text, const std::string& path) {
    return Parser(text, path).run();
}

std::vector<std::string> gsiKeywords(GsiObjectKind kind) {
    return specOf(kind).names();
}

}  // namespace granulab::io
