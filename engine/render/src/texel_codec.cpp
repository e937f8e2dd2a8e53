// SPDX-License-Identifier: MIT
#include "engine/render/texel_codec.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/render/pixel_codec.hpp"

namespace engine::render {
namespace {

bool isHalf(Format f) { return f == Format::RGBA16F || f == Format::RG16F || f == Format::R16F; }

}  // namespace

int storedBytesPerPixel(Format format) { return formatInfo(format).bytesPerPixel; }

std::vector<std::byte> toStored(Format format, std::span<const std::byte> level, std::size_t pixels) {
    if (!isHalf(format)) return {level.begin(), level.end()};
    const std::size_t values = pixels * formatInfo(format).channels;
    std::vector<std::byte> out(values * 2);
    for (std::size_t i = 0; i < values; ++i) {
        float f;
        std::memcpy(&f, level.data() + 4 * i, 4);
        const std::uint16_t bits = encodeHalf(f);
        std::memcpy(out.data() + 2 * i, &bits, 2);
    }
    return out;
}

std::vector<std::byte> encodeTexel(Format format, const glm::vec4& value) {
    std::vector<std::byte> out(std::size_t(storedBytesPerPixel(format)));
    storeTexel(out.data(), format, value, 0xF);
    return out;
}

std::vector<std::byte> generateMip(Format format, std::span<const std::byte> above, int aboveWidth, int aboveHeight,
                                   int width, int height) {
    const int bpp = storedBytesPerPixel(format);
    std::vector<std::byte> out(std::size_t(width) * height * bpp);
    auto texel = [&](int x, int y) { return above.data() + (std::size_t(y) * aboveWidth + x) * bpp; };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int x0 = std::min(2 * x, aboveWidth - 1), x1 = std::min(2 * x + 1, aboveWidth - 1);
            const int y0 = std::min(2 * y, aboveHeight - 1), y1 = std::min(2 * y + 1, aboveHeight - 1);
            const glm::vec4 sum = loadTexel(texel(x0, y0), format) + loadTexel(texel(x1, y0), format) +
                                  loadTexel(texel(x0, y1), format) + loadTexel(texel(x1, y1), format);
            storeTexel(out.data() + (std::size_t(y) * width + x) * bpp, format, sum * 0.25f, 0xF);
        }
    }
    return out;
}

}  // namespace engine::render
