// SPDX-License-Identifier: MIT
#pragma once
// Conversion between stored texels and the float values blending and shading work on,
// following the API rules (GL 4.5 §2.3.5, §17.3.6.3; Vulkan "Conversion"):
// UNORM stores clamp to [0,1] and round to nearest, NaN stores as 0; sRGB decodes on load
// and encodes on store; 16-bit float rounds to nearest even (Imath); 32-bit float is raw.
#include <cmath>
#include <cstdint>
#include <cstring>

#include <Imath/half.h>
#include <glm/glm.hpp>

#include "engine/render/format.hpp"

namespace engine::render {

// IEC 61966-2-1 curves, exact formulas.
inline float srgbToLinearExact(float s) { return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f); }
inline float linearToSrgbExact(float l) {
    return l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f;
}

// Decoded value of each 8-bit code: code/255 for UNORM, the sRGB curve of it for sRGB.
struct ByteTables {
    float unorm[256];
    float srgb[256];
    ByteTables();
};
const ByteTables& byteTables();

inline std::uint8_t encodeUnorm8(float v) {
    if (!(v > 0.0f)) return 0;  // also NaN -> 0
    if (v >= 1.0f) return 255;
    // v * 255 is in (0, 255) here, never negative: + 0.5 and truncation round half up.
    return static_cast<std::uint8_t>(v * 255.0f + 0.5f);  // NOLINT(bugprone-incorrect-roundings)
}

// sRGB encode of a linear value. The exact curve, then UNORM rounding.
inline std::uint8_t encodeSrgb8Exact(float linear) {
    if (!(linear > 0.0f)) return 0;
    if (linear >= 1.0f) return 255;
    return encodeUnorm8(linearToSrgbExact(linear));
}

// encodeSrgb8Exact without the pow per call. It is a non-decreasing step function of the
// float, so it is fixed by the 255 floats where it steps: threshold[k] is the least float
// it encodes to k or more. `start` holds the code at the least float of each bucket of
// 2^16 consecutive float bit patterns in [0, 1]; no bucket holds more than one step
// (`maxBucketSteps`, counted when the tables are made and checked by the tests), so one
// comparison finishes the code, with no loop and no branch: the colour writes of every
// sRGB target call this three times a pixel, and the loop's exit, as unpredictable as the
// colour, was a mispredicted branch per channel. Equality with encodeSrgb8Exact for every
// float in (0, 1) was checked exhaustively.
inline constexpr int kSrgbEncodeBuckets = 0x3F81;  // through 1.0f's bucket (0x3F800000 >> 16)
struct SrgbEncodeTables {
    float threshold[257];  // [0] unused; [256] = +infinity, never reached
    std::uint8_t start[kSrgbEncodeBuckets];
    int maxBucketSteps = 0;  // the most steps within one bucket
    SrgbEncodeTables();
};
// Defined here so the encode below inlines whole; the tables are made in pixel_codec.cpp.
inline const SrgbEncodeTables& srgbEncodeTables() {
    static const SrgbEncodeTables tables;
    return tables;
}

inline std::uint8_t encodeSrgb8(float linear) {
    // Clamped to [0, 1], NaN to 0, as two compare-selects (maxss/minss), no branch.
    float clamped = linear > 0.0f ? linear : 0.0f;
    clamped = clamped < 1.0f ? clamped : 1.0f;
    const SrgbEncodeTables& t = srgbEncodeTables();
    std::uint32_t bits;
    std::memcpy(&bits, &clamped, sizeof bits);
    const unsigned code = t.start[bits >> 16];
    return static_cast<std::uint8_t>(code + unsigned(clamped >= t.threshold[code + 1]));
}

inline float decodeHalf(std::uint16_t bits) {
    Imath::half h;
    h.setBits(bits);
    return static_cast<float>(h);
}
inline std::uint16_t encodeHalf(float v) { return Imath::half(v).bits(); }

// Callers pass a buffer sized for their own format; once inlined, GCC 12 at -O3 also sees the
// other formats' branches read or write past it and warns (-Warray-bounds,
// -Wstringop-overflow), in our code and in a consumer's. The branches never run for that format.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#endif
// Reads sample `p` of the given format as RGBA with the GL defaults for missing
// channels (0, 0, 1): R8 loads as (r, 0, 0, 1). sRGB colour channels come out linear.
inline glm::vec4 loadTexel(const std::byte* p, Format format) {
    const ByteTables& t = byteTables();
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

// Writes the channels of `v` selected by `writeMask` (bit 0 = R ... bit 3 = A); channels the
// format lacks or the mask excludes keep their stored bits untouched.
inline void storeTexel(std::byte* p, Format format, const glm::vec4& v, std::uint8_t writeMask) {
    const int channels = formatInfo(format).channels;
    for (int c = 0; c < channels; ++c) {
        if (!(writeMask & (1u << c))) continue;
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

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// The value a store followed by a load would give (what the target really holds).
inline glm::vec4 quantize(const glm::vec4& v, Format format) {
    std::byte tmp[16] = {};
    storeTexel(tmp, format, v, 0xF);
    glm::vec4 q = loadTexel(tmp, format);
    return q;
}

}  // namespace engine::render
