// SPDX-License-Identifier: MIT
#pragma once
// An independent scalar reference for fixed-function blending and colour stores, written
// from the OpenGL 4.5 (Core) specification, §17.3.6 "Blending":
//   Table 17.1 (blend equations): FUNC_ADD        R = Rs*Sr + Rd*Dr
//                                 FUNC_SUBTRACT   R = Rs*Sr - Rd*Dr
//                                 FUNC_REV_SUBTRACT R = Rd*Dr - Rs*Sr
//                                 MIN             R = min(Rs, Rd)   (factors ignored)
//                                 MAX             R = max(Rs, Rd)   (factors ignored)
//   Table 17.2 (blend factors), RGB factor / alpha factor:
//     ZERO (0,0,0)/0, ONE (1,1,1)/1, SRC_COLOR (Rs,Gs,Bs)/As, ONE_MINUS_SRC_COLOR, DST_COLOR
//     (Rd,Gd,Bd)/Ad, ONE_MINUS_DST_COLOR, SRC_ALPHA As/As, ONE_MINUS_SRC_ALPHA, DST_ALPHA Ad/Ad,
//     ONE_MINUS_DST_ALPHA, CONSTANT_COLOR (Rc,Gc,Bc)/Ac, ONE_MINUS_CONSTANT_COLOR,
//     CONSTANT_ALPHA Ac/Ac, ONE_MINUS_CONSTANT_ALPHA, SRC_ALPHA_SATURATE min(As,1-Ad)/1.
// and the API rules around it:
//   * fixed-point (UNORM) colour buffers: source, destination, constant colour and factors
//     are clamped to [0,1] before the equation; the result is clamped to [0,1] and converted
//     by rounding to nearest (§2.3.5.2 "Conversion from Floating-Point to Normalized
//     Fixed-Point");
//   * sRGB buffers (§17.3.6.1, FRAMEBUFFER_SRGB on): RGB of the destination is decoded to
//     linear before blending and the RGB result is encoded after it, with the exact
//     IEC 61966-2-1 curves (§8.24 eq. 8.15 and §17.3.7 eq. 17.1); alpha is linear;
//   * floating-point buffers: nothing is clamped; RGBA16F stores round to the nearest half.
//
// Everything is computed in double so the reference has no rounding of its own that could
// line up with the implementation's. It deliberately does not include, or share any code
// with, the soft backend (engine/render/soft/src).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "engine/render/blend_state.hpp"
#include "engine/render/format.hpp"

namespace ssam::test::reference {

using Rgba = std::array<double, 4>;

inline double clamp01(double v) { return v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v); }

// --- sRGB transfer functions (exact curves) ----------------------------------------------

inline double srgbDecode(double s) { return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4); }
inline double srgbEncode(double l) { return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }

// --- IEEE binary16 --------------------------------------------------------------------------

// v rounded to the nearest binary16 value (ties to even), as a double. Overflow gives +-inf.
inline double roundToHalf(double v) {
    if (std::isnan(v) || v == 0.0) return v;
    const double magnitude = std::fabs(v);
    if (magnitude >= 65520.0) return std::copysign(INFINITY, v);  // 65504 + half an ulp rounds up
    int exponent = static_cast<int>(std::floor(std::log2(magnitude)));
    // log2 can be off by one at exact powers of two: fix the exponent so 2^e <= |v| < 2^(e+1).
    if (std::ldexp(1.0, exponent) > magnitude) --exponent;
    if (std::ldexp(1.0, exponent + 1) <= magnitude) ++exponent;
    exponent = std::max(exponent, -14);  // subnormals share the quantum of 2^-14
    const double quantum = std::ldexp(1.0, exponent - 10);
    const double steps = magnitude / quantum;  // exact: scaling by a power of two
    double rounded = std::floor(steps);
    const double fraction = steps - rounded;
    if (fraction > 0.5 || (fraction == 0.5 && std::fmod(rounded, 2.0) != 0.0)) rounded += 1.0;
    return std::copysign(rounded * quantum, v);
}

