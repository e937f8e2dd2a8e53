#include "png_writer.hpp"

#include <cstdio>

#include <png.h>

namespace gl_embedding {

bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
    if (width <= 0 || height <= 0 || rgba.size() != std::size_t(width) * std::size_t(height) * 4) return false;
    // libpng's simplified API: one call, deflate-compressed, 8-bit straight-alpha RGBA.
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    image.format = PNG_FORMAT_RGBA;
    const bool written = png_image_write_to_file(&image, path.c_str(), 0, rgba.data(), 0, nullptr) != 0;
    if (!written) std::fprintf(stderr, "libpng: %s\n", image.message);
    png_image_free(&image);
    return written;
}

}  // namespace gl_embedding
