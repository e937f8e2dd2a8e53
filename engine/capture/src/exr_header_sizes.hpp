// SPDX-License-Identifier: MIT
#pragma once
// Private: OpenEXR 3.1 allocates a header attribute of a type it does not know at the size
// the file declares before reading it, so a 364-byte file declaring a 1.75 GiB attribute
// costs that allocation before the read fails (found by fuzz_capture_image; up to 2 GiB, the
// size is an int32). The readers walk the header first and refuse a size larger than what is
// left of the file.
#include <cstdint>
#include <istream>
#include <string>

namespace engine::capture::detail {

// `in` at the start of an EXR file of `fileSize` bytes: the first attribute (of any part's
// header) whose declared size is negative or runs past the end of the file, described
// ("header attribute 'x' of type '\x01' declares 1879048192 bytes, the file has 239 left",
// bytes outside printable ASCII spelled \xNN), or empty when there is none. A header that
// is malformed otherwise is left to OpenEXR.
std::string oversizedExrAttribute(std::istream& in, std::uint64_t fileSize);

}  // namespace engine::capture::detail
