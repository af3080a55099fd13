// SPDX-License-Identifier: MIT
// gsi syntax (io/gsi_syntax.hpp; gc2d spec 9.2-9.3): the thesis's sample file, the syntax rules,
// and every error with its file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "io/gsi_syntax.hpp"

using granulab::SceneError;
using granulab::io::GsiDocument;
using granulab::io::GsiObjectKind;
using granulab::io::parseGsi;

namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The error text of parsing `text` ("" if it parses).
std::string errorsOf(const std::string& text) {
    try {
        parseGsi(text, "scene.gsi");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

const std::string kHead = "PARAMETER v1.4\n\n";

}  // namespace

TEST(GsiSyntax, ThesisSamplePistonParses) {
    const std::string path = std::string(GRANULAB_SOURCE_DIR) + "/tests/data/gsi/piston.gsi";
    const GsiDocument d = parseGsi(readFile(path), path);
    EXPECT_EQ(d.identification, "");
    ASSERT_EQ(d.objects.size(), 7u);  // GENERAL, DISPLAY, 4 walls, the block
    const auto& g = d.general();
    EXPECT_DOUBLE_EQ(g.find("DELTA_T")->numbers[0], 1.5e-5);
    EXPECT_EQ(g.find("TIME")->numbers, (std::vector<double>{0, 0.2}));
    EXPECT_DOUBLE_EQ(g.find("E_MODUL")->numbers[0], 1e7);
    EXPECT_DOUBLE_EQ(g.find("STEPS_DATA")->numbers[0], 1000);
    EXPECT_EQ(g.find("BASENAME")->text, "data/piston2");  // case kept
    EXPECT_EQ(g.find("G")->given, 1);                     // one number: constant g
    EXPECT_EQ(g.find("G")->numbers, (std::vector<double>{0}));
    EXPECT_EQ(g.find("G")->loc.line, 13);
    ASSERT_NE(d.display(), nullptr);
    EXPECT_EQ(d.display()->find("SCREEN")->numbers, (std::vector<double>{800, 0}));
    int walls = 0;
    for (const auto& o : d.objects)
        if (o.kind == GsiObjectKind::Wall) {
            ++walls;
            ASSERT_NE(o.find("CORNERS"), nullptr);
            EXPECT_EQ(o.find("CORNERS")->corners.size(), 4u);
        }
    EXPECT_EQ(walls, 4);
    const auto& piston = d.objects[2];
    EXPECT_DOUBLE_EQ(piston.find("PISTON_FORCE")->numbers[0], 10000);
    EXPECT_EQ(piston.find("OFFSET")->numbers, (std::vector<double>{-0.3, 0.0}));
    EXPECT_DOUBLE_EQ(piston.find("CORNERS")->corners[2].y, 0.1);
    const auto& block = d.objects.back();
    EXPECT_EQ(block.kind, GsiObjectKind::GenerateBlock);
    EXPECT_EQ(block.find("GRID_TYPE")->text, "FCC");
    EXPECT_EQ(block.find("PART_RANDOM_POS_CORNERS")->text, "RAND1");  // written Random_Pos_Corners
    EXPECT_EQ(block.find("RANDOM_NUM_CORNERS")->text, "EQUAL");
    EXPECT_DOUBLE_EQ(block.find("PART_NUM_CORNERS")->numbers[0], 8);
}

TEST(GsiSyntax, CaseMissingParametersTrailingTextAndComments) {
    const GsiDocument d = parseGsi(kHead +
                                       "# a comment\n"
                                       "$ echoed to the screen\n"
                                       "  dElTa_t\t2e-5   the step\n"
                                       "TIME 0\n"               // the second parameter missing: 0
                                       "G 9.81 0.5 variable\n"  // two numbers: variable g
                                       "Basename Out/Run1\n"
                                       "particle\n"
                                       "corners\n"
                                       "0 0\n"
                                       "1 0 trailing\n"
                                       "\n"
                                       "0 1\n"
                                       "end\n"
                                       "Com 0.5\n"
                                       "position_absolut\n"
                                       "END_OF_FILE\n"
                                       "anything at all, never read\n",
                                   "x.gsi");
    EXPECT_EQ(d.echoes, (std::vector<std::string>{"echoed to the screen"}));
    EXPECT_EQ(d.general().loc.line, 3);  // GENERAL starts after the identification line
    const auto& g = d.general();
    EXPECT_DOUBLE_EQ(g.find("DELTA_T")->numbers[0], 2e-5);
    EXPECT_EQ(g.find("TIME")->numbers, (std::vector<double>{0, 0}));
    EXPECT_EQ(g.find("TIME")->given, 1);
    EXPECT_EQ(g.find("G")->given, 2);
    EXPECT_EQ(g.find("G")->numbers, (std::vector<double>{9.81, 0.5}));
    EXPECT_EQ(g.find("BASENAME")->text, "Out/Run1");
    ASSERT_EQ(d.objects.size(), 2u);
    const auto& p = d.objects[1];
    EXPECT_EQ(p.kind, GsiObjectKind::Particle);
    EXPECT_EQ(p.loc.line, 9);
    ASSERT_EQ(p.find("CORNERS")->corners.size(), 3u);
    EXPECT_EQ(p.find("CORNERS")->cornersEnd.line, 15);
    EXPECT_EQ(p.find("COM")->numbers, (std::vector<double>{0.5, 0}));
    EXPECT_NE(p.find("POSITION_ABSOLUT"), nullptr);
}

TEST(GsiSyntax, LastDisplayAndLastKeywordCount) {
    const GsiDocument d = parseGsi(kHead + "DISPLAY\nInterval 5\nDISPLAY\nInterval 7\nInterval 9\n", "x.gsi");
    ASSERT_NE(d.display(), nullptr);
    EXPECT_DOUBLE_EQ(d.display()->find("INTERVAL")->numbers[0], 9);
    EXPECT_EQ(d.display()->loc.line, 5);
}

TEST(GsiSyntax, IdentificationLineKept) {
    const GsiDocument d =
        parseGsi("PARAMETER v1.4\nWed May 24 18:31:54 2000 --- doublon --- schinner\r\n", "x.gsi");
    EXPECT_EQ(d.identification, "Wed May 24 18:31:54 2000 --- doublon --- schinner");
}

/// True if `errors` holds `piece`.
#define EXPECT_HAS(errors, piece) EXPECT_NE((errors).find(piece), std::string::npos) << (errors)

TEST(GsiSyntax, ErrorsNameFileLineAndHint) {
    std::string e = errorsOf(kHead + "Delta_TT 1e-4\n");  // unknown keyword: the closest one
    EXPECT_HAS(e, "scene.gsi:3");
    EXPECT_HAS(e, "unknown keyword 'Delta_TT' in GENERAL");
    EXPECT_HAS(e, "did you mean 'DELTA_T'");
    e = errorsOf(kHead + "PARTICLES\n");  // unknown object
    EXPECT_HAS(e, "did you mean 'PARTICLE'");
    e = errorsOf(kHead + "WALL\nPiston_Force 1\nE_Modul 1e7\n");  // a GENERAL keyword in WALL
    EXPECT_HAS(e, "scene.gsi:5");
    EXPECT_HAS(e, "unknown keyword 'E_Modul' in WALL");
    e = errorsOf(kHead + "WALL\nGENERAL\nGamma 0.5\n");  // GENERAL re-entered
    EXPECT_HAS(e, "scene.gsi:4");
    EXPECT_HAS(e, "GENERAL cannot be entered again");
    e = errorsOf(kHead + "Delta_T fast\n");  // not a number
    EXPECT_HAS(e, "'fast' is not a number");
    e = errorsOf(kHead + "Steps_Data 10.5\n");  // not whole
    EXPECT_HAS(e, "10.5 is not a whole number");
    e = errorsOf(kHead + "G_Type SMOTH_STEP\n");  // a choice outside its list
    EXPECT_HAS(e, "'SMOTH_STEP' is not allowed (did you mean 'SMOOTH_STEP'?)");
    EXPECT_HAS(e, "allowed: CONSTANT, LINEAR, STEP, SMOOTH_STEP");
    e = errorsOf(kHead + "PARTICLE\nCorners\n0 0\n# a comment\n1 0\n0 1\nEND\n");
    EXPECT_HAS(e, "scene.gsi:6");
    EXPECT_HAS(e, "a CORNERS block allows no comments");
    e = errorsOf(kHead + "PARTICLE\nCorners\n0 0\n1 0\n0 1\nCom 1 1\n");  // no END before a keyword
    EXPECT_HAS(e, "scene.gsi:8");
    EXPECT_HAS(e, "CORNERS at line 4 needs END");
    e = errorsOf(kHead + "PARTICLE\nCorners\n0 0\n1 0\n");  // no END at the end of the file
    EXPECT_HAS(e, "scene.gsi:4");
    EXPECT_HAS(e, "the CORNERS block has no END");
    e = errorsOf("PARAMETER v1.3\n\n");
    EXPECT_HAS(e, "scene.gsi:1");
    EXPECT_HAS(e, "PARAMETER v1.4");
    e = errorsOf(kHead + "Basename " + std::string(1020, 'x') + "\n");
    EXPECT_HAS(e, "1029 characters: a gsi line holds at most 1023");
    e = errorsOf(kHead + "Basename\n");
    EXPECT_HAS(e, "BASENAME needs a value");
}

TEST(GsiSyntax, EveryErrorOfAFileAtOnce) {
    const std::string e = errorsOf(kHead + "Gamma x\nWALL\nVib_Type WOBBLE\nFoo 1\n");
    EXPECT_HAS(e, "scene.gsi:3");
    EXPECT_HAS(e, "scene.gsi:5");
    EXPECT_HAS(e, "scene.gsi:6");
}

TEST(GsiSyntax, KeywordTablesHoldTheSpecsKeywords) {
    using granulab::io::gsiKeywords;
    const auto has = [](GsiObjectKind k, const std::string& word) {
        const auto all = gsiKeywords(k);
        return std::find(all.begin(), all.end(), word) != all.end();
    };
    EXPECT_EQ(gsiKeywords(GsiObjectKind::General).size(), 24u);
    EXPECT_TRUE(has(GsiObjectKind::GenerateBlock, "PART_RANDOM_POS_CORNERS"));
    EXPECT_TRUE(has(GsiObjectKind::DropSource, "PART_NUM_CORNERS"));  // the shared grain keywords
    EXPECT_TRUE(has(GsiObjectKind::DropSource, "DELTA_T"));
    EXPECT_TRUE(has(GsiObjectKind::Wall, "VIB_FREQUENCE"));
    EXPECT_TRUE(has(GsiObjectKind::Particle, "DRAG_PULLING_POINT"));
    EXPECT_FALSE(has(GsiObjectKind::Wall, "COM"));
}

namespace {

/// A mutant of `text`: 1-4 stacked edits of lines (delete, duplicate, swap), words (a keyword
/// of any object, an object name, a number, garbage) and bytes (flip, insert a control byte).
std::string mutateGsi(std::string text, std::mt19937_64& rng) {
    static const std::vector<std::string> dictionary = [] {
        std::vector<std::string> d = {"END",
                                      "END_OF_FILE",
                                      "CORNERS",
                                      "GENERAL",
                                      "PARTICLE",
                                      "WALL",
                                      "DISPLAY",
                                      "GENERATE_BLOCK",
                                      "DROPSOURCE",
                                      "#",
                                      "$",
                                      "nan",
                                      "inf",
                                      "-0",
                                      "1e308",
                                      "1e-320",
                                      "99999999999999999999",
                                      "",
                                      "\t",
                                      "x"};
        for (int k = 0; k < 6; ++k)
            for (const auto& w : granulab::io::gsiKeywords(static_cast<GsiObjectKind>(k))) d.push_back(w);
        return d;
    }();
    const auto pick = [&](std::size_t n) {
        return static_cast<std::size_t>(rng() % std::max<std::size_t>(n, 1));
    };
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
        std::vector<std::string> lines;
        std::stringstream in(text);
        for (std::string l; std::getline(in, l);) lines.push_back(l);
        if (lines.empty()) lines.emplace_back();
        const std::size_t at = pick(lines.size());
        switch (rng() % 7) {
            case 0:
                lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(at));
                break;
            case 1:
                lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), lines[pick(lines.size())]);
                break;
            case 2:
                std::swap(lines[at], lines[pick(lines.size())]);
                break;
            case 3:
                lines[at] = dictionary[pick(dictionary.size())] + " " + lines[at];
                break;
            case 4:
                lines[at] += " " + dictionary[pick(dictionary.size())];
                break;
            case 5:
                if (!lines[at].empty()) lines[at][pick(lines[at].size())] = static_cast<char>(rng() & 0xFF);
                break;
            default:
                lines[at] = std::string(pick(2048), static_cast<char>('a' + rng() % 26));
                break;
        }
        text.clear();
        for (const auto& l : lines) text += l + "\n";
    }
    return text;
}

}  // namespace

TEST(GsiSyntax, MutantsOfTheSampleParseOrFailCleanly) {
    // A mutant either parses or is bad input (SceneError); anything else (another exception, a
    // crash under the sanitizers) is a finding. 10,000 mutants from a fixed seed.
    const std::string sample = readFile(std::string(GRANULAB_SOURCE_DIR) + "/tests/data/gsi/piston.gsi");
    std::mt19937_64 rng(17);
    int parsed = 0, rejected = 0;
    for (int k = 0; k < 10000; ++k) {
        const std::string mutant = mutateGsi(sample, rng);
        try {
            const GsiDocument d = parseGsi(mutant, "mutant.gsi");
            ASSERT_FALSE(d.objects.empty());
            ++parsed;
        } catch (const SceneError& e) {
            ASSERT_FALSE(e.diagnostics().empty());
            ++rejected;
        } catch (const std::exception& e) {
            FAIL() << "mutant " << k << ": " << e.what() << "\n" << mutant;
        }
    }
    EXPECT_GT(parsed, 500);  // both outcomes are exercised
    EXPECT_GT(rejected, 500);
}
