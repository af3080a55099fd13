// SPDX-License-Identifier: MIT
// The cfddem seed's three input files (io/cfddem_files.hpp: syntax, mapping and errors).
#include "io/cfddem_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <system_error>

#include "core/suggest.hpp"
#include "core/utf8.hpp"

namespace granulab::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kConditions = "conditions.txt";
constexpr const char* kBoundary = "boundary.txt";
constexpr const char* kStart = "startvalue.txt";
constexpr const char* kStartPlural = "startvalues.txt";

/// The keys of each file (spec Tab. 4.2, 4.4, 4.5; #KR and #CF added, spec 6.5 [R]).
const std::vector<std::string>& startKeys() {
    static const std::vector<std::string> k = {"#RX", "#RY", "#VX", "#VY", "#PH",
                                               "#OM", "#RA", "#RH", "#EM", "#NU"};
    return k;
}
const std::vector<std::string>& boundaryKeys() {
    static const std::vector<std::string> k = {"#PX", "#PY", "#PZ", "#PB", "#E1", "#E2", "#EB", "#WE", "#WN",
                                               "#WM", "#VX", "#VY", "#PH", "#OM", "#RA", "#RH", "#EM", "#NU"};
    return k;
}
const std::vector<std::string>& conditionKeys() {
    static const std::vector<std::string> k = {"#PS", "#DT", "#TE", "#EP", "#PK", "#CO", "#Dn", "#Dt",
                                               "#Dr", "#RF", "#MU", "#Fg", "#FA", "#Fw", "#FG", "#FP",
                                               "#FB", "#SC", "#SV", "#PI", "#KR", "#CF"};
    return k;
}

bool contains(const std::vector<std::string>& list, const std::string& s) {
    return std::find(list.begin(), list.end(), s) != list.end();
}

struct Value {
    double number = 0;
    std::string text;  ///< the token as written
    int line = 0;
};

struct KeyValues {
    std::vector<Value> values;
    int line = 0;  ///< first line of the key
};

/// One parsed file: every key's values in file order.
struct TrioFile {
    std::string path;  ///< as named in messages
    std::string name;  ///< conditions.txt, ...
    bool present = false;
    std::string info;  ///< the first line, when it is not a data line
    std::map<std::string, KeyValues> keys;

    const KeyValues* get(const std::string& key) const {
        const auto it = keys.find(key);
        return it != keys.end() ? &it->second : nullptr;
    }
    std::size_t count(const std::string& key) const {
        const KeyValues* kv = get(key);
        return kv ? kv->values.size() : 0;
    }
    SourceLoc at(int line) const { return {path, line, 0}; }
    /// The key's first line, or the file when it is absent.
    SourceLoc keyLoc(const std::string& key) const {
        const KeyValues* kv = get(key);
        return at(kv ? kv->line : 0);
    }
};

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return "";
    const auto e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

bool isKeyChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

/// Which of the three files owns `key` ("" if none).
std::string ownerOf(const std::string& key) {
    if (contains(conditionKeys(), key)) return kConditions;
    if (contains(startKeys(), key)) return kStart;
    if (contains(boundaryKeys(), key)) return kBoundary;
    return "";
}

/// " (did you mean '#Fg'?)" for a key that differs by case or one character.
std::string keyHint(const std::string& key, const std::vector<std::string>& allowed) {
    std::string caseOnly;
    for (const auto& k : allowed)
        if (editDistance(key, k) == 0) caseOnly += (caseOnly.empty() ? "'" : " or '") + k + "'";
    if (!caseOnly.empty()) return " (keys are case-sensitive: did you mean " + caseOnly + "?)";
    for (const auto& k : allowed)
        if (editDistance(key, k) == 1 && k[1] == key[1]) return " (did you mean '" + k + "'?)";
    return "";
}

