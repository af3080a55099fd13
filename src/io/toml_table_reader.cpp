// SPDX-License-Identifier: MIT
// TableReader (io/toml_table_reader.hpp): typed getters and the unknown-key report of the scene
// reader (docs/scene-format.md "Errors and exit status").
#include "io/toml_table_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/suggest.hpp"

namespace granulab::io {

/// Location of a node; nodes inserted by --set have no source and are named by their key.
SourceLoc locOf(const toml::node& node, const std::string& file) {
    const auto& src = node.source();
    if (src.begin.line == 0) return {"--set", 0, 0};
    return {file, static_cast<int>(src.begin.line), static_cast<int>(src.begin.column)};
}

std::string typeName(const toml::node& n) {
    switch (n.type()) {
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a number";
        case toml::node_type::boolean:
            return "a boolean";
        default:
            return "a date/time";
    }
}

namespace {

constexpr std::int64_t kExactInteger = std::int64_t{1} << 53;  ///< integers a double holds exactly

/// A number node's value: floats as they are, integers only where a double holds them exactly
/// (toml++ returns nothing for the others, which used to read as 0).
std::optional<double> exactNumber(const toml::node& n) {
    if (const auto* i = n.as_integer()) {
        const std::int64_t v = i->get();
        if (v > kExactInteger || v < -kExactInteger) return std::nullopt;
        return static_cast<double>(v);
    }
    if (const auto* f = n.as_floating_point()) return f->get();
    return std::nullopt;
}

std::string inexactIntegerMessage(const toml::node& n) {
    return fmt::format(
        "the integer {} has no exact floating-point value (|n| > 2^53); write it as a float "
        "(e.g. {:.17g}) if the nearest value is meant",
        n.as_integer()->get(), static_cast<double>(n.as_integer()->get()));
}

}  // namespace

const toml::node* TableReader::node(const std::string& key) {
    m_known.push_back(key);
    return m_table.get(key);
}

void TableReader::typeError(const std::string& key, const toml::node& n, const std::string& expected) {
    m_diags.error(locOf(n, m_file), keyPath(key), fmt::format("expected {}, got {}", expected, typeName(n)));
}

bool TableReader::number(const std::string& key, Real& out) {
    const toml::node* n = node(key);
    if (!n) return false;
    if (!n->is_number()) {
        typeError(key, *n, "a number");
        return false;
    }
    const auto exact = exactNumber(*n);
    if (!exact) {
        m_diags.error(locOf(*n, m_file), keyPath(key), inexactIntegerMessage(*n));
        return false;
    }
    const Real v = *exact;
    if (!std::isfinite(v)) {
        m_diags.error(locOf(*n, m_file), keyPath(key), fmt::format("must be a finite number, got {}", v));
        return false;
    }
    out = v;
    return true;
}

bool TableReader::integer(const std::string& key, std::int64_t& out) {
    const toml::node* n = node(key);
    if (!n) return false;
    if (const auto* f = n->as_floating_point()) {  // 1e6 is a count too, if it is a whole number
        const double v = f->get();
        if (!(std::abs(v) <= static_cast<double>(kExactInteger)) || v != std::floor(v)) {
            m_diags.error(
                locOf(*n, m_file), keyPath(key),
                fmt::format("expected an integer, got {} (whole numbers up to 2^53 may be written as "
                            "floats, e.g. 1e6)",
                            v));
            return false;
        }
        out = static_cast<std::int64_t>(v);
        return true;
    }
    if (!n->is_integer()) {
        typeError(key, *n, "an integer");
        return false;
    }
    out = n->as_integer()->get();
    return true;
}

bool TableReader::boolean(const std::string& key, bool& out) {
    const toml::node* n = node(key);
    if (!n) return false;
    if (!n->is_boolean()) {
        typeError(key, *n, "true or false");
        return false;
    }
    out = n->value<bool>().value_or(false);
    return true;
}

bool TableReader::string(const std::string& key, std::string& out) {
    const toml::node* n = node(key);
    if (!n) return false;
    if (!n->is_string()) {
        typeError(key, *n, "a string");
        return false;
    }
    out = n->value<std::string>().value_or("");
    return true;
}

bool TableReader::strings(const std::string& key, std::vector<std::string>& out) {
    const toml::node* n = node(key);
    if (!n) return false;
    const toml::array* a = n->as_array();
    if (!a || !std::all_of(a->begin(), a->end(), [](const toml::node& e) { return e.is_string(); })) {
        typeError(key, *n, "an array of strings");
        return false;
    }
    out.clear();
    for (const auto& e : *a) out.push_back(e.value<std::string>().value_or(""));
    return true;
}

bool TableReader::choice(const std::string& key, std::string& out, const std::vector<std::string>& allowed) {
    std::string v;
    if (!string(key, v)) return false;
    for (const auto& a : allowed)
        if (a == v) {
            out = v;
            return true;
        }
    m_diags.error(
        locOf(*m_table.get(key), m_file), keyPath(key),
        fmt::format("'{}' is not allowed{}; allowed: {}", v, didYouMean(v, allowed), joinList(allowed)));
    return false;
}

bool TableReader::numbers(const std::string& key, std::vector<Real>& out, std::size_t count) {
    const toml::node* n = node(key);
    if (!n) return false;
    const toml::array* a = n->as_array();
    if (!a || a->size() != count) {
        m_diags.error(locOf(*n, m_file), keyPath(key), fmt::format("expected an array of {} numbers", count));
        return false;
    }
    out.clear();
    for (const auto& e : *a) {
        const auto v = exactNumber(e);
        if (e.is_integer() && !v) {
            m_diags.error(locOf(e, m_file), keyPath(key), inexactIntegerMessage(e));
            return false;
        }
        if (!v || !std::isfinite(*v)) {
            m_diags.error(locOf(e, m_file), keyPath(key), "expected finite numbers in the array");
            return false;
        }
        out.push_back(*v);
    }
    return true;
}

bool TableReader::vec2(const std::string& key, Vec2& out) {
    std::vector<Real> v;
    if (!numbers(key, v, 2)) return false;
    out = {v[0], v[1]};
    return true;
}

bool TableReader::points(const std::string& key, std::vector<Vec2>& out) {
    const toml::node* n = node(key);
    if (!n) return false;
    const toml::array* a = n->as_array();
    if (!a) {
        typeError(key, *n, "an array of [x, y] points");
        return false;
    }
    bool ok = true;
    for (const auto& e : *a) {
        const toml::array* pt = e.as_array();
        if (!pt || pt->size() != 2 || !(*pt)[0].is_number() || !(*pt)[1].is_number()) {
            m_diags.error(locOf(e, m_file), keyPath(key), "each point must be [x, y] in m");
            ok = false;
            continue;
        }
        const auto x = exactNumber((*pt)[0]), y = exactNumber((*pt)[1]);
        if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) {
            m_diags.error(locOf(e, m_file), keyPath(key),
                          "points must be finite numbers (integers at most 2^53 in magnitude)");
            ok = false;
            continue;
        }
        out.push_back({*x, *y});
    }
    return ok;
}

void TableReader::finish() {
    for (auto&& [k, v] : m_table) {
        const std::string key(k.str());
        bool known = false;
        for (const auto& kk : m_known) known = known || kk == key;
        for (const auto& kk : m_ignored) known = known || kk == key;
        if (!known)
            m_diags.error(
                locOf(v, m_file), keyPath(key),
                fmt::format("unknown key{}; allowed here: {}", didYouMean(key, m_known), joinList(m_known)));
    }
}

}  // namespace granulab::io
