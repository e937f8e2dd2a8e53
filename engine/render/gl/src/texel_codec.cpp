#include "texel_codec.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <Imath/half.h>

namespace engine::render::gl {
namespace {

struct ByteTables {
    float unorm[256];
    float srgb[256];
    ByteTables() {
        for (int i = 0; i < 256; ++i) {
            unorm[i] = static_cast<float>(i) / 255.0f;
            const double s = i / 255.0;
            srgb[i] = static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
        }
    }
};
const ByteTables& tables() {
    static const ByteTables t;
    return t;
}

float linearToSrgbExact(float l) { return l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f; }

std::uint8_t encodeUnorm8(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return static_cast<std::uint8_t>(v * 255.0f + 0.5f);
}
std::uint8_t encodeSrgb8(float linear) {
    if (!(linear > 0.0f)) return 0;
    if (linear >= 1.0f) return 255;
    return encodeUnorm8(linearToSrgbExact(linear));
}

float decodeHalf(std::uint16_t bits) {
    Imath::half h;
    h.setBits(bits);
    return static_cast<float>(h);
}
std::uint16_t encodeHalf(float v) { return Imath::half(v).bits(); }

glm::vec4 load(const std::byte* p, Format format) {
    const ByteTables& t = tables();
    auto u8 = [p](int i) { return std::to_integer<std::uint8_t>(p[i]); };
    auto h16 = [p](int i) {
        std::uint16_t bits;
        std::memcpy(&bits, p + 2 * i, 2);
        return decodeHalf(bits);
    };
    auto f32 = [p](int i) {
        float v;
        std::memcpy(&v, p + 4 * i, 4);
        return v;
    };
    switch (format) {
        case Format::RGBA8_UNORM: return {t.unorm[u8(0)], t.unorm[u8(1)], t.unorm[u8(2)], t.unorm[u8(3)]};
        case Format::RGBA8_SRGB: return {t.srgb[u8(0)], t.srgb[u8(1)], t.srgb[u8(2)], t.unorm[u8(3)]};
        case Format::R8_UNORM: return {t.unorm[u8(0)], 0.0f, 0.0f, 1.0f};
        case Format::RG8_UNORM: return {t.unorm[u8(0)], t.unorm[u8(1)], 0.0f, 1.0f};
        case Format::RGBA16F: return {h16(0), h16(1), h16(2), h16(3)};
        case Format::RG16F: return {h16(0), h16(1), 0.0f, 1.0f};
        case Format::R16F: return {h16(0), 0.0f, 0.0f, 1.0f};
        case Format::RGBA32F: return {f32(0), f32(1), f32(2), f32(3)};
        case Format::R32F:
        case Format::D32F: return {f32(0), 0.0f, 0.0f, 1.0f};
    }
    return {};
}

void store(std::byte* p, Format format, const glm::vec4& v) {
    const int channels = formatInfo(format).channels;
    for (int c = 0; c < channels; ++c) {
        switch (format) {
            case Format::RGBA8_UNORM:
            case Format::R8_UNORM:
            case Format::RG8_UNORM: p[c] = std::byte{encodeUnorm8(v[c])}; break;
            case Format::RGBA8_SRGB: p[c] = std::byte{c < 3 ? encodeSrgb8(v[c]) : encodeUnorm8(v[c])}; break;
            case Format::RGBA16F:
            case Format::RG16F:
            case Format::R16F: {
                const std::uint16_t bits = encodeHalf(v[c]);
                std::memcpy(p + 2 * c, &bits, 2);
                break;
            }
            case Format::RGBA32F:
            case Format::R32F:
            case Format::D32F: std::memcpy(p + 4 * c, &v[c], 4); break;
        }
    }
}

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
    store(out.data(), format, value);
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
            const glm::vec4 sum = load(texel(x0, y0), format) + load(texel(x1, y0), format) +
                                  load(texel(x0, y1), format) + load(texel(x1, y1), format);
            store(out.data() + (std::size_t(y) * width + x) * bpp, format, sum * 0.25f);
        }
    }
    return out;
}

}  // namespace engine::render::gl
