// SPDX-License-Identifier: MIT
// Decoding glTF images held in memory through OpenImageIO. engine_capture reads image
// *files*; glTF images also come from data: URIs and GLB bufferViews, so every image (external
// files too, after a confined read) goes through this one in-memory path, with one set of
// limits and one channel expansion to RGBA8.
#include "engine/assets/image.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstring>

#include "engine/capture/jpeg_metadata.hpp"
#include "engine/core/error.hpp"
#include "engine/core/file_signature.hpp"

namespace engine::assets {

namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what, std::string detail = {}) {
    while (!detail.empty() && std::isspace(static_cast<unsigned char>(detail.back()))) detail.pop_back();
    throw Error(name + ": " + what + (detail.empty() ? "" : ": " + detail));
}

// glTF 2.0 §3.8.1: images are PNG or JPEG (other formats only through extensions, which we do
// not support). The file name's extension is what tells OpenImageIO which reader to use.
const char* formatOf(std::span<const std::uint8_t> data) {
    static constexpr std::uint8_t kPng[] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    static constexpr std::uint8_t kJpeg[] = {0xFF, 0xD8, 0xFF};
    if (data.size() >= sizeof kPng && std::memcmp(data.data(), kPng, sizeof kPng) == 0) return "image.png";
    if (data.size() >= sizeof kJpeg && std::memcmp(data.data(), kJpeg, sizeof kJpeg) == 0) return "image.jpg";
    return nullptr;
}

}  // namespace

RgbaImage decodeImage(std::span<const std::uint8_t> encoded, const std::string& name, const ImageLimits& limits) {
    if (encoded.empty()) fail(name, "empty image data");
    const char* format = formatOf(encoded);
    if (!format)
        fail(name, "not a PNG or JPEG image (glTF 2.0 images must be one of these): it " + describeFileStart(encoded));

    // OpenImageIO never sees JPEG metadata: its parser trusts lengths inside it (jpeg_metadata.hpp).
    std::vector<std::uint8_t> jpeg;
    if (std::strcmp(format, "image.jpg") == 0) {
        jpeg = capture::withoutJpegMetadata(encoded);
        encoded = jpeg;
    }
    OIIO::Filesystem::IOMemReader reader(encoded.data(), encoded.size());
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // keep PNG's straight alpha as stored
    // OpenImageIO 2.4 ignores open()'s ioproxy argument once a config is given; the proxy
    // must travel in the config as "oiio:ioproxy".
    void* proxy = &reader;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto input = OIIO::ImageInput::open(format, &config);
    if (!input) fail(name, "cannot decode the image", OIIO::geterror());
    const OIIO::ImageSpec spec = input->spec();

    // The caps, from the header, before any pixel is allocated.
    const std::string size = std::to_string(spec.width) + "x" + std::to_string(spec.height);
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) fail(name, "zero-size image (" + size + ")");
    if (spec.depth > 1 || spec.deep) fail(name, "volume and deep images are not supported");
    if (spec.width > limits.maxDimension || spec.height > limits.maxDimension)
        fail(name, "image is " + size + ", over the size cap of " + std::to_string(limits.maxDimension) + "x" +
                       std::to_string(limits.maxDimension));
    const std::uint64_t texels = static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height);
    const std::uint64_t channels = static_cast<std::uint64_t>(std::max(spec.nchannels, 4));
    if (texels * channels > limits.maxDecodedBytes)
        fail(name, "image is " + size + ", " + std::to_string(texels * channels) + " bytes decoded, over the cap of " +
                       std::to_string(limits.maxDecodedBytes) + " bytes");

    const int nch = spec.nchannels;
    std::vector<std::uint8_t> stored(static_cast<std::size_t>(texels) * static_cast<std::size_t>(nch));
    if (!input->read_image(0, 0, 0, nch, OIIO::TypeDesc::UINT8, stored.data())) {
        std::string message = input->geterror();
        if (message.empty()) message = OIIO::geterror();
        fail(name, "cannot read the pixels (truncated or corrupt image?)", message);
    }

    // Grey -> RGB, a missing alpha -> opaque; more than 4 channels: RGB + the alpha channel.
    const int alpha = spec.alpha_channel >= 0 ? spec.alpha_channel : (nch == 2 ? 1 : nch >= 4 ? 3 : -1);
    RgbaImage image = RgbaImage::make(spec.width, spec.height, render::AlphaMode::Straight);
    for (std::size_t t = 0; t < texels; ++t) {
        const std::uint8_t* src = stored.data() + t * static_cast<std::size_t>(nch);
        std::uint8_t* dst = image.pixels.data() + t * 4;
        if (nch <= 2) {
            dst[0] = dst[1] = dst[2] = src[0];
        } else {
            dst[0] = src[0];
            dst[1] = src[1];
            dst[2] = src[2];
        }
        dst[3] = alpha >= 0 && alpha < nch ? src[alpha] : 255;
    }
    return image;
}

}  // namespace engine::assets
