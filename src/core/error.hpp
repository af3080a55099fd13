// SPDX-License-Identifier: MIT
// Error tiers (STYLE.md "Error handling"): SceneError for user input (exit status 2),
// GL_ASSERT for programmer invariants in debug builds.
#pragma once
#include <cassert>
#include <stdexcept>
#include <string>
#include <vector>

namespace granulab {

/// Where a value came from: a scene file position or a command-line override.
struct SourceLoc {
    std::string file;  ///< file path, or "--set" for a command-line override
    int line = 0;      ///< 1-based; 0 when unknown
    int column = 0;

    std::string str() const {
        if (line <= 0) return file;
        return file + ":" + std::to_string(line);
    }
};

/// One problem found in user input.
struct Diagnostic {
    SourceLoc loc;
    std::string key;      ///< dotted scene key, e.g. "contact[0].kn"
    std::string message;  ///< what is wrong and the allowed range

    std::string str() const {
        std::string s = loc.str();
        if (!s.empty()) s += ": ";
        if (!key.empty()) s += key + ": ";
        return s + message;
    }
};

/// Builds a Diagnostic (a function rather than aggregate initialisation, which trips GCC 12's
/// -Wmaybe-uninitialized false positive).
inline Diagnostic makeDiagnostic(std::string file, int line, std::string key, std::string message) {
    Diagnostic d;
    d.loc.file = std::move(file);
    d.loc.line = line;
    d.key = std::move(key);
    d.message = std::move(message);
    return d;
}

/// All problems of a scene at once; thrown after validation, mapped to exit status 2.
class SceneError : public std::runtime_error {
public:
    explicit SceneError(std::vector<Diagnostic> diags)
        : std::runtime_error(join(diags)), m_diags(std::move(diags)) {}
    explicit SceneError(Diagnostic d) : SceneError(std::vector<Diagnostic>{std::move(d)}) {}
    const std::vector<Diagnostic>& diagnostics() const noexcept { return m_diags; }

private:
    static std::string join(const std::vector<Diagnostic>& diags) {
        std::string s;
        for (const auto& d : diags) s += "error: " + d.str() + "\n";
        return s;
    }
    std::vector<Diagnostic> m_diags;
};

/// Collects diagnostics during parsing and validation.
class Diagnostics {
public:
    void error(SourceLoc loc, std::string key, std::string message) {
        m_list.push_back({std::move(loc), std::move(key), std::move(message)});
    }
    bool empty() const noexcept { return m_list.empty(); }
    const std::vector<Diagnostic>& list() const noexcept { return m_list; }
    void throwIfAny() const {
        if (!m_list.empty()) throw SceneError(m_list);
    }

private:
    std::vector<Diagnostic> m_list;
};

}  // namespace granulab

#ifndef NDEBUG
#define GL_ASSERT(cond, msg) assert((cond) && (msg))
#else
#define GL_ASSERT(cond, msg) ((void)0)
#endif
