// SPDX-License-Identifier: MIT
// The scene mutator (tests/fuzz/mutator.hpp). A small scanner finds the numbers, quoted strings,
// keys and section headers of TOML text (comments skipped); each mutation kind edits one of them.
#include "mutator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>

namespace granulab::fuzz {

namespace {

constexpr std::size_t kMaxLength = 1 << 20;  ///< mutants are not grown beyond 1 MiB

/// Values that broke or nearly broke scene checks: zero, signs, denormals, overflow, integers
/// beyond 2^53 and 2^31, non-finite floats, and numbers TOML cannot hold.
const std::vector<std::string>& interestingValues() {
    static const std::vector<std::string> values = {"0",
                                                    "-1",
                                                    "1",
                                                    "1e-300",
                                                    "5e-324",
                                                    "1e300",
                                                    "-1e300",
                                                    "1e14",
                                                    "nan",
                                                    "inf",
                                                    "-inf",
                                                    "9007199254740993",
                                                    "2147483648",
                                                    "4294967296",
                                                    "1e12",
                                                    "-0.0",
                                                    "1e-12",
                                                    "0.5",
                                                    "2",
                                                    "-9223372036854775808",
                                                    "9223372036854775807",
                                                    "1.7976931348623157e308",
                                                    "2.2250738585072014e-308",
                                                    "1" + std::string(400, '0'),
                                                    "0." + std::string(400, '0') + "1"};
    return values;
}

/// Replacements of another TOML type (type errors at every key).
const std::vector<std::string>& otherTypes() {
    static const std::vector<std::string> values = {"\"x\"", "true", "[]", "{}", "[1, 2]", "{ a = 1 }", "''"};
    return values;
}

std::size_t below(CounterRng& rng, std::size_t n) {
    return n == 0 ? 0 : static_cast<std::size_t>(rng.nextU64() % n);
}

template <class T>
const T& pick(const std::vector<T>& v, CounterRng& rng) {
    return v[below(rng, v.size())];
}

struct Span {
    std::size_t pos = 0, len = 0;
};

bool isTokenChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '+' || c == '-';
}

bool looksLikeValue(const std::string& t) {
    if (t == "true" || t == "false") return true;
    const std::string s = (t[0] == '+' || t[0] == '-') ? t.substr(1) : t;
    if (s == "inf" || s == "nan") return true;
    if (s.empty()) return false;
    return std::isdigit(static_cast<unsigned char>(s[0])) ||
           (s[0] == '.' && s.size() > 1 && std::isdigit(static_cast<unsigned char>(s[1])));
}

/// The tokens of TOML text that mutations edit.
struct Tokens {
    std::vector<Span> values;   ///< numbers and booleans
    std::vector<Span> strings;  ///< "..." and '...', quotes included
    std::vector<Span> keys;     ///< bare keys left of '='
};

Tokens scan(const std::string& t) {
    Tokens out;
    const std::size_t n = t.size();
    std::size_t i = 0;
    while (i < n) {
        const char c = t[i];
        if (c == '#') {
            while (i < n && t[i] != '\n') ++i;
        } else if (c == '"' || c == '\'') {
            std::size_t j = i + 1;
            while (j < n && t[j] != c && t[j] != '\n') j += (c == '"' && t[j] == '\\') ? 2 : 1;
            j = std::min(j + 1, n);
            out.strings.push_back({i, j - i});
            i = j;
        } else if (isTokenChar(c)) {
            std::size_t j = i;
            while (j < n && isTokenChar(t[j])) ++j;
            std::size_t k = j;
            while (k < n && (t[k] == ' ' || t[k] == '\t')) ++k;
            if (k < n && t[k] == '=')
                out.keys.push_back({i, j - i});
            else if (looksLikeValue(t.substr(i, j - i)))
                out.values.push_back({i, j - i});
            i = j;
        } else {
            ++i;
        }
    }
    return out;
}

std::vector<std::string> splitLines(const std::string& t) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < t.size()) {
        const std::size_t end = t.find('\n', start);
        if (end == std::string::npos) {
            lines.push_back(t.substr(start));
            break;
        }
        lines.push_back(t.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string t;
    for (const auto& l : lines) t += l + "\n";
    return t;
}

bool isHeader(const std::string& line) {
    const auto p = line.find_first_not_of(" \t");
    return p != std::string::npos && line[p] == '[';
}

/// A scaled, negated or shifted version of the number `s` (integers stay integers).
std::string arithmetic(const std::string& s, CounterRng& rng) {
    const bool integer = s.find_first_of(".eEin") == std::string::npos;
    const long long v = std::strtoll(s.c_str(), nullptr, 10);
    if (integer && v > -(1LL << 60) && v < (1LL << 60)) {  // no signed overflow below
        switch (below(rng, 6)) {
            case 0:
                return std::to_string(v + 1);
            case 1:
                return std::to_string(v - 1);
            case 2:
                return std::to_string(-v);
            case 3:
                return std::to_string(v / 2);
            case 4:
                return fmt::format("{}{}", v, std::string(1 + below(rng, 12), '0'));
            default:
                return std::to_string(v * 2);
        }
    }
    const double x = std::strtod(s.c_str(), nullptr);
    switch (below(rng, 4)) {
        case 0:
            return fmt::format("{:.17g}", -x);
        case 1:
            return fmt::format("{:.17g}", x * (1 + 1e-15));
        case 2:
            return fmt::format("{:.17g}", x * 2);
        default:
            return fmt::format("{:.17g}", x * std::pow(10.0, static_cast<double>(below(rng, 61)) - 30));
    }
}

void replaceSpan(std::string& t, const Span& s, const std::string& with) {
    t.replace(s.pos, s.len, with);
}

/// Drops or duplicates one section (a header line and the lines up to the next header).
void mutateSection(std::vector<std::string>& lines, bool drop, CounterRng& rng) {
    std::vector<std::size_t> headers;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (isHeader(lines[i])) headers.push_back(i);
    if (headers.empty()) return;
    const std::size_t h = below(rng, headers.size());
    const auto from = static_cast<std::ptrdiff_t>(headers[h]);
    const auto to = static_cast<std::ptrdiff_t>(h + 1 < headers.size() ? headers[h + 1] : lines.size());
    const std::vector<std::string> section(lines.begin() + from, lines.begin() + to);
    if (drop)
        lines.erase(lines.begin() + from, lines.begin() + to);
    else
        lines.insert(lines.begin() + to, section.begin(), section.end());
}

/// Appends an interesting value to, or drops the last element of, an array on a value line.
void mutateArray(std::vector<std::string>& lines, bool grow, CounterRng& rng) {
    std::vector<std::size_t> arrays;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (lines[i].find("= [") != std::string::npos && lines[i].rfind(']') != std::string::npos)
            arrays.push_back(i);
    if (arrays.empty()) return;
    std::string& line = lines[pick(arrays, rng)];
    const std::size_t close = line.rfind(']');
    if (grow) {
        line.insert(close, ", " + pick(interestingValues(), rng));
    } else {
        const std::size_t comma = line.rfind(',', close);
        if (comma != std::string::npos && comma > line.find("= [")) line.erase(comma, close - comma);
    }
}

}  // namespace

