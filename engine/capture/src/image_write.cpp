// SPDX-License-Identifier: MIT
#include "engine/capture/image_write.hpp"

#include "engine/capture/exr_layers.hpp"
#include "engine/capture/image_convert.hpp"
#include "oiio_input.hpp"
#include "oiio_output.hpp"

#include <algorithm>
#include <cctype>

namespace engine::capture {
namespace {

// PNG has no channel names: 2 and 4 channels always mean "... + alpha last".
void requirePngLayout(const std::filesystem::path& path, const Image8& image) {
    if (image.empty()) detail::throwImageError(path, "cannot write an empty image");
    if (image.channels > 4)
        detail::throwImageError(path, "PNG holds 1 to 4 channels, image has " + std::to_string(image.channels));
    const int alphaIndex = image.alphaChannel();
    const bool needsAlphaLast = image.channels == 2 || image.channels == 4;
    if (needsAlphaLast != (alphaIndex == image.channels - 1))
        detail::throwImageError(path, "PNG stores alpha as the last of 2 or 4 channels only; image has " +
                                          std::to_string(image.channels) + " channels with alpha at index " +
                                          std::to_string(alphaIndex));
}

std::string lowercaseExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return ext;
}

}  // namespace

void writePng(const std::filesystem::path& path, const Image& image) {
    if (image.empty()) detail::throwImageError(path, "cannot write an empty image");
    writePng(path, encodeSrgbImage(image));
}

void writePng(const std::filesystem::path& path, const Image8& image) {
    requirePngLayout(path, image);
    if (image.alpha == AlphaMode::Premultiplied && image.alphaChannel() >= 0)
        detail::throwImageError(path, "PNG stores straight alpha; this 8-bit image is premultiplied");
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::UINT8);
    spec.channelnames = image.channelNames;
    spec.alpha_channel = image.alphaChannel();
    // Without this OpenImageIO assumes the data is premultiplied and divides by alpha
    // before writing, which would corrupt the straight colour we hand it.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    spec.attribute("oiio:ColorSpace", "sRGB");
    detail::writeWithOiio(path, spec, OIIO::TypeDesc::UINT8, image.pixels.data());
}

void writeExr(const std::filesystem::path& path, const Image& image, ExrPixelType type) {
    writeExrLayers(path, {Layer{"", image, type}});
}

void writeImage(const std::filesystem::path& path, const Image& image) {
    const std::string ext = lowercaseExtension(path);
    if (ext == ".png") return writePng(path, image);
    if (ext == ".exr") return writeExr(path, image);
    detail::throwImageError(path, "unsupported extension '" + ext + "' (write .png or .exr)");
}

void requireImageExtension(const std::filesystem::path& path, std::initializer_list<std::string_view> extensions) {
    const std::string ext = lowercaseExtension(path);
    std::string names;
    bool listed = false;
    for (std::string_view allowed : extensions) {
        names += (names.empty() ? "" : " or ") + std::string(allowed);
        listed = listed || ext == allowed;
    }
    if (!listed)
        detail::throwImageError(path,
                                "the name must end in " + names +
                                    (ext.empty() ? std::string(", and it has no extension") : ", not '" + ext + "'"));
    if (!detail::hasWriterFor(path))
        detail::throwImageError(path, "this OpenImageIO build has no writer for '" + ext + "' files");
}

}  // namespace engine::capture