// Position of a finite binary16 value on the ordered line of all of them, so two values
// are n ULPs apart when their ordinals differ by n (+0 and -0 share ordinal 0).
inline long halfOrdinal(double h) {
    const double magnitude = std::fabs(h);
    long ordinal;
    if (magnitude < std::ldexp(1.0, -14)) {
        ordinal = static_cast<long>(magnitude / std::ldexp(1.0, -24));  // subnormal: 0..1023
    } else {
        int exponent = static_cast<int>(std::floor(std::log2(magnitude)));
        if (std::ldexp(1.0, exponent) > magnitude) --exponent;
        if (std::ldexp(1.0, exponent + 1) <= magnitude) ++exponent;
        const long mantissa = static_cast<long>(magnitude / std::ldexp(1.0, exponent - 10)) - 1024;
        ordinal = static_cast<long>(exponent + 15) * 1024 + mantissa;  // normal: 1024..
    }
    return h < 0.0 ? -ordinal : ordinal;
}

// --- What a colour buffer holds ------------------------------------------------------------

enum class TargetClass { Unorm8, Srgb8, Float16, Float32 };

inline TargetClass targetClass(engine::render::Format format) {
    using engine::render::Format;
    switch (format) {
        case Format::RGBA8_SRGB: return TargetClass::Srgb8;
        case Format::RGBA16F:
        case Format::RG16F:
        case Format::R16F: return TargetClass::Float16;
        case Format::RGBA32F:
        case Format::R32F:
        case Format::D32F: return TargetClass::Float32;
        default: return TargetClass::Unorm8;
    }
}

// Round-to-nearest UNORM8 code of a value already clamped to [0,1].
inline int unormCode(double v) { return static_cast<int>(std::floor(clamp01(v) * 255.0 + 0.5)); }

// One channel of a *linear* value as the buffer stores it, in the readback domain
// (UNORM/sRGB: code/255, sRGB not decoded; float: the stored value).
inline double storeChannel(TargetClass target, int channel, double linear) {
    switch (target) {
        case TargetClass::Unorm8: return unormCode(linear) / 255.0;
        case TargetClass::Srgb8:
            return channel < 3 ? unormCode(srgbEncode(clamp01(linear))) / 255.0 : unormCode(linear) / 255.0;
        case TargetClass::Float16: return roundToHalf(linear);
        case TargetClass::Float32: return static_cast<double>(static_cast<float>(linear));
    }
    return linear;
}

inline Rgba store(engine::render::Format format, const Rgba& linear) {
    const TargetClass target = targetClass(format);
    return {storeChannel(target, 0, linear[0]), storeChannel(target, 1, linear[1]), storeChannel(target, 2, linear[2]),
            storeChannel(target, 3, linear[3])};
}

// A stored value (readback domain) as blending sees it: sRGB RGB decoded, the rest as is.
inline Rgba load(engine::render::Format format, const Rgba& stored) {
    if (targetClass(format) != TargetClass::Srgb8) return stored;
    return {srgbDecode(stored[0]), srgbDecode(stored[1]), srgbDecode(stored[2]), stored[3]};
}

// --- Blending (Tables 17.1 and 17.2) -------------------------------------------------------

// The factor a BlendFactor gives for one channel (0..2: RGB, 3: alpha), Table 17.2.
inline double blendFactor(engine::render::BlendFactor factor, int channel, const Rgba& s, const Rgba& d,
                          const Rgba& c) {
    using engine::render::BlendFactor;
    const bool alpha = channel == 3;
    switch (factor) {
        case BlendFactor::Zero: return 0.0;
        case BlendFactor::One: return 1.0;
        case BlendFactor::SrcColor: return s[channel];
        case BlendFactor::InvSrcColor: return 1.0 - s[channel];
        case BlendFactor::SrcAlpha: return s[3];
        case BlendFactor::InvSrcAlpha: return 1.0 - s[3];
        case BlendFactor::DstColor: return d[channel];
        case BlendFactor::InvDstColor: return 1.0 - d[channel];
        case BlendFactor::DstAlpha: return d[3];
        case BlendFactor::InvDstAlpha: return 1.0 - d[3];
        case BlendFactor::SrcAlphaSat: return alpha ? 1.0 : std::min(s[3], 1.0 - d[3]);
        case BlendFactor::ConstantColor: return c[channel];
        case BlendFactor::InvConstantColor: return 1.0 - c[channel];
        case BlendFactor::ConstantAlpha: return c[3];
        case BlendFactor::InvConstantAlpha: return 1.0 - c[3];
    }
    std::abort();
}