/// Splits `rest` into value tokens: blanks, tabs, commas and semicolons separate; for a text key a
/// token may be double-quoted (with spaces inside).
std::vector<std::string> tokens(const std::string& rest, bool text) {
    std::vector<std::string> out;
    std::size_t k = 0;
    const auto sep = [](char c) { return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r'; };
    while (k < rest.size()) {
        while (k < rest.size() && sep(rest[k])) ++k;
        if (k >= rest.size()) break;
        if (text && rest[k] == '"') {
            const auto close = rest.find('"', k + 1);
            const auto end = close == std::string::npos ? rest.size() : close;
            out.push_back(rest.substr(k + 1, end - k - 1));
            k = end + 1;
            continue;
        }
        const auto start = k;
        while (k < rest.size() &&
               !(text ? (rest[k] == ' ' || rest[k] == '\t' || rest[k] == '\r') : sep(rest[k])))
            ++k;
        out.push_back(rest.substr(start, k - start));
    }
    return out;
}

/// A number as the seed writes it (MATLAB: 1, -0.5, 1e-5, 2.0E+11, +3).
std::optional<double> parseNumber(const std::string& token) {
    std::string_view s(token);
    if (!s.empty() && s.front() == '+') {
        s.remove_prefix(1);
        if (!s.empty() && (s.front() == '+' || s.front() == '-')) return std::nullopt;
    }
    double v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
    return v;
}

TrioFile readTrioFile(const fs::path& path, const std::string& name, const std::vector<std::string>& keys,
                      Diagnostics& d) {
    TrioFile f;
    f.path = path.string();
    f.name = name;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        d.error(f.at(0), "", "cannot read the file");
        return f;
    }
    f.present = true;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (lineNo == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte order mark
        const std::string s = trimmed(line);
        if (s.rfind("//", 0) == 0) continue;  // comment
        const bool keyLine = s.size() >= 3 && s[0] == '#' && isKeyChar(s[1]) && isKeyChar(s[2]);
        const std::string key = keyLine ? s.substr(0, 3) : "";
        if (lineNo == 1 && !(keyLine && contains(keys, key))) {  // the info line (spec 6.2)
            f.info = s;
            continue;
        }
        if (!keyLine) continue;  // unknown lines are skipped (spec 6.2)
        if (!contains(keys, key)) {
            const std::string owner = ownerOf(key);
            if (!owner.empty())
                d.error(f.at(lineNo), key, fmt::format("this key belongs to {}, not to {}", owner, name));
            else
                d.error(
                    f.at(lineNo), key,
                    fmt::format("unknown key{}; keys of {}: {}", keyHint(key, keys), name, joinList(keys)));
            continue;
        }
        std::string rest = s.substr(3);
        if (const auto c = rest.find("//"); c != std::string::npos) rest.resize(c);
        const bool text = key == "#CF";
        KeyValues& kv = f.keys[key];
        if (kv.line == 0) kv.line = lineNo;
        for (const std::string& t : tokens(rest, text)) {
            Value v;
            v.text = t;
            v.line = lineNo;
            if (!text) {
                const auto n = parseNumber(t);
                if (!n) {
                    d.error(f.at(lineNo), key, fmt::format("'{}' is not a number", t));
                    continue;
                }
                if (!std::isfinite(*n)) {
                    d.error(f.at(lineNo), key, fmt::format("must be a finite number, got '{}'", t));
                    continue;
                }
                v.number = *n;
            }
            kv.values.push_back(std::move(v));
        }
    }
    return f;
}

/// `s` as UTF-8: unchanged when it is valid UTF-8, else read as Latin-1 (the seed's info lines were
/// written on Windows).
std::string asUtf8(const std::string& s) {
    if (isUtf8(s)) return s;
    std::string out;
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x80) {
            out += ch;
        } else {
            out += static_cast<char>(0xC0 | (c >> 6));
            out += static_cast<char>(0x80 | (c & 0x3F));
        }
    }
    return out;
}

bool isWhole(double v) {
    return std::floor(v) == v && std::fabs(v) <= 9007199254740992.0;
}

/// The reading of the three files into a SceneDef: helpers that report with file:line.
class TrioBuilder {
public:
    explicit TrioBuilder(Diagnostics& d) : m_d(d) {}

