// SPDX-License-Identifier: MIT
#include "engine/capture/image_read.hpp"

#include "engine/capture/srgb.hpp"
#include "oiio_input.hpp"

#include <cstdint>
#include <vector>

namespace engine::capture {

Image readImage(const std::filesystem::path& path, const ReadOptions& options) {
    detail::OpenedImage opened = detail::openImage(path, options, sizeof(float));
    const OIIO::ImageSpec& spec = opened.spec;
    Image image = Image::make(spec.width, spec.height, detail::channelNamesOf(spec), opened.alpha);
    const int alphaIndex = image.alphaChannel();
    const auto channels = static_cast<std::size_t>(image.channels);
    const bool decode = opened.srgbEncoded && options.linearize;
    auto isColour = [&](std::size_t i) { return static_cast<int>(i % channels) != alphaIndex; };

    if (spec.format == OIIO::TypeDesc::UINT8 && spec.channelformats.empty()) {
        // 8-bit files go through the exact decode table rather than code/255 then the curve.
        std::vector<std::uint8_t> codes(image.pixels.size());
        detail::readPixels(path, opened, OIIO::TypeDesc::UINT8, codes.data());
        for (std::size_t i = 0; i < codes.size(); ++i)
            image.pixels[i] = decode && isColour(i) ? decodeSrgb8(codes[i]) : decodeUnorm8(codes[i]);
        return image;
    }

    detail::readPixels(path, opened, OIIO::TypeDesc::FLOAT, image.pixels.data());
    if (decode)
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            if (isColour(i)) image.pixels[i] = srgbToLinear(image.pixels[i]);
    return image;
}

Image8 readImage8(const std::filesystem::path& path, const ReadOptions& options) {
    detail::OpenedImage opened = detail::openImage(path, options, sizeof(std::uint8_t));
    const OIIO::ImageSpec& spec = opened.spec;
    if (spec.format != OIIO::TypeDesc::UINT8 || !spec.channelformats.empty())
        detail::throwImageError(
            path, std::string("stores ") + spec.format.c_str() + " data, not 8-bit codes; read it with readImage");
    Image8 image = Image8::make(spec.width, spec.height, detail::channelNamesOf(spec), opened.alpha);
    detail::readPixels(path, opened, OIIO::TypeDesc::UINT8, image.pixels.data());
    return image;
}

}  // namespace engine::capture
