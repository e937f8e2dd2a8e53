// SPDX-License-Identifier: MIT
#include "exr_header_sizes.hpp"

#include <array>

namespace engine::capture::detail {

namespace {

// OpenEXR file layout ("Technical Introduction", File Layout): magic 76 2f 31 01, a version
// word whose bit 0x1000 marks a multi-part file, then each part's header as attributes
// (name\0 type\0 int32 size, value) ending in a 0 byte; a multi-part file ends the list of
// headers with one more 0 byte. Names are at most 255 bytes (with the long-names flag).
constexpr std::size_t kMaxName = 256;
constexpr std::uint32_t kMultiPart = 0x1000;

// A NUL-terminated string of at most kMaxName bytes; false if there is none.
bool readName(std::istream& in, std::string& name) {
    name.clear();
    for (char c; in.get(c);) {
        if (c == '\0') return true;
        if (name.size() == kMaxName) return false;
        name += c;
    }
    return false;
}

// Names from the file quoted in a message: bytes outside printable ASCII as \xNN.
std::string printable(const std::string& text) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7F) out += c;
        else out += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
    }
    return out;
}

}  // namespace

std::string oversizedExrAttribute(std::istream& in, std::uint64_t fileSize) {
    std::array<unsigned char, 8> start{};
    if (!in.read(reinterpret_cast<char*>(start.data()), start.size())) return {};
    if (start[0] != 0x76 || start[1] != 0x2F || start[2] != 0x31 || start[3] != 0x01) return {};
    const std::uint32_t flags =
        start[4] | std::uint32_t(start[5]) << 8 | std::uint32_t(start[6]) << 16 | std::uint32_t(start[7]) << 24;
    const bool multiPart = (flags & kMultiPart) != 0;
    std::string name, type;
    for (bool headerStart = true;;) {
        if (!readName(in, name)) return {};
        if (name.empty()) {
            // End of a header; in a multi-part file an empty header ends the list.
            if (!multiPart || headerStart) return {};
            headerStart = true;
            continue;
        }
        headerStart = false;
        std::array<unsigned char, 4> size{};
        if (!readName(in, type) || !in.read(reinterpret_cast<char*>(size.data()), size.size())) return {};
        const std::int32_t declared = static_cast<std::int32_t>(
            size[0] | std::uint32_t(size[1]) << 8 | std::uint32_t(size[2]) << 16 | std::uint32_t(size[3]) << 24);
        const std::uint64_t at = static_cast<std::uint64_t>(in.tellg());
        const std::uint64_t left = at <= fileSize ? fileSize - at : 0;
        if (declared < 0 || static_cast<std::uint64_t>(declared) > left)
            return "header attribute '" + printable(name) + "' of type '" + printable(type) + "' declares " +
                   std::to_string(declared) + " bytes, the file has " + std::to_string(left) + " left";
        in.seekg(declared, std::ios::cur);
    }
}

}  // namespace engine::capture::detail
