// SPDX-License-Identifier: MIT
// engine/core/file_signature.hpp: a file named by what its first bytes say it is, in words
// that never echo a raw byte.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/core/file_signature.hpp"

namespace {

std::vector<std::uint8_t> bytes(const std::string& text) { return {text.begin(), text.end()}; }

TEST(FileSignature, KnownFormatsAreNamed) {
    EXPECT_EQ(engine::fileSignatureName(bytes("\x89PNG\r\n\x1a\n....")), "PNG");
    EXPECT_EQ(engine::fileSignatureName(bytes("\xFF\xD8\xFF\xE0")), "JPEG");
    EXPECT_EQ(engine::fileSignatureName(bytes(std::string("\x76\x2F\x31\x01\x02\x00", 6))), "OpenEXR");
    EXPECT_EQ(engine::fileSignatureName(bytes(std::string("glTF\x02\x00\x00\x00", 8))), "GLB");
    EXPECT_EQ(engine::fileSignatureName(bytes("RIFF\x10\x20\x30\x40WEBPVP8 ")), "WebP");
    EXPECT_EQ(engine::fileSignatureName(bytes("{\"asset\":{}}")), "");
    EXPECT_EQ(engine::fileSignatureName(bytes("\x89PN")), "");  // too short to be sure
}

TEST(FileSignature, DescriptionIsPrintable) {
    EXPECT_EQ(engine::describeFileStart(bytes("\x89PNG\r\n\x1a\n")), "starts with the PNG signature");
    EXPECT_EQ(engine::describeFileStart(bytes("\x93\x01")), "starts with the byte 0x93");
    EXPECT_EQ(engine::describeFileStart(bytes("hello world, a long line of text\n")),
              "starts with the text 'hello world, a l'");
    EXPECT_EQ(engine::describeFileStart(bytes("ab\x01")), "starts with the text 'ab'");
    EXPECT_EQ(engine::describeFileStart({}), "is empty");
}

}  // namespace
