// SPDX-License-Identifier: MIT
// Typed reading of one TOML table of a scene (docs/scene-format.md "Errors and exit status"): every key read
// is remembered, so that finish() reports anything left over as an unknown key with a hint. Shared by the
// run/output reader and the engines' section readers (io/*_sections.hpp).
#pragma once
#include <toml++/toml.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "io/scene_override.hpp"

namespace granulab::io {

/// Location of a node; nodes inserted by --set have no source and are named by their key.
SourceLoc locOf(const toml::node& node, const std::string& file);

/// "a table", "a number", ... for type errors.
std::string typeName(const toml::node& n);

/// Reads the keys of one table into *Def fields, collecting type and unknown-key errors.
class TableReader {
public:
    TableReader(const toml::table& table, std::string path, const std::string& file, Diagnostics& diags)
        : m_table(table), m_path(std::move(path)), m_file(file), m_diags(diags) {}

    SourceLoc loc() const { return locOf(m_table, m_file); }
    std::string keyPath(const std::string& key) const { return m_path.empty() ? key : m_path + "." + key; }
    const std::string& file() const { return m_file; }
    Diagnostics& diags() { return m_diags; }
    const toml::table& table() const { return m_table; }

    /// Marks a key as known and returns its node (nullptr if absent).
    const toml::node* node(const std::string& key);

    void typeError(const std::string& key, const toml::node& n, const std::string& expected);

    bool number(const std::string& key, Real& out);
    bool integer(const std::string& key, std::int64_t& out);
    bool boolean(const std::string& key, bool& out);
    bool string(const std::string& key, std::string& out);
    /// Array of strings (names are checked by validate()).
    bool strings(const std::string& key, std::vector<std::string>& out);
    /// A string that must be one of `allowed`.
    bool choice(const std::string& key, std::string& out, const std::vector<std::string>& allowed);
    /// Array of `count` finite numbers.
    bool numbers(const std::string& key, std::vector<Real>& out, std::size_t count);
    bool vec2(const std::string& key, Vec2& out);
    /// Array of [x, y] points [m]; counts are checked by validate().
    bool points(const std::string& key, std::vector<Vec2>& out);

    /// Marks a key as dealt with (already reported) without listing it as allowed here.
    void ignore(const std::string& key) { m_ignored.push_back(key); }

    /// Reports keys that were never asked for.
    void finish();

private:
    const toml::table& m_table;
    std::string m_path;
    const std::string& m_file;
    Diagnostics& m_diags;
    std::vector<std::string> m_known;
    std::vector<std::string> m_ignored;
};

/// Calls fn(reader, index) for every table of an array of tables `key` of `root`.
template <class Fn>
void forEachTable(TableReader& root, const std::string& key, Fn&& fn) {
    const toml::node* n = root.node(key);
    if (!n) return;
    const toml::array* arr = n->as_array();
    if (!arr) {
        root.typeError(key, *n, "an array of tables ([[" + key + "]])");
        return;
    }
    for (std::size_t k = 0; k < arr->size(); ++k) {
        const toml::table* t = (*arr)[k].as_table();
        if (!t) {
            root.typeError(key, (*arr)[k], "a table");
            continue;
        }
        TableReader r(*t, key + "[" + std::to_string(k) + "]", root.file(), root.diags());
        fn(r, k);
        r.finish();
    }
}

/// Optional sub-table; calls fn(reader) when present.
template <class Fn>
void withTable(TableReader& root, const std::string& key, Fn&& fn) {
    const toml::node* n = root.node(key);
    if (!n) return;
    const toml::table* t = n->as_table();
    if (!t) {
        root.typeError(key, *n, "a table");
        return;
    }
    TableReader r(*t, root.keyPath(key), root.file(), root.diags());
    fn(r);
    r.finish();
}

/// Sets the value of `ov` in the TOML tree (creating missing tables); an array element must exist.
/// Problems go to `diags`, located at "--set key".
void applyOverride(toml::table& root, const Override& ov, Diagnostics& diags);

}  // namespace granulab::io