    /// The single value of `key`; false when absent (or reported: more than one value).
    bool single(const TrioFile& f, const std::string& key, double& out) {
        const KeyValues* kv = f.get(key);
        if (!kv) return false;
        if (kv->values.size() != 1) {
            if (!kv->values.empty() || !hasErrorsAt(f, kv->line))
                m_d.error(f.at(kv->line), key, fmt::format("expects one value, got {}", kv->values.size()));
            return false;
        }
        out = kv->values[0].number;
        return true;
    }
    /// As single(), and an error when absent.
    bool required(const TrioFile& f, const std::string& key, double& out, const std::string& what) {
        if (!f.get(key)) {
            m_d.error(f.at(0), key, fmt::format("missing: {}", what));
            return false;
        }
        return single(f, key, out);
    }
    /// A whole number in [lo, hi].
    bool count(const TrioFile& f, const std::string& key, std::int64_t& out, std::int64_t lo,
               std::int64_t hi) {
        double v = 0;
        if (!single(f, key, v)) return false;
        if (!isWhole(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi)) {
            m_d.error(f.keyLoc(key), key,
                      fmt::format("expects a whole number in [{}, {}], got {}", lo, hi,
                                  f.get(key)->values[0].text));
            return false;
        }
        out = static_cast<std::int64_t>(v);
        return true;
    }
    /// 0 (off) or 1 (on); `out` keeps its default when absent.
    void flag(const TrioFile& f, const std::string& key, bool& out) {
        double v = 0;
        if (!single(f, key, v)) return;
        if (v != 0 && v != 1) {
            m_d.error(f.keyLoc(key), key,
                      fmt::format("a switch is 0 (off) or 1 (on), got {}", f.get(key)->values[0].text));
            return;
        }
        out = v == 1;
    }
    /// Every value of `key` positive.
    void positive(const TrioFile& f, const std::string& key, const char* unit, const char* what) {
        if (const KeyValues* kv = f.get(key))
            for (const Value& v : kv->values)
                if (!(v.number > 0))
                    m_d.error(f.at(v.line), key,
                              fmt::format("{} must be > 0 [{}], got {}", what, unit, v.text));
    }
    void nonNegative(const TrioFile& f, const std::string& key, const char* unit, const char* what) {
        if (const KeyValues* kv = f.get(key))
            for (const Value& v : kv->values)
                if (!(v.number >= 0))
                    m_d.error(f.at(v.line), key,
                              fmt::format("{} must be >= 0 [{}], got {}", what, unit, v.text));
    }
    void poisson(const TrioFile& f, const std::string& key) {
        if (const KeyValues* kv = f.get(key))
            for (const Value& v : kv->values)
                if (!(v.number >= 0 && v.number < 0.5))
                    m_d.error(f.at(v.line), key,
                              fmt::format("Poisson ratio must be in [0, 0.5), got {}", v.text));
    }
    /// Each of `keys` present in `f` has `n` values (`alsoOne`: or one value, shared).
    bool lengths(const TrioFile& f, const std::vector<std::string>& keys, std::size_t n,
                 const std::string& ref, const std::string& per, bool alsoOne = false) {
        bool ok = true;
        for (const auto& key : keys) {
            const KeyValues* kv = f.get(key);
            if (!kv || kv->values.size() == n || (alsoOne && kv->values.size() == 1)) continue;
            m_d.error(f.at(kv->line), key,
                      fmt::format("{} value{}, but {} has {} ({}{})", kv->values.size(),
                                  kv->values.size() == 1 ? "" : "s", ref, n, per,
                                  alsoOne ? ", or one for all" : ""));
            ok = false;
        }
        return ok;
    }
    void missing(const TrioFile& f, const std::string& key, const std::string& what) {
        m_d.error(f.at(0), key, fmt::format("missing: {}", what));
    }

    /// The material of a (rho, E, nu) triple: "m1", "m2", ... in first-seen order.
    std::string material(std::vector<model::MaterialDef>& mats, double rho, double e, double nu,
                         SourceLoc loc) {
        for (const auto& m : mats)
            if (m.name != "wall" && m.density == rho && m.youngsModulus == e && m.poisson == nu)
                return m.name;
        model::MaterialDef m;
        m.name = fmt::format("m{}", ++m_materials);
        m.density = rho;
        m.youngsModulus = e;
        m.poisson = nu;
        m.loc = std::move(loc);
        mats.push_back(m);
        return m.name;
    }