const std::vector<std::string>& Mutator::kinds() {
    static const std::vector<std::string> names = {
        "interesting_value", "arithmetic", "other_type",  "swap_string",  "swap_key",          "delete_line",
        "duplicate_line",    "swap_lines", "splice_line", "drop_section", "duplicate_section", "grow_array",
        "shrink_array",      "flip_bit",   "insert_byte", "delete_bytes", "interesting_value2"};
    return names;
}

Mutator::Mutator(const std::vector<std::string>& corpus) {
    std::set<std::string> strings, keys, lines;
    for (const auto& text : corpus) {
        const Tokens tok = scan(text);
        for (const auto& s : tok.strings) strings.insert(text.substr(s.pos, s.len));
        for (const auto& k : tok.keys) keys.insert(text.substr(k.pos, k.len));
        for (const auto& l : splitLines(text))
            if (!l.empty() && l[0] != '#') lines.insert(l);
    }
    strings.insert("\"\"");
    strings.insert("\"" + std::string(5000, 'a') + "\"");
    strings.insert("\"\\u0000\"");
    m_strings.assign(strings.begin(), strings.end());
    m_keys.assign(keys.begin(), keys.end());
    m_lines.assign(lines.begin(), lines.end());
    if (m_keys.empty()) m_keys.push_back("x");
    if (m_lines.empty()) m_lines.push_back("x = 1");
}

