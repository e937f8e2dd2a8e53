// SPDX-License-Identifier: MIT
// Fuzz target: engine::assets::decodeImage, the in-memory PNG/JPEG decoding every glTF image
// goes through (OpenImageIO behind it). Seeds: tests/fuzz/corpus/image_decode.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "engine/assets/image.hpp"
#include "engine/core/error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Smaller caps than the default 16384 / 1 GiB: the same header checks run, but a mutated
    // header cannot make each run allocate and decode a gigabyte.
    engine::assets::ImageLimits limits;
    limits.maxDimension = 4096;
    limits.maxDecodedBytes = std::uint64_t{64} << 20;
    const std::string name = "fuzz.png";
    try {
        const engine::assets::RgbaImage image = engine::assets::decodeImage(std::span(data, size), name, limits);
        ssam::fuzz::require(image.width > 0 && image.height > 0 && image.width <= limits.maxDimension &&
                                image.height <= limits.maxDimension,
                            "decoded size " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                " is outside 1.." + std::to_string(limits.maxDimension));
        ssam::fuzz::require(
            image.pixels.size() == image.pixelCount() * 4,
            std::to_string(image.pixels.size()) + " bytes for " + std::to_string(image.pixelCount()) + " RGBA8 pixels");
    } catch (const engine::Error& e) {
        ssam::fuzz::requireMessageNames(e, name + ": ");
    }
    return 0;
}
