// SPDX-License-Identifier: MIT
// TableReader (io/toml_table_reader.hpp): typed getters and the unknown-key report of the scene
// reader (docs/scene-format.md "Errors and exit status").
#include "io/toml_table_reader.hpp"

#include <fmt/format.h>

#include <cmath>

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
    const Real v = n->value<double>().value_or(0.0);
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
    if (!n->is_integer()) {
        typeError(key, *n, "an integer");
        return false;
    }
    out = n->value<std::int64_t>().value_or(0);
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
        const auto v = e.value<double>();
        if (!e.is_number() || !v || !std::isfinite(*v)) {
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
        const Real x = (*pt)[0].value<double>().value_or(0), y = (*pt)[1].value<double>().value_or(0);
        if (!std::isfinite(x) || !std::isfinite(y)) {
            m_diags.error(locOf(e, m_file), keyPath(key), "points must be finite");
            ok = false;
            continue;
        }
        out.push_back({x, y});
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
