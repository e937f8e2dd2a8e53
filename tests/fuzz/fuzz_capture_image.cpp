// SPDX-License-Identifier: MIT
// Fuzz target: engine::capture's image readers (readImage, readImage8, and for EXR files
// listExrLayers and readExrLayer), which ssam-idiff and the golden-image tests run on files
// they did not write. The input is written to a file whose extension matches its magic
// number (PNG, JPEG, EXR; anything else is tried as TGA, which has none), as OpenImageIO
// picks its reader by extension first. Seeds: tests/fuzz/corpus/capture_image.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include "engine/capture/exr_layers.hpp"
#include "engine/capture/image_read.hpp"
#include "engine/core/error.hpp"
#include "fuzz_support.hpp"

namespace {

const char* extensionFor(const std::uint8_t* data, std::size_t size) {
    const auto startsWith = [&](std::initializer_list<std::uint8_t> magic) {
        return size >= magic.size() && std::memcmp(data, magic.begin(), magic.size()) == 0;
    };
    if (startsWith({0x89, 'P', 'N', 'G'})) return ".png";
    if (startsWith({0xFF, 0xD8, 0xFF})) return ".jpg";
    if (startsWith({0x76, 0x2F, 0x31, 0x01})) return ".exr";
    return ".tga";
}

template <typename Picture>
void checkShape(const Picture& image, const engine::capture::ReadOptions& options, const char* reader) {
    using ssam::fuzz::require;
    const std::string what = std::string(reader) + ": ";
    require(image.width > 0 && image.height > 0 && image.width <= options.maxWidth && image.height <= options.maxHeight,
            what + "size " + std::to_string(image.width) + "x" + std::to_string(image.height) + " outside the caps");
    require(image.channels > 0 && image.channelNames.size() == static_cast<std::size_t>(image.channels),
            what + std::to_string(image.channelNames.size()) + " names for " + std::to_string(image.channels) +
                " channels");
    require(
        image.pixels.size() == image.pixelCount() * static_cast<std::size_t>(image.channels),
        what + std::to_string(image.pixels.size()) + " values for " + std::to_string(image.pixelCount()) + " pixels");
}

// One reader on the file: accepted results keep their shape, refusals name the file.
template <typename Read>
void tryReader(const std::filesystem::path& file, Read read) {
    try {
        read();
    } catch (const engine::Error& e) {
        ssam::fuzz::requireMessageNames(e, "image '" + file.string() + "': ");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path dir = [] {
        ssam::fuzz::silenceWarnings();
        return ssam::fuzz::scratchDir("capture_image");
    }();
    const std::filesystem::path file = dir / (std::string("input") + extensionFor(data, size));
    ssam::fuzz::writeInput(file, data, size);

    engine::capture::ReadOptions options;  // the same checks as the defaults, smaller caps (see image_decode)
    options.maxWidth = 4096;
    options.maxHeight = 4096;
    options.maxDecodedBytes = std::uint64_t{64} << 20;
    tryReader(file, [&] { checkShape(engine::capture::readImage(file, options), options, "readImage"); });
    tryReader(file, [&] {
        const engine::capture::Image8 image = engine::capture::readImage8(file, options);
        checkShape(image, options, "readImage8");
    });
    if (file.extension() == ".exr")
        tryReader(file, [&] {
            for (const std::string& layer : engine::capture::listExrLayers(file, options))
                checkShape(engine::capture::readExrLayer(file, layer, options), options, "readExrLayer");
        });
    std::filesystem::remove(file);  // the next input may have another extension
    return 0;
}
