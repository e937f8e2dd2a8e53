// SPDX-License-Identifier: MIT
#pragma once
// Fixed-function blending as data, per colour target, RGB and alpha set separately
// (D3DRS_SEPARATEALPHABLENDENABLE in [Hathaway 2010] §3.5.2, glBlendFuncSeparatei in GL).
//   result.rgb = op_rgb(src.rgb * srcFactorRgb, dst.rgb * dstFactorRgb)
//   result.a   = op_a  (src.a   * srcFactorAlpha, dst.a  * dstFactorAlpha)
// MIN and MAX ignore the factors (GL 4.5 Table 17.1).
#include <cstdint>

namespace engine::render {

enum class BlendFactor : std::uint8_t {
    Zero,
    One,
    SrcColor,
    InvSrcColor,
    SrcAlpha,
    InvSrcAlpha,
    DstColor,
    InvDstColor,
    DstAlpha,
    InvDstAlpha,
    SrcAlphaSat,  // rgb: min(src.a, 1 - dst.a); alpha: 1
    ConstantColor,
    InvConstantColor,
    ConstantAlpha,
    InvConstantAlpha,
};

enum class BlendOp : std::uint8_t { Add, Subtract, RevSubtract, Min, Max };

inline constexpr BlendFactor kAllBlendFactors[] = {BlendFactor::Zero,
                                                   BlendFactor::One,
                                                   BlendFactor::SrcColor,
                                                   BlendFactor::InvSrcColor,
                                                   BlendFactor::SrcAlpha,
                                                   BlendFactor::InvSrcAlpha,
                                                   BlendFactor::DstColor,
                                                   BlendFactor::InvDstColor,
                                                   BlendFactor::DstAlpha,
                                                   BlendFactor::InvDstAlpha,
                                                   BlendFactor::SrcAlphaSat,
                                                   BlendFactor::ConstantColor,
                                                   BlendFactor::InvConstantColor,
                                                   BlendFactor::ConstantAlpha,
                                                   BlendFactor::InvConstantAlpha};
inline constexpr BlendOp kAllBlendOps[] = {BlendOp::Add, BlendOp::Subtract, BlendOp::RevSubtract, BlendOp::Min,
                                           BlendOp::Max};

// Channel write mask bits.
enum ColorWrite : std::uint8_t { WriteR = 1, WriteG = 2, WriteB = 4, WriteA = 8, WriteRGB = 7, WriteAll = 15 };

struct BlendState {
    bool enabled = false;
    BlendFactor srcRgb = BlendFactor::One;
    BlendFactor dstRgb = BlendFactor::Zero;
    BlendOp opRgb = BlendOp::Add;
    BlendFactor srcAlpha = BlendFactor::One;
    BlendFactor dstAlpha = BlendFactor::Zero;
    BlendOp opAlpha = BlendOp::Add;
    std::uint8_t writeMask = WriteAll;

    // Blending that reproduces the source exactly: ONE/ZERO with ADD on both halves.
    bool isPlainWrite() const {
        auto plain = [](BlendFactor s, BlendFactor d, BlendOp op) {
            return op == BlendOp::Add && s == BlendFactor::One && d == BlendFactor::Zero;
        };
        return !enabled || (plain(srcRgb, dstRgb, opRgb) && plain(srcAlpha, dstAlpha, opAlpha));
    }

    // Common set-ups, named as the seeds name them.
    static BlendState opaque() { return {}; }
    // Straight-alpha "over" ([Hargreaves 2009] "conventional"), alpha accumulated as in [Turánszki 2017].
    static BlendState alphaOver() {
        return {true,
                BlendFactor::SrcAlpha,
                BlendFactor::InvSrcAlpha,
                BlendOp::Add,
                BlendFactor::One,
                BlendFactor::InvSrcAlpha,
                BlendOp::Add,
                WriteAll};
    }
    // Premultiplied "over" ([Hargreaves 2009], [Turánszki 2017] layer blend).
    static BlendState premultipliedOver() {
        return {true,         BlendFactor::One, BlendFactor::InvSrcAlpha,
                BlendOp::Add, BlendFactor::One, BlendFactor::InvSrcAlpha,
                BlendOp::Add, WriteAll};
    }
    // Straight-alpha "over" onto the colour only, the target's alpha kept (ZERO / ONE):
    // lerp(target, source, alpha), e.g. a mask composite ([Hathaway 2010] §3.5.4).
    static BlendState alphaOverKeepAlpha() {
        return {true,
                BlendFactor::SrcAlpha,
                BlendFactor::InvSrcAlpha,
                BlendOp::Add,
                BlendFactor::Zero,
                BlendFactor::One,
                BlendOp::Add,
                WriteAll};
    }
    // Every factor ONE, one operation per half: sums (ADD) and maxima (MAX) of what is drawn,
    // e.g. coverage masks ([Hathaway 2010] Table 3.1). The soft driver finds this family by its
    // factors and has a fast path for it (kernel/detail/one_one_half_blend.hpp).
    static BlendState oneOne(BlendOp rgb, BlendOp alpha) {
        return {true, BlendFactor::One, BlendFactor::One, rgb, BlendFactor::One, BlendFactor::One, alpha, WriteAll};
    }
    // RGB = MAX, A = ADD, all factors ONE: the largest colour and the summed alpha (e.g. an
    // alpha-z-buffer and a coverage sum at once, [Hathaway 2010] Table 3.1).
    static BlendState maxRgbAddAlpha() { return oneOne(BlendOp::Max, BlendOp::Add); }
};

const char* blendFactorName(BlendFactor factor);
const char* blendOpName(BlendOp op);

}  // namespace engine::render