    Diagnostics& diags() { return m_d; }

private:
    /// A key line whose values were all rejected as non-numbers has already been reported.
    bool hasErrorsAt(const TrioFile& f, int line) const {
        return std::any_of(m_d.list().begin(), m_d.list().end(),
                           [&](const Diagnostic& x) { return x.loc.file == f.path && x.loc.line == line; });
    }
    Diagnostics& m_d;
    int m_materials = 0;
};

/// The value of a per-inlet key for inlet `i`: its only value or its i-th; `def` when absent.
double inletValue(const TrioFile& f, const std::string& key, std::size_t i, double def) {
    const KeyValues* kv = f.get(key);
    if (!kv || kv->values.empty()) return def;
    return kv->values.size() == 1 ? kv->values[0].number : kv->values[i].number;
}

void readStartValues(TrioBuilder& b, const TrioFile& f, model::SceneDef& scene) {
    if (!f.present) return;
    const auto& keys = startKeys();
    const bool any = std::any_of(keys.begin(), keys.end(), [&](const std::string& k) { return f.get(k); });
    if (!any) return;  // no particles at t = 0 (inlets only)
    if (!f.get("#RX")) {
        b.missing(f, "#RX", "start x positions [m], one per particle");
        return;
    }
    const std::size_t n = f.count("#RX");
    bool ok = b.lengths(f, keys, n, "#RX", "one per particle");
    const std::vector<std::pair<std::string, std::string>> required = {{"#RY", "start y positions [m]"},
                                                                       {"#RA", "radii [m]"},
                                                                       {"#RH", "densities [kg/m^3]"},
                                                                       {"#EM", "Young's moduli [Pa]"},
                                                                       {"#NU", "Poisson ratios"}};
    for (const auto& [key, what] : required)
        if (!f.get(key)) {
            b.missing(f, key, what + ", one per particle");
            ok = false;
        }
    b.positive(f, "#RA", "m", "radius");
    b.positive(f, "#RH", "kg/m^3", "density");
    b.positive(f, "#EM", "Pa", "Young's modulus");
    b.poisson(f, "#NU");
    if (!ok) return;
    const auto val = [&](const char* key, std::size_t k) {
        const KeyValues* kv = f.get(key);
        return kv ? kv->values[k].number : 0.0;
    };
    for (std::size_t k = 0; k < n; ++k) {
        model::ParticleDef p;
        p.loc = f.at(f.get("#RX")->values[k].line);
        p.position = {val("#RX", k), val("#RY", k)};
        p.velocity = {val("#VX", k), val("#VY", k)};
        p.angle = val("#PH", k);
        p.omega = val("#OM", k);
        p.radius = val("#RA", k);
        p.material = b.material(scene.materials, val("#RH", k), val("#EM", k), val("#NU", k),
                                f.at(f.get("#RH")->values[k].line));
        scene.particles.push_back(std::move(p));
    }
}

/// What the inlets insert: one InsertDef per inlet edge.
struct InletState {
    model::InsertDef insert;
    SourceLoc loc;
};