// Table 17.1.
inline double blendEquation(engine::render::BlendOp op, double source, double sourceFactor, double destination,
                            double destinationFactor) {
    using engine::render::BlendOp;
    switch (op) {
        case BlendOp::Add: return source * sourceFactor + destination * destinationFactor;
        case BlendOp::Subtract: return source * sourceFactor - destination * destinationFactor;
        case BlendOp::RevSubtract: return destination * destinationFactor - source * sourceFactor;
        case BlendOp::Min: return std::min(source, destination);
        case BlendOp::Max: return std::max(source, destination);
    }
    std::abort();
}

// The linear (unstored) result of blending a linear source over a linear destination in a
// buffer of the given class: clamping applied for fixed-point buffers, no store rounding.
inline Rgba blendLinear(const engine::render::BlendState& state, Rgba s, Rgba d, Rgba c, TargetClass target) {
    const bool fixedPoint = target == TargetClass::Unorm8 || target == TargetClass::Srgb8;
    if (fixedPoint) {
        for (int i = 0; i < 4; ++i) {
            s[i] = clamp01(s[i]);
            d[i] = clamp01(d[i]);
            c[i] = clamp01(c[i]);
        }
    }
    if (!state.enabled) return s;
    Rgba result{};
    for (int i = 0; i < 4; ++i) {
        const bool alpha = i == 3;
        double sf = blendFactor(alpha ? state.srcAlpha : state.srcRgb, i, s, d, c);
        double df = blendFactor(alpha ? state.dstAlpha : state.dstRgb, i, s, d, c);
        if (fixedPoint) sf = clamp01(sf), df = clamp01(df);
        result[i] = blendEquation(alpha ? state.opAlpha : state.opRgb, s[i], sf, d[i], df);
        if (fixedPoint) result[i] = clamp01(result[i]);
    }
    return result;
}

// What the buffer holds after one fragment with linear colour `source` is blended into a
// pixel that held `destinationStored` (readback domain: sRGB codes not decoded), with the
// channel write mask applied. The result is in the readback domain too.
inline Rgba blendStored(const engine::render::BlendState& state, const Rgba& source, const Rgba& destinationStored,
                        const Rgba& constant, engine::render::Format format) {
    const TargetClass target = targetClass(format);
    const Rgba linear = blendLinear(state, source, load(format, destinationStored), constant, target);
    const Rgba stored = store(format, linear);
    Rgba out = destinationStored;
    for (int i = 0; i < 4; ++i)
        if (state.writeMask & (1u << i)) out[i] = stored[i];
    return out;
}

// --- Tolerances ----------------------------------------------------------------------------

// Whether `actual` (readback domain) matches `expected`: UNORM/sRGB within one code,
// RGBA16F within one ULP of half, RGBA32F within 1e-6 relative (1e-6 absolute near 0).
inline bool matches(engine::render::Format format, double expected, double actual) {
    switch (targetClass(format)) {
        case TargetClass::Unorm8:
        case TargetClass::Srgb8:
            return std::abs(static_cast<long>(std::lround(expected * 255.0)) -
                            static_cast<long>(std::lround(actual * 255.0))) <= 1;
        case TargetClass::Float16:
            if (!std::isfinite(expected) || !std::isfinite(actual)) return expected == actual;
            return std::abs(halfOrdinal(expected) - halfOrdinal(actual)) <= 1;
        case TargetClass::Float32: return std::fabs(expected - actual) <= std::max(1e-6, 1e-6 * std::fabs(expected));
    }
    return false;
}

inline std::string describe(const Rgba& v) {
    std::ostringstream out;
    out.precision(9);
    out << "(" << v[0] << ", " << v[1] << ", " << v[2] << ", " << v[3] << ")";
    return out.str();
}

}  // namespace ssam::test::reference
