// SPDX-License-Identifier: MIT
#include "engine/capture/diff_image.hpp"

#include "engine/capture/compare.hpp"
#include "engine/capture/image_convert.hpp"
#include "engine/capture/image_write.hpp"
#include "engine/core/error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace engine::capture {

Image absoluteDifference(const Image& a, const Image& b, float scale) {
    if (const std::string mismatch = describeMismatch(a, b); !mismatch.empty())
        throw Error("difference image: " + mismatch);
    // Straight: a difference of alphas is not an alpha to premultiply or divide by.
    Image diff = Image::make(a.width, a.height, a.channelNames, AlphaMode::Straight);
    for (std::size_t i = 0; i < diff.pixels.size(); ++i) diff.pixels[i] = std::abs(a.pixels[i] - b.pixels[i]) * scale;
    return diff;
}

void writeDiffImage(const std::filesystem::path& path, const Image& a, const Image& b, float scale) {
    const Image diff = absoluteDifference(a, b, scale);
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    if (ext == ".png") return writePng(path, quantizeUnorm8(diff));
    if (ext == ".exr") return writeExr(path, diff, ExrPixelType::Float);
    throw Error("difference image '" + path.string() + "': unsupported extension '" + ext + "' (write .png or .exr)");
}

}  // namespace engine::capture
