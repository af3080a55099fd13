// SPDX-License-Identifier: MIT
// The contact file (io/contact_file.hpp): exact .npy round trip, the header NumPy expects,
// refusal of foreign or truncated files; the contact line set's cells end at the contact point.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "../support.hpp"
#include "io/contact_file.hpp"
#include "io/vtk_writer.hpp"

namespace granulab::io {
namespace {

namespace fs = std::filesystem;

analysis::ContactFrame sampleContacts() {
    analysis::ContactFrame c;
    const auto add = [&c](std::int64_t a, std::int64_t b, std::int32_t wall, double base) {
        c.a.push_back(a);
        c.b.push_back(b);
        c.wall.push_back(wall);
        for (auto* col :
             {&c.px, &c.py, &c.nx, &c.ny, &c.fx, &c.fy, &c.fn, &c.ft, &c.depth, &c.area, &c.length}) {
            col->push_back(base);
            base = base * 1.0000001 + 1.0 / 3.0;
        }
    };
    add(7, 42, -1, 0.1);
    add(4000000000LL, -1, 3, -1e-300);
    add(0, 1, -1, 1e300);
    return c;
}

std::string slurp(const fs::path& p) {
    std::ifstream is(p, std::ios::binary);
    std::ostringstream ss;
    ss << is.rdbuf();
    return ss.str();
}

TEST(ContactFile, NpyRoundTripIsExact) {
    const test::ScratchDir scratch;
    const std::string path = (scratch.path / "c.npy").string();
    const analysis::ContactFrame c = sampleContacts();
    writeContactsNpy(path, c);
    const analysis::ContactFrame r = readContactsNpy(path);
    ASSERT_EQ(r.size(), c.size());
    EXPECT_EQ(r.a, c.a);
    EXPECT_EQ(r.b, c.b);
    EXPECT_EQ(r.wall, c.wall);
    EXPECT_EQ(r.px, c.px);
    EXPECT_EQ(r.ny, c.ny);
    EXPECT_EQ(r.fx, c.fx);
    EXPECT_EQ(r.length, c.length);
    // NumPy's layout: magic, version 1.0, header padded to 64 bytes ending in '\n', 108-byte records.
    const std::string bytes = slurp(path);
    ASSERT_GT(bytes.size(), 10u);
    EXPECT_EQ(bytes.substr(0, 6), "\x93NUMPY");
    const std::size_t headerLen =
        static_cast<unsigned char>(bytes[8]) + 256u * static_cast<unsigned char>(bytes[9]);
    EXPECT_EQ((10 + headerLen) % 64, 0u);
    EXPECT_EQ(bytes[10 + headerLen - 1], '\n');
    EXPECT_NE(bytes.find("'shape': (3,)"), std::string::npos);
    EXPECT_EQ(bytes.size(), 10 + headerLen + 3 * 108);
}

TEST(ContactFile, EmptyFrameRoundTrips) {
    const test::ScratchDir scratch;
    const std::string path = (scratch.path / "empty.npy").string();
    writeContactsNpy(path, {});
    EXPECT_EQ(readContactsNpy(path).size(), 0u);
}

TEST(ContactFile, RefusesForeignAndTruncatedFiles) {
    const test::ScratchDir scratch;
    const std::string path = (scratch.path / "c.npy").string();
    EXPECT_THROW(readContactsNpy(path), std::runtime_error);  // missing
    writeContactsNpy(path, sampleContacts());
    const std::string bytes = slurp(path);
    std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() - 5);
    EXPECT_THROW(readContactsNpy(path), std::runtime_error);
    std::ofstream(path, std::ios::binary) << "x,y\n1,2\n";
    EXPECT_THROW(readContactsNpy(path), std::runtime_error);
}

TEST(ContactFile, LineSetEndsAtTheContactPoint) {
    const test::ScratchDir scratch;
    const std::string path = (scratch.path / "c.vtp").string();
    const analysis::ContactFrame c = sampleContacts();
    const std::vector<Vec2> ca{{1, 2}, {3, 4}, {5, 6}}, cb{{7, 8}, {0, 0}, {9, 10}};
    writeContactsVtp(path, c, ca, cb, 0.5);
    const std::string text = slurp(path);
    // 3 + 2 + 3 points: the wall contact has no second centre.
    EXPECT_NE(text.find("NumberOfPoints=\"8\""), std::string::npos);
    EXPECT_NE(text.find("NumberOfLines=\"3\""), std::string::npos);
    EXPECT_NE(text.find("Name=\"force_magnitude\""), std::string::npos);
    EXPECT_THROW(writeContactsVtp(path, c, ca, {}, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace granulab::io