std::string Mutator::mutate(const std::string& text, CounterRng& rng) const {
    std::string t = text;
    const std::size_t stack = 1 + below(rng, 4);
    for (std::size_t k = 0; k < stack; ++k) mutateOnce(t, rng);
    return t;
}

void Mutator::mutateOnce(std::string& t, CounterRng& rng) const {
    const std::size_t kind = below(rng, kinds().size());
    if (kind <= 4 || kind == 16)
        mutateToken(t, kind, rng);
    else if (kind <= 12)
        mutateLines(t, kind, rng);
    else
        mutateBytes(t, kind, rng);
}

void Mutator::mutateToken(std::string& t, std::size_t kind, CounterRng& rng) const {
    const Tokens tok = scan(t);
    const bool value = kind <= 2 || kind == 16;
    const std::vector<Span>& spans = value ? tok.values : kind == 3 ? tok.strings : tok.keys;
    if (spans.empty()) return;
    const Span s = pick(spans, rng);
    switch (kind) {
        case 1:
            replaceSpan(t, s, arithmetic(t.substr(s.pos, s.len), rng));
            return;
        case 2:
            replaceSpan(t, s, pick(otherTypes(), rng));
            return;
        case 3:
            replaceSpan(t, s, pick(m_strings, rng));
            return;
        case 4:
            replaceSpan(t, s, pick(m_keys, rng));
            return;
        default:
            replaceSpan(t, s, pick(interestingValues(), rng));
            return;  // drawn twice as often
    }
}

void Mutator::mutateLines(std::string& t, std::size_t kind, CounterRng& rng) const {
    std::vector<std::string> lines = splitLines(t);
    if (lines.empty()) lines.push_back("");
    const auto at = [&](std::size_t i) { return lines.begin() + static_cast<std::ptrdiff_t>(i); };
    const std::size_t a = below(rng, lines.size()), b = below(rng, lines.size());
    switch (kind) {
        case 5:
            lines.erase(at(a));
            break;
        case 6: {
            const std::string copy = lines[a];
            lines.insert(at(b), copy);
            break;
        }
        case 7:
            std::swap(lines[a], lines[b]);
            break;
        case 8:
            lines.insert(at(a), pick(m_lines, rng));
            break;
        case 9:
        case 10:
            mutateSection(lines, kind == 9, rng);
            break;
        default:
            mutateArray(lines, kind == 11, rng);
            break;
    }
    t = joinLines(lines);
    if (t.size() > kMaxLength) t.resize(kMaxLength);
}

void Mutator::mutateBytes(std::string& t, std::size_t kind, CounterRng& rng) const {
    const std::size_t pos = below(rng, t.size() + 1);
    if (kind == 13 && !t.empty()) {
        t[std::min(pos, t.size() - 1)] ^= static_cast<char>(1u << below(rng, 8));
    } else if (kind == 14) {
        static const std::string special = "[]\"'={}#\n.,-+\\e0";
        const char c =
            below(rng, 2) ? special[below(rng, special.size())] : static_cast<char>(below(rng, 256));
        t.insert(pos, 1, c);
    } else if (!t.empty()) {
        t.erase(std::min(pos, t.size() - 1), 1 + below(rng, 8));
    }
}

}  // namespace granulab::fuzz
