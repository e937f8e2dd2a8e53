// SPDX-License-Identifier: MIT
// Printable names of state enums, for errors, logs and test names.
#include "engine/render/alpha_test.hpp"
#include "engine/render/blend_state.hpp"
#include "engine/render/compare_func.hpp"
#include "engine/render/program.hpp"

namespace engine::render {

const char* compareFuncName(CompareFunc func) {
    constexpr const char* kNames[] = {"Never",   "Less",     "Equal",        "LessEqual",
                                      "Greater", "NotEqual", "GreaterEqual", "Always"};
    return kNames[static_cast<int>(func)];
}

const char* blendFactorName(BlendFactor factor) {
    constexpr const char* kNames[] = {
        "Zero",        "One",           "SrcColor",         "InvSrcColor",   "SrcAlpha",
        "InvSrcAlpha", "DstColor",      "InvDstColor",      "DstAlpha",      "InvDstAlpha",
        "SrcAlphaSat", "ConstantColor", "InvConstantColor", "ConstantAlpha", "InvConstantAlpha"};
    return kNames[static_cast<int>(factor)];
}

const char* blendOpName(BlendOp op) {
    constexpr const char* kNames[] = {"Add", "Subtract", "RevSubtract", "Min", "Max"};
    return kNames[static_cast<int>(op)];
}

const char* alphaFailModeName(AlphaFailMode mode) {
    constexpr const char* kNames[] = {"Keep", "FbOnly", "ZbOnly", "RgbOnly"};
    return kNames[static_cast<int>(mode)];
}

const char* programKindName(ProgramKind kind) {
    constexpr const char* kNames[] = {"Flat", "OpaqueLit", "MaskedLit", "AlphaOnly"};
    return kNames[static_cast<int>(kind)];
}

}  // namespace engine::render
