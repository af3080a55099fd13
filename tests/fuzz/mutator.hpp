// SPDX-License-Identifier: MIT
// Structure-aware text mutations of TOML scenes for the fuzz harness (tests/fuzz/fuzz_scenes.cpp):
// numbers replaced by interesting or scaled values, strings and keys swapped for others seen in
// the seed scenes, lines and sections deleted, duplicated, swapped or spliced in, raw bytes
// flipped. Deterministic: the same text and random stream give the same mutant.
#pragma once
#include <string>
#include <vector>

#include "core/rng.hpp"

namespace granulab::fuzz {

class Mutator {
public:
    /// `corpus`: the seed scenes; their keys, quoted strings and lines form the dictionary.
    explicit Mutator(const std::vector<std::string>& corpus);

    /// A mutant of `text`: one to four stacked mutations drawn from `rng`.
    std::string mutate(const std::string& text, CounterRng& rng) const;

    /// Names of the mutation kinds (for messages), in the order mutate draws them.
    static const std::vector<std::string>& kinds();

private:
    void mutateOnce(std::string& text, CounterRng& rng) const;
    void mutateToken(std::string& text, std::size_t kind, CounterRng& rng) const;  ///< values, strings, keys
    void mutateLines(std::string& text, std::size_t kind,
                     CounterRng& rng) const;  ///< lines, sections, arrays
    void mutateBytes(std::string& text, std::size_t kind, CounterRng& rng) const;  ///< raw bytes

    std::vector<std::string> m_strings;  ///< quoted strings of the corpus, with their quotes
    std::vector<std::string> m_keys;     ///< keys (left of '=') of the corpus
    std::vector<std::string> m_lines;    ///< non-empty lines of the corpus
};

}  // namespace granulab::fuzz
