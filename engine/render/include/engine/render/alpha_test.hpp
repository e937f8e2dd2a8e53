// SPDX-License-Identifier: MIT
#pragma once
// Alpha test in the PS2 GS sense ([PCSX2]): a fragment whose alpha fails
// `alpha <func> reference` is not necessarily discarded whole; the fail mode says
// what it still writes. Modern APIs only know Keep (GL/D3D `discard`).
#include <cstdint>

#include "engine/render/compare_func.hpp"

namespace engine::render {

enum class AlphaFailMode : std::uint8_t {
    Keep,     // nothing written (colour, alpha and depth kept as they are) = discard
    FbOnly,   // colour and alpha written, depth not
    ZbOnly,   // depth written, colour and alpha not
    RgbOnly,  // colour written, alpha and depth not
};

inline constexpr AlphaFailMode kAllAlphaFailModes[] = {AlphaFailMode::Keep, AlphaFailMode::FbOnly,
                                                       AlphaFailMode::ZbOnly, AlphaFailMode::RgbOnly};

struct AlphaTest {
    bool enabled = false;
    CompareFunc func = CompareFunc::GreaterEqual;  // pass when alpha >= reference
    float reference = 0.5f;                        // in [0,1]
    AlphaFailMode failMode = AlphaFailMode::Keep;
    // MSAA only: the fragment covers round(alpha * samples) of its samples (ignored at 1 sample, as in GL).
    bool alphaToCoverage = false;

    bool passes(float alpha) const { return !enabled || compare(func, alpha, reference); }

    static AlphaTest off() { return {}; }
    static AlphaTest discardBelow(float ref) {
        return {true, CompareFunc::GreaterEqual, ref, AlphaFailMode::Keep, false};
    }
};

const char* alphaFailModeName(AlphaFailMode mode);

}  // namespace engine::render
