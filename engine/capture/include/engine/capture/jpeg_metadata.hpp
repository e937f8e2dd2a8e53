// SPDX-License-Identifier: MIT
#pragma once
// JPEG files with their metadata segments hidden from OpenImageIO. Its JPEG reader (2.4)
// parses the segments it keeps (APP1 Exif and XMP, APP2 ICC profile, APP13 Photoshop IPTC)
// trusting lengths written inside them: an IPTC block that claims more bytes than its
// segment holds is read past the end of a heap buffer (found by tests/fuzz, fuzz_image_decode,
// reproducer corpus/image_decode/regress_jpeg_iptc_size_past_segment.jpg). Nothing in the
// engine uses that metadata, so every reader of JPEG data (engine::assets::decodeImage,
// engine::capture::readImage) passes the bytes through here first.
#include <cstdint>
#include <span>
#include <vector>

namespace engine::capture {

// True for data starting with the JPEG SOI marker and a segment marker (FF D8 FF).
bool isJpeg(std::span<const std::uint8_t> data);

// A copy of `jpeg` in which the APP1, APP2 and APP13 segments before the first scan are
// renamed APP15: libjpeg skips those by their segment length, which it checks itself, and
// OpenImageIO never looks inside them. Pixels decode exactly as before. Malformed structure
// is left as it is, for libjpeg to report.
std::vector<std::uint8_t> withoutJpegMetadata(std::span<const std::uint8_t> jpeg);

}  // namespace engine::capture
