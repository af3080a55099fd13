// SPDX-License-Identifier: MIT
// gc2d's contact files (io/gci_file.hpp; gc2d spec 9.4): parsing, errors with file:line, the
// gco text reading back as the same contacts, and gc2d's naming foo.gsi -> foo.gci.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/gci_file.hpp"

using namespace granulab;

namespace {

std::string errorsOf(const std::string& text) {
    try {
        io::parseGci(text, "c.gci");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(GciFile, ParsesCollisionsCaseInsensitively) {
    const io::GciDocument d = io::parseGci(
        "PARAMETER v1.4\nrun 7 --- host --- me\n# a comment\nCOLLISION\nParticles 4 12\nSumm_Friction -0.5\n"
        "Old_Area 2.5e-9\ncollision\nPARTICLES 12 1\nEND_OF_FILE\nCOLLISION\n",
        "c.gci");
    EXPECT_EQ(d.identification, "run 7 --- host --- me");
    ASSERT_EQ(d.contacts.size(), 2u);  // what follows END_OF_FILE is ignored
    EXPECT_EQ(d.contacts[0].id1, 4);
    EXPECT_EQ(d.contacts[0].id2, 12);
    EXPECT_EQ(d.contacts[0].friction, -0.5);
    EXPECT_EQ(d.contacts[0].oldArea, 2.5e-9);
    EXPECT_EQ(d.contacts[0].loc.line, 4);
    EXPECT_EQ(d.contacts[1].id1, 12);
    EXPECT_EQ(d.contacts[1].friction, 0.0);  // a missing value is 0
}

TEST(GciFile, ErrorsNameFileAndLine) {
    std::string e = errorsOf("PARAMETER v1.3\n\n");
    EXPECT_NE(e.find("c.gci:1"), std::string::npos) << e;
    e = errorsOf("PARAMETER v1.4\n\nParticles 1 2\n");
    EXPECT_NE(e.find("c.gci:3"), std::string::npos) << e;
    EXPECT_NE(e.find("COLLISION section"), std::string::npos) << e;
    e = errorsOf("PARAMETER v1.4\n\nCOLLISION\nParticles 1 x\nSum_Friction 2\nOld_Area -1\n");
    EXPECT_NE(e.find("c.gci:4"), std::string::npos) << e;
    EXPECT_NE(e.find("c.gci:5"), std::string::npos) << e;
    EXPECT_NE(e.find("did you mean"), std::string::npos) << e;  // Summ_Friction
    EXPECT_NE(e.find("c.gci:6"), std::string::npos) << e;
    e = errorsOf("PARAMETER v1.4\n\nCOLLISION\nOld_Area 1e-9\n");
    EXPECT_NE(e.find("c.gci:3"), std::string::npos) << e;
    EXPECT_NE(e.find("needs `Particles id1 id2`"), std::string::npos) << e;
}

TEST(GciFile, GcoTextReadsBackExactly) {
    model::RememberedContactDef c;
    c.id1 = 3;
    c.id2 = 0;
    c.friction = 0.1 + 0.2;  // not a short decimal
    c.oldArea = 1.0 / 3.0 * 1e-9;
    const io::GciDocument d = io::parseGci(io::gcoText("ident", {c}), "c.gco");
    ASSERT_EQ(d.contacts.size(), 1u);
    EXPECT_EQ(d.identification, "ident");
    EXPECT_EQ(d.contacts[0].friction, c.friction);
    EXPECT_EQ(d.contacts[0].oldArea, c.oldArea);
    EXPECT_EQ(io::gciPathFor("runs/foo-in.gsi"), "runs/foo-in.gci");
    EXPECT_EQ(io::gciPathFor("foo.GSI.gz"), "foo.gci");
    EXPECT_EQ(io::gciPathFor("foo.gsi.pl"), "foo.gci");
}
