// SPDX-License-Identifier: MIT
// The syntax of gc2d's scene language gsi (gc2d spec 9.2-9.3, App. B.1): text -> a GsiDocument of
// objects and typed keyword entries, each with its file:line. The mapping onto the native scene
// Defs (the same ones the TOML reader fills) reads this document; nothing here knows a Def.
//
// Rules (spec 9.2):
//   - line 1 `PARAMETER v1.4` (the version check); line 2 the identification text (may be empty),
//     which a matching gci must repeat;
//   - `#` lines are comments; `$` lines are comments that gc2d echoes (kept in `echoes`); blank
//     lines are ignored; a line may hold at most 1023 characters;
//   - keywords and object names are case-insensitive, and so are choice values; the parameters of
//     BASENAME and EMAIL keep their case;
//   - a missing numeric parameter is 0, text after a keyword's parameters is ignored (G takes one
//     number, or two: variable g);
//   - the file starts in GENERAL, which cannot be entered again; PARTICLE, WALL, GENERATE_BLOCK,
//     DROPSOURCE and DISPLAY start a new object, in any order and number (only the last DISPLAY
//     counts: GsiDocument::display);
//   - CORNERS starts a block of "x y" lines closed by END, with nothing else inside (no comments);
//   - END_OF_FILE ends the scene; what follows is ignored.
// Aliases: RANDOM_POS_CORNERS = PART_RANDOM_POS_CORNERS and PART_RANDOM_NUM_CORNERS =
// RANDOM_NUM_CORNERS (the thesis's sample and its Perl names differ). A keyword given twice in one
// object: the last one counts, as in gc2d. Errors (all of them, one SceneError, exit status 2)
// name file:line: unknown object or keyword (with "did you mean"), a parameter that is not a
// number (or not whole where a count is expected), a choice outside its list, GENERAL re-entered,
// a CORNERS block with a comment or a bad line inside or without END, a wrong version line.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace granulab::io {

enum class GsiObjectKind { General, Display, Particle, Wall, GenerateBlock, DropSource };

/// The object's keyword as written in gsi ("GENERATE_BLOCK").
const char* gsiObjectName(GsiObjectKind kind) noexcept;

/// One keyword line (or CORNERS block) of an object.
struct GsiEntry {
    std::string keyword;        ///< canonical spelling, upper case (aliases resolved)
    SourceLoc loc;              ///< its line
    std::vector<Real> numbers;  ///< numeric parameters, missing ones 0 (a flag: none)
    int given = 0;              ///< how many numeric parameters the line held (G: 1 or 2)
    std::string text;           ///< a string parameter (case kept) or a choice (upper case)
    std::vector<Vec2> corners;  ///< CORNERS: the block's points, in order
    SourceLoc cornersEnd;       ///< CORNERS: the END line
};

struct GsiObject {
    GsiObjectKind kind = GsiObjectKind::General;
    SourceLoc loc;                  ///< the object's keyword line (GENERAL: line 3)
    std::vector<GsiEntry> entries;  ///< in file order

    /// The last entry of `keyword` (canonical, upper case), or nullptr.
    const GsiEntry* find(std::string_view keyword) const noexcept;
};

struct GsiDocument {
    std::string path;
    std::string identification;       ///< line 2, verbatim (trailing blanks and CR removed)
    std::vector<std::string> echoes;  ///< the `$` comments, text after the `$`, in order
    std::vector<GsiObject> objects;   ///< objects[0] is GENERAL, then the rest in file order

    const GsiObject& general() const noexcept { return objects.front(); }
    /// The last DISPLAY, or nullptr.
    const GsiObject* display() const noexcept;
};

/// Parses gsi text; `path` names the file in messages. Throws SceneError listing every error.
GsiDocument parseGsi(std::string_view text, const std::string& path);

/// Every keyword of an object kind (canonical spellings), for docs and tests.
std::vector<std::string> gsiKeywords(GsiObjectKind kind);

}  // namespace granulab::io
