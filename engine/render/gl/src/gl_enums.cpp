// SPDX-License-Identifier: MIT
#include "gl_enums.hpp"

namespace engine::render::gl {

GlFormat glFormat(Format format) {
    switch (format) {
        case Format::RGBA8_UNORM: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
        case Format::RGBA8_SRGB: return {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
        case Format::R8_UNORM: return {GL_R8, GL_RED, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
        case Format::RG8_UNORM: return {GL_RG8, GL_RG, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
        case Format::RGBA16F: return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, GL_FLOAT};
        case Format::RG16F: return {GL_RG16F, GL_RG, GL_HALF_FLOAT, GL_FLOAT};
        case Format::R16F: return {GL_R16F, GL_RED, GL_HALF_FLOAT, GL_FLOAT};
        case Format::RGBA32F: return {GL_RGBA32F, GL_RGBA, GL_FLOAT, GL_FLOAT};
        case Format::R32F: return {GL_R32F, GL_RED, GL_FLOAT, GL_FLOAT};
        case Format::D32F: return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, GL_FLOAT};
    }
    return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE};
}

// GL 4.5 Table 17.2. SRC_ALPHA_SATURATE is (f, f, f, 1) with f = min(As, 1 - Ad): the same
// as BlendFactor::SrcAlphaSat, whose alpha factor is 1 too; GL 4.x accepts it for the
// destination as well, so every factor maps directly.
GLenum glBlendFactor(BlendFactor factor) {
    switch (factor) {
        case BlendFactor::Zero: return GL_ZERO;
        case BlendFactor::One: return GL_ONE;
        case BlendFactor::SrcColor: return GL_SRC_COLOR;
        case BlendFactor::InvSrcColor: return GL_ONE_MINUS_SRC_COLOR;
        case BlendFactor::SrcAlpha: return GL_SRC_ALPHA;
        case BlendFactor::InvSrcAlpha: return GL_ONE_MINUS_SRC_ALPHA;
        case BlendFactor::DstColor: return GL_DST_COLOR;
        case BlendFactor::InvDstColor: return GL_ONE_MINUS_DST_COLOR;
        case BlendFactor::DstAlpha: return GL_DST_ALPHA;
        case BlendFactor::InvDstAlpha: return GL_ONE_MINUS_DST_ALPHA;
        case BlendFactor::SrcAlphaSat: return GL_SRC_ALPHA_SATURATE;
        case BlendFactor::ConstantColor: return GL_CONSTANT_COLOR;
        case BlendFactor::InvConstantColor: return GL_ONE_MINUS_CONSTANT_COLOR;
        case BlendFactor::ConstantAlpha: return GL_CONSTANT_ALPHA;
        case BlendFactor::InvConstantAlpha: return GL_ONE_MINUS_CONSTANT_ALPHA;
    }
    return GL_ONE;
}

GLenum glBlendOp(BlendOp op) {
    switch (op) {
        case BlendOp::Add: return GL_FUNC_ADD;
        case BlendOp::Subtract: return GL_FUNC_SUBTRACT;
        case BlendOp::RevSubtract: return GL_FUNC_REVERSE_SUBTRACT;
        case BlendOp::Min: return GL_MIN;
        case BlendOp::Max: return GL_MAX;
    }
    return GL_FUNC_ADD;
}

static_assert(glCompareFunc(CompareFunc::Never) == GL_NEVER && glCompareFunc(CompareFunc::Less) == GL_LESS &&
                  glCompareFunc(CompareFunc::Equal) == GL_EQUAL && glCompareFunc(CompareFunc::LessEqual) == GL_LEQUAL &&
                  glCompareFunc(CompareFunc::Greater) == GL_GREATER &&
                  glCompareFunc(CompareFunc::NotEqual) == GL_NOTEQUAL &&
                  glCompareFunc(CompareFunc::GreaterEqual) == GL_GEQUAL &&
                  glCompareFunc(CompareFunc::Always) == GL_ALWAYS,
              "CompareFunc is in GL's order");

GLenum glCompare(CompareFunc func) { return glCompareFunc(func); }

GLenum glWrap(AddressMode mode) {
    switch (mode) {
        case AddressMode::Wrap: return GL_REPEAT;
        case AddressMode::Clamp: return GL_CLAMP_TO_EDGE;
        case AddressMode::Mirror: return GL_MIRRORED_REPEAT;
    }
    return GL_REPEAT;
}

}  // namespace engine::render::gl
