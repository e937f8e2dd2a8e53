// SPDX-License-Identifier: MIT
#include "engine/capture/jpeg_metadata.hpp"

#include <algorithm>

namespace engine::capture {

namespace {

// JPEG markers (ITU T.81 Table B.1).
constexpr std::uint8_t kSoi = 0xD8, kEoi = 0xD9, kSos = 0xDA, kTem = 0x01;
constexpr std::uint8_t kRst0 = 0xD0, kRst7 = 0xD7;
constexpr std::uint8_t kApp1 = 0xE1, kApp2 = 0xE2, kApp13 = 0xED, kApp15 = 0xEF;

bool standalone(std::uint8_t marker) {
    return marker == kSoi || marker == kTem || (marker >= kRst0 && marker <= kRst7);
}

}  // namespace

bool isJpeg(std::span<const std::uint8_t> data) {
    return data.size() >= 3 && data[0] == 0xFF && data[1] == kSoi && data[2] == 0xFF;
}

std::vector<std::uint8_t> withoutJpegMetadata(std::span<const std::uint8_t> jpeg) {
    std::vector<std::uint8_t> out(jpeg.begin(), jpeg.end());
    if (!isJpeg(jpeg)) return out;
    // The walk is libjpeg's own (jdmarker.c), so it sees the segments libjpeg will see.
    std::size_t at = 2;  // after SOI
    while (at < out.size()) {
        // next_marker(): bytes that are not FF are skipped, fill FFs swallowed; FF 00 is no marker.
        while (at < out.size() && out[at] != 0xFF) ++at;
        while (at < out.size() && out[at] == 0xFF) ++at;
        if (at >= out.size()) break;
        const std::uint8_t marker = out[at];
        if (marker == 0x00 || standalone(marker)) {
            ++at;
            continue;
        }
        if (marker == kSos || marker == kEoi) break;  // OpenImageIO takes metadata from the header only
        if (at + 2 >= out.size()) break;
        if (marker == kApp1 || marker == kApp2 || marker == kApp13) out[at] = kApp15;
        // The length counts its own two bytes; skip_variable() steps over at least those.
        const std::size_t length = static_cast<std::size_t>(out[at + 1]) << 8 | out[at + 2];
        at += 1 + std::max<std::size_t>(length, 2);
    }
    return out;
}

}  // namespace engine::capture
