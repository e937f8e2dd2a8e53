// SPDX-License-Identifier: MIT
#include "engine/core/file_signature.hpp"

#include <cstdio>

namespace engine {

namespace {

struct Signature {
    std::string_view name;
    std::string_view magic;  // bytes at `offset`
    std::size_t offset = 0;
};

using namespace std::string_view_literals;

// Formats a user may hand a tool by mistake: images, models, archives, documents, programs.
constexpr Signature kSignatures[] = {
    {"PNG", "\x89PNG\r\n\x1a\n"sv},
    {"JPEG", "\xFF\xD8\xFF"sv},
    {"GIF", "GIF87a"sv},
    {"GIF", "GIF89a"sv},
    {"OpenEXR", "\x76\x2F\x31\x01"sv},
    {"TIFF", "II*\0"sv},
    {"TIFF", "MM\0*"sv},
    {"WebP", "WEBP"sv, 8},
    {"KTX2", "\xABKTX 20\xBB"sv},
    {"KTX", "\xABKTX 11\xBB"sv},
    {"DDS", "DDS "sv},
    {"Radiance HDR", "#?RADIANCE"sv},
    {"Radiance HDR", "#?RGBE"sv},
    {"GLB", "glTF"sv},
    {"Draco", "DRACO"sv},
    {"binary FBX", "Kaydara FBX Binary"sv},
    {"ZIP", "PK\x03\x04"sv},
    {"gzip", "\x1F\x8B"sv},
    {"PDF", "%PDF-"sv},
    {"ELF executable",
     "\x7F"
     "ELF"sv},
};

bool startsWith(std::span<const std::uint8_t> head, const Signature& s) {
    if (head.size() < s.offset + s.magic.size()) return false;
    for (std::size_t i = 0; i < s.magic.size(); ++i)
        if (head[s.offset + i] != static_cast<std::uint8_t>(s.magic[i])) return false;
    return true;
}

bool printable(std::uint8_t c) { return c >= 0x20 && c < 0x7F; }

}  // namespace

std::string_view fileSignatureName(std::span<const std::uint8_t> head) {
    for (const Signature& s : kSignatures)
        if (startsWith(head, s)) return s.name;
    return {};
}

std::string describeFileStart(std::span<const std::uint8_t> head) {
    if (head.empty()) return "is empty";
    if (const std::string_view name = fileSignatureName(head); !name.empty())
        return "starts with the " + std::string(name) + " signature";
    if (!printable(head[0])) {
        char text[32];
        std::snprintf(text, sizeof text, "starts with the byte 0x%02X", head[0]);
        return text;
    }
    std::string text;
    for (std::size_t i = 0; i < head.size() && i < 16 && printable(head[i]); ++i) text += static_cast<char>(head[i]);
    return "starts with the text '" + text + "'";
}

}  // namespace engine