/// Reads boundary.txt; `wallMu` gets the wall friction #WM when the boundary has wall edges.
void readBoundaryFile(TrioBuilder& b, const TrioFile& f, const TrioFile& cond, model::SceneDef& scene,
                      std::optional<model::LawParamDef>& wallMu) {
    if (!f.present) return;
    Diagnostics& d = b.diags();
    // Points.
    const std::size_t np = f.count("#PX");
    bool ok = true;
    if (!f.get("#PX") && (f.get("#PY") || f.get("#E1"))) {
        b.missing(f, "#PX", "point x coordinates [m]");
        ok = false;
    }
    if (f.get("#PX") && !f.get("#PY")) {
        b.missing(f, "#PY", "point y coordinates [m], one per point");
        ok = false;
    }
    ok = b.lengths(f, {"#PY", "#PZ", "#PB"}, np, "#PX", "one per point") && ok;
    if (const KeyValues* pz = f.get("#PZ"))
        for (const Value& v : pz->values)
            if (v.number != 0)
                d.error(f.at(v.line), "#PZ", fmt::format("the model is 2D: z must be 0 [m], got {}", v.text));
    // Edges.
    const std::size_t ne = f.count("#E1");
    if (!f.get("#E1") && (f.get("#E2") || f.get("#EB"))) {
        b.missing(f, "#E1", "edge start point indices (from 1)");
        ok = false;
    }
    for (const char* key : {"#E2", "#EB"})
        if (f.get("#E1") && !f.get(key)) {
            b.missing(f, key,
                      key == std::string("#E2") ? "edge end point indices (from 1), one per edge"
                                                : "edge types (1 wall, 2 outlet, 3 inlet), one per edge");
            ok = false;
        }
    ok = b.lengths(f, {"#E2", "#EB"}, ne, "#E1", "one per edge") && ok;
    if (!ok || ne == 0) return;
    model::BoundaryDef bd;
    bd.loc = f.keyLoc("#E1");
    for (std::size_t k = 0; k < np; ++k)
        bd.points.push_back({f.get("#PX")->values[k].number, f.get("#PY")->values[k].number});
    static const std::array<const char*, 3> kTypes = {"wall", "outlet", "inlet"};
    bool edgesOk = true;
    for (std::size_t k = 0; k < ne; ++k) {
        model::BoundaryDef::Edge e;
        for (const char* key : {"#E1", "#E2"}) {
            const Value& v = f.get(key)->values[k];
            if (!isWhole(v.number) || v.number < 1 || v.number > static_cast<double>(np)) {
                d.error(f.at(v.line), key,
                        fmt::format(
                            "edge {}: point index {} out of range; allowed 1 ... {} (the points #PX, #PY, "
                            "counted from 1)",
                            k + 1, v.text, np));
                edgesOk = false;
                continue;
            }
            (key == std::string("#E1") ? e.from : e.to) = static_cast<std::int64_t>(v.number) - 1;
        }
        const Value& t = f.get("#EB")->values[k];
        if (t.number != 1 && t.number != 2 && t.number != 3) {
            d.error(f.at(t.line), "#EB",
                    fmt::format("edge {}: type {} is not allowed; allowed: 1 (wall), 2 (outlet), 3 (inlet)",
                                k + 1, t.text));
            edgesOk = false;
            continue;
        }
        e.type = kTypes[static_cast<std::size_t>(t.number) - 1];
        bd.edges.push_back(e);
    }
    if (!edgesOk) return;
    const auto has = [&](const char* type) {
        return std::any_of(bd.edges.begin(), bd.edges.end(), [&](const auto& e) { return e.type == type; });
    };
    // Walls: the material "wall" and the particle-wall friction.
    double we = 0, wn = 0, wm = 0;
    const bool weOk = b.single(f, "#WE", we), wnOk = b.single(f, "#WN", wn), wmOk = b.single(f, "#WM", wm);
    if (has("wall")) {
        for (const auto& [key, what] : {std::pair{"#WE", "the wall's Young's modulus [Pa]"},
                                        std::pair{"#WN", "the wall's Poisson ratio"},
                                        std::pair{"#WM", "the wall-particle friction coefficient"}})
            if (!f.get(key)) b.missing(f, key, std::string(what) + " (the boundary has wall edges)");
        b.positive(f, "#WE", "Pa", "Young's modulus");
        b.poisson(f, "#WN");
        b.nonNegative(f, "#WM", "-", "friction coefficient");
        if (wmOk) wallMu = model::LawParamDef{wm, false, f.keyLoc("#WM")};
        if (weOk && wnOk) {
            model::MaterialDef wall;
            wall.name = "wall";
            wall.youngsModulus = we;
            wall.poisson = wn;
            wall.loc = f.keyLoc("#WE");
            scene.materials.push_back(wall);
            bd.material = "wall";
        }
    }
    // Inlets: the state of their particles (one value for all, or one per inlet edge) and the rate.
    std::vector<std::size_t> inletEdges;
    for (std::size_t k = 0; k < bd.edges.size(); ++k)
        if (bd.edges[k].type == "inlet") inletEdges.push_back(k);
    const std::size_t nin = inletEdges.size();
    std::vector<InletState> states;
    double rate = 0;
    if (nin > 0) {
        const std::vector<std::string> keys = {"#VX", "#VY", "#PH", "#OM", "#RA", "#RH", "#EM", "#NU"};
        bool inOk = b.lengths(f, keys, nin, "the boundary",
                              fmt::format("{} inlet edge{}", nin, nin == 1 ? "" : "s"), true);
        const std::vector<std::pair<std::string, std::string>> required = {
            {"#VX", "the inlet particles' x velocity [m/s]"},
            {"#VY", "the inlet particles' y velocity [m/s]"},
            {"#RA", "the inlet particles' radius [m]"},
            {"#RH", "the inlet particles' density [kg/m^3]"},
            {"#EM", "the inlet particles' Young's modulus [Pa]"},
            {"#NU", "the inlet particles' Poisson ratio"}};
        for (const auto& [key, what] : required)
            if (!f.get(key) || f.get(key)->values.empty()) {
                b.missing(f, key, what + " (the boundary has inlet edges)");
                inOk = false;
            }
        b.positive(f, "#RA", "m", "radius");
        b.positive(f, "#RH", "kg/m^3", "density");
        b.positive(f, "#EM", "Pa", "Young's modulus");
        b.poisson(f, "#NU");
        if (!cond.get("#PS")) {
            if (cond.present)
                b.missing(cond, "#PS",
                          fmt::format("particles per second per inlet [1/s] (boundary.txt has {} inlet "
                                      "edge{})",
                                      nin, nin == 1 ? "" : "s"));
            inOk = false;
        } else if (b.single(cond, "#PS", rate) && !(rate > 0)) {
            d.error(cond.keyLoc("#PS"), "#PS",
                    fmt::format("particles per second must be > 0 [1/s], got {}",
                                cond.get("#PS")->values[0].text));
            inOk = false;
        }
        if (!inOk) return;
        for (std::size_t i = 0; i < nin; ++i) {
            InletState s;
            s.insert.radius.kind = model::SizeDistDef::Kind::Constant;
            s.insert.radius.value = inletValue(f, "#RA", i, 0);
            s.insert.radius.loc = f.keyLoc("#RA");
            s.insert.velocity = {inletValue(f, "#VX", i, 0), inletValue(f, "#VY", i, 0)};
            s.insert.angle = inletValue(f, "#PH", i, 0);
            s.insert.omega = inletValue(f, "#OM", i, 0);
            const KeyValues* rh = f.get("#RH");
            s.insert.material =
                b.material(scene.materials, inletValue(f, "#RH", i, 0), inletValue(f, "#EM", i, 0),
                           inletValue(f, "#NU", i, 0), f.at(rh->values[rh->values.size() == 1 ? 0 : i].line));
            const KeyValues* eb = f.get("#EB");
            s.loc = f.at(eb->values[inletEdges[i]].line);
            states.push_back(std::move(s));
        }
    }
    const auto sameInsert = [](const model::InsertDef& a, const model::InsertDef& c) {
        return a.radius.value == c.radius.value && a.velocity == c.velocity && a.angle == c.angle &&
               a.omega == c.omega && a.material == c.material;
    };
    const bool shared = std::all_of(states.begin(), states.end(), [&](const InletState& s) {
        return sameInsert(s.insert, states.front().insert);
    });
    if (!states.empty() && shared) {
        bd.rate = rate;
        bd.insert = states.front().insert;
    } else if (!states.empty()) {  // one [[inlet]] per inlet edge, in edge order
        for (std::size_t i = 0; i < nin; ++i) {
            const auto& e = bd.edges[inletEdges[i]];
            model::InletDef in;
            in.a = bd.points[static_cast<std::size_t>(e.from)];
            in.b = bd.points[static_cast<std::size_t>(e.to)];
            in.rate = rate;
            in.insert = states[i].insert;
            in.loc = states[i].loc;
            scene.machines.inlets.push_back(std::move(in));
        }
        std::erase_if(bd.edges, [](const auto& e) { return e.type == "inlet"; });
    }
    if (!bd.edges.empty()) scene.machines.boundaries.push_back(std::move(bd));
}

