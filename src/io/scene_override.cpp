// SPDX-License-Identifier: MIT
// `--set key=value` overrides (io/scene_override.hpp; docs/scene-format.md "Command-line overrides").
#include "io/scene_override.hpp"

#include <fmt/format.h>

#include <vector>

#include "io/toml_table_reader.hpp"

namespace granulab::io {

namespace {

/// Splits "a.b[2].c" into segments {"a", "b", "[2]", "c"}.
std::vector<std::string> splitPath(const std::string& key) {
    std::vector<std::string> parts;
    std::string cur;
    for (std::size_t k = 0; k < key.size(); ++k) {
        const char ch = key[k];
        if (ch == '.') {
            if (!cur.empty()) parts.push_back(cur);
            cur.clear();
        } else if (ch == '[') {
            if (!cur.empty()) parts.push_back(cur);
            cur.assign(1, '[');  // not cur = "[": GCC 12 -Wrestrict false positive when inlined
        } else if (ch == ']') {
            parts.push_back(cur + "]");
            cur.clear();
        } else {
            cur += ch;
        }
    }
    if (!cur.empty()) parts.push_back(cur);
    return parts;
}

}  // namespace

Override parseOverride(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw SceneError(makeDiagnostic("--set", 0, text, "expected key=value, e.g. --set dem.dt=1e-5"));
    Override ov{text.substr(0, eq), text.substr(eq + 1)};
    // Every segment named: no leading, trailing or doubled dot; indices closed and numeric.
    const std::string& k = ov.key;
    bool ok = k.front() != '.' && k.back() != '.' && k.find("..") == std::string::npos && k.front() != '[';
    for (std::size_t p = k.find('['); ok && p != std::string::npos; p = k.find('[', p + 1)) {
        const auto close = k.find(']', p);
        ok = close != std::string::npos && close > p + 1 &&
             k.find_first_not_of("0123456789", p + 1) == close &&
             (close + 1 == k.size() || k[close + 1] == '.' || k[close + 1] == '[');
    }
    if (!ok || k.find_first_of(" \t") != std::string::npos)
        throw SceneError(makeDiagnostic(
            "--set " + text, 0, k,
            "malformed key; expected section.key or section[index].key, e.g. dem.dt or block[0].count"));
    return ov;
}

SceneError attributeToOverrides(const SceneError& error, const std::vector<Override>& overrides) {
    std::vector<Diagnostic> diags = error.diagnostics();
    for (auto& d : diags)
        for (const auto& ov : overrides) {
            const std::string& k = ov.key;
            const bool about = d.key == k || (d.key.size() > k.size() && d.key.compare(0, k.size(), k) == 0 &&
                                              (d.key[k.size()] == '.' || d.key[k.size()] == '['));
            if (about) d.loc = {"--set " + k + "=" + ov.value, 0, 0};
        }
    return SceneError(std::move(diags));
}

void applyOverride(toml::table& root, const Override& ov, Diagnostics& diags) {
    const SourceLoc loc{"--set " + ov.key, 0, 0};
    const auto parts = splitPath(ov.key);
    if (parts.empty() || parts.back().front() == '[') {
        diags.error(loc, ov.key, "malformed key; expected section.key or section[index].key");
        return;
    }
    toml::node* cur = &root;
    for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
        const std::string& part = parts[k];
        if (part.front() == '[') {
            toml::array* arr = cur->as_array();
            std::size_t idx = 0;
            try {
                idx = std::stoul(part.substr(1, part.size() - 2));
            } catch (...) {
                diags.error(loc, ov.key, "array index must be a number");
                return;
            }
            if (!arr || idx >= arr->size()) {
                diags.error(loc, ov.key, fmt::format("no element {} to override", part));
                return;
            }
            cur = arr->get(idx);
        } else {
            toml::table* t = cur->as_table();
            if (!t) {
                diags.error(loc, ov.key, fmt::format("'{}' is not inside a table", part));
                return;
            }
            if (!t->get(part)) t->insert(part, toml::table{});
            cur = t->get(part);
        }
    }
    toml::table* target = cur->as_table();
    if (!target) {
        diags.error(loc, ov.key, "the parent of the key is not a table");
        return;
    }
    toml::table parsed;
    try {
        parsed = toml::parse("v = " + ov.value);
    } catch (const toml::parse_error&) {
        parsed = toml::table{};
        parsed.insert("v", ov.value);  // bare word: a string
    }
    target->insert_or_assign(parts.back(), *parsed.get("v"));
}

}  // namespace granulab::io
