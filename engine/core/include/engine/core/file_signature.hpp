// SPDX-License-Identifier: MIT
#pragma once
// What a file is, judged by its first bytes, for the message that refuses it: a PNG handed to
// a glTF loader is reported as "starts with the PNG signature", never by echoing its bytes.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace engine {

// The format whose signature (magic number) `head` starts with: "PNG", "JPEG", "OpenEXR",
// "GLB", "ZIP", ... or "" for none known. 16 bytes are enough for every signature listed.
std::string_view fileSignatureName(std::span<const std::uint8_t> head);

// How `head` begins, in printable words: "starts with the PNG signature", "starts with the
// text 'hello'" (printable ASCII only, at most 16 characters), "starts with the byte 0x89",
// or "is empty".
std::string describeFileStart(std::span<const std::uint8_t> head);

}  // namespace engine