/// [[contact]] with the seed's laws (spec 3): Hertz, Lehr D_n, Mindlin mu and D_t, rolling k_r, D_r.
model::ContactDef seedContact(TrioBuilder& b, const TrioFile& c, const std::string& a,
                              const std::string& other) {
    model::ContactDef law;
    law.materialA = a;
    law.materialB = other;
    law.normal = "hertz";
    law.damping = "lehr";
    law.tangential = "mindlin";
    law.rolling = "spring_dashpot";
    law.loc = c.keyLoc(c.get("#MU") ? "#MU" : "#Dn");
    for (const auto& [key, param] :
         {std::pair{"#Dn", "D_n"}, std::pair{"#Dt", "D_t"}, std::pair{"#Dr", "D_r"}, std::pair{"#MU", "mu"},
          std::pair{"#KR", "k_r"}}) {
        double v = 0;
        b.single(c, key, v);
        b.nonNegative(c, key, key == std::string("#KR") ? "N" : "-", param);
        law.params[param] = {v, false, c.keyLoc(key)};
    }
    return law;
}

void readConditions(TrioBuilder& b, const TrioFile& c, model::SceneDef& scene) {
    if (!c.present) return;
    Diagnostics& d = b.diags();
    scene.run.title = c.info.empty() ? "cfddem input files" : asUtf8(c.info);
    scene.run.loc = c.keyLoc("#TE");
    b.required(c, "#TE", scene.run.endTime, "the end time t_end [s]");
    auto& dem = scene.dem;
    dem.loc = c.keyLoc("#DT");
    b.required(c, "#DT", dem.dt, "the time step dt [s]");
    dem.integrator = "pc";
    dem.massModel = "sphere";
    dem.overlapGuard = true;
    dem.gravity = {0, -9.81};
    b.positive(c, "#TE", "s", "the end time");
    b.positive(c, "#DT", "s", "the time step");
    b.single(c, "#EP", dem.pcTolerance);
    b.positive(c, "#EP", "m/s^2", "the predictor-corrector tolerance");
    b.count(c, "#PK", dem.pcIterations, 0, 1000);
    if (b.single(c, "#CO", dem.pcCorrector) && !(dem.pcCorrector > 0 && dem.pcCorrector <= 1))
        d.error(c.keyLoc("#CO"), "#CO",
                fmt::format("the corrector factor must be in (0, 1], got {}", c.get("#CO")->values[0].text));
    b.flag(c, "#Fg", dem.weight);
    b.flag(c, "#FP", dem.particleContacts);
    b.flag(c, "#FB", dem.wallContacts);
    scene.contacts.push_back(seedContact(b, c, "*", "*"));
    // Fluid (spec 5).
    bool drag = true, buoyancy = true, attraction = false;
    b.flag(c, "#Fw", drag);
    b.flag(c, "#FA", buoyancy);
    b.flag(c, "#FG", attraction);
    double rf = 0;
    const bool hasRf = b.single(c, "#RF", rf);
    if (hasRf && rf < 0)
        d.error(c.keyLoc("#RF"), "#RF", fmt::format("fluid density must be >= 0 [kg/m^3], got {}", rf));
    const KeyValues* cf = c.get("#CF");
    if (cf && cf->values.empty())
        d.error(c.at(cf->line), "#CF", "expects a path (the CFD files or their folder)");
    if (hasRf && rf > 0) {
        auto& f = scene.fluid;
        f.present = true;
        f.loc = c.keyLoc("#RF");
        f.density = rf;
        f.drag = drag ? "quadratic" : "none";
        f.cw = 0.47;
        f.buoyancy = buoyancy;
        f.timing = "even";
        if (cf)
            for (const Value& v : cf->values) {
                f.fields.push_back(v.text);
                f.fieldLocs.push_back(c.at(v.line));
            }
    } else if (cf && !cf->values.empty()) {
        d.error(c.at(cf->line), "#CF", "the CFD fields need a fluid: set the fluid density #RF > 0 [kg/m^3]");
    }
    if (attraction) {
        scene.attraction.present = true;
        scene.attraction.constant = 6.674e-11;
        scene.attraction.loc = c.keyLoc("#FG");
    }
    // Output.
    auto& o = scene.output;
    o.loc = c.keyLoc(c.get("#SC") ? "#SC" : "#SV");
    std::int64_t sc = 0, sv = 0, pi = 0;
    b.count(c, "#SC", sc, 0, std::int64_t{1} << 53);
    b.count(c, "#SV", sv, 0, std::int64_t{1} << 53);
    b.count(c, "#PI", pi, 0, std::int64_t{1} << 53);  // live plot: ignored
    if (sc > 0) {
        o.seriesInterval = static_cast<Real>(sc) * dem.dt;
        o.particleSeries = true;
    }
    if (sv > 0)
        o.snapshotInterval = static_cast<Real>(sv) * dem.dt;
    else
        o.vtk = false;
}

}  // namespace

