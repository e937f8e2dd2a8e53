// SPDX-License-Identifier: MIT
// RgbaImage (image.hpp), shared by the image decoders: OpenImageIO's natively
// (image_decode.cpp), stb_image's in the web page's build (image_decode_web.cpp).
#include <string>

#include "engine/assets/image.hpp"
#include "engine/core/error.hpp"

namespace engine::assets {

RgbaImage RgbaImage::make(int width, int height, render::AlphaMode alpha) {
    if (width <= 0 || height <= 0)
        throw Error("RgbaImage::make: size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is not positive");
    RgbaImage image;
    image.width = width;
    image.height = height;
    image.alpha = alpha;
    image.pixels.assign(image.pixelCount() * 4, 0);
    return image;
}

}  // namespace engine::assets