bool isCfddemFolder(const std::string& dir) {
    std::error_code ec;
    const fs::path p(dir);
    if (!fs::is_directory(p, ec)) return false;
    return fs::is_regular_file(p / kConditions, ec) && fs::is_regular_file(p / kBoundary, ec) &&
           (fs::is_regular_file(p / kStart, ec) || fs::is_regular_file(p / kStartPlural, ec));
}

bool hasCfddemFiles(const std::string& dir) {
    std::error_code ec;
    const fs::path p(dir);
    if (!fs::is_directory(p, ec)) return false;
    for (const char* name : {kConditions, kBoundary, kStart, kStartPlural})
        if (fs::exists(p / name, ec)) return true;
    return false;
}

model::SceneDef readCfddemFolder(const std::string& dir) {
    Diagnostics d;
    const fs::path root(dir);
    std::error_code ec;
    if (!fs::is_directory(root, ec))
        throw SceneError(
            makeDiagnostic(dir, 0, "",
                           "not a folder; expected the cfddem seed's folder holding conditions.txt, "
                           "boundary.txt and startvalue.txt"));
    if (!hasCfddemFiles(dir))
        throw SceneError(
            makeDiagnostic(dir, 0, "",
                           "is a folder without the cfddem seed's input files; expected a scene file "
                           "(.toml) or a folder holding conditions.txt, boundary.txt and "
                           "startvalue.txt"));
    const auto fileOf = [&](const char* name, const char* what) {
        const fs::path p = root / name;
        if (!fs::exists(p, ec))
            d.error({p.string(), 0, 0}, "", fmt::format("missing: {} (cfddem spec 6)", what));
        return p;
    };
    const fs::path condPath = fileOf(kConditions, "the conditions file (time step, end time, laws, flags)");
    const fs::path boundPath = fileOf(kBoundary, "the boundary file (points, edges, wall material, inlets)");
    const bool singular = fs::exists(root / kStart, ec), plural = fs::exists(root / kStartPlural, ec);
    fs::path startPath = root / (plural && !singular ? kStartPlural : kStart);
    if (singular && plural)
        d.error({(root / kStartPlural).string(), 0, 0}, "",
                "both startvalue.txt and startvalues.txt are present; keep one (they are the same file)");
    if (!singular && !plural)
        d.error({startPath.string(), 0, 0}, "",
                "missing: startvalue.txt or startvalues.txt (the particles at t = 0; cfddem spec 6.3)");

    const auto read = [&](const fs::path& p, const std::string& name, const std::vector<std::string>& keys) {
        if (!fs::exists(p, ec)) {
            TrioFile f;
            f.path = p.string();
            f.name = name;
            return f;
        }
        return readTrioFile(p, name, keys, d);
    };
    const TrioFile cond = read(condPath, kConditions, conditionKeys());
    const TrioFile bound = read(boundPath, kBoundary, boundaryKeys());
    const TrioFile start = read(startPath, startPath.filename().string(), startKeys());

    model::SceneDef scene;
    scene.path = condPath.string();
    scene.run.engine = "dem";
    TrioBuilder b(d);
    readStartValues(b, start, scene);
    readConditions(b, cond, scene);
    std::optional<model::LawParamDef> wallMu;
    readBoundaryFile(b, bound, cond, scene, wallMu);
    if (wallMu && !scene.contacts.empty()) {  // particle-wall: the particle laws with mu = #WM
        model::ContactDef wall = scene.contacts.front();
        wall.materialA = "wall";
        wall.materialB = "*";
        wall.params["mu"] = *wallMu;
        wall.loc = wallMu->loc;
        scene.contacts.push_back(std::move(wall));
    }
    d.throwIfAny();
    return scene;
}

}  // namespace granulab::io
