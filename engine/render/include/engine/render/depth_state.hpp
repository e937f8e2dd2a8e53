// SPDX-License-Identifier: MIT
#pragma once
// Depth test and write. Depth is a float in [0,1] (clip z in [0,w], as D3D/Vulkan and
// GL with glClipControl(ZERO_TO_ONE)); reverse-Z (near = 1, far = 0, func Greater, clear 0)
// keeps float precision over the 30 km vistas of [Hathaway 2010] §3.1.
#include "engine/render/compare_func.hpp"

namespace engine::render {

struct DepthState {
    bool test = false;
    bool write = false;
    CompareFunc func = CompareFunc::Less;

    static DepthState off() { return {}; }
    static DepthState testAndWrite(CompareFunc f = CompareFunc::Less) { return {true, true, f}; }
    static DepthState testOnly(CompareFunc f = CompareFunc::Less) { return {true, false, f}; }
};

// The sample "closest to the observer" for a given depth function: the one that would
// win the depth test ([Hathaway 2010] §3.5.1 closest-sample downsample).
constexpr bool isCloser(CompareFunc func, float a, float b) {
    switch (func) {
        case CompareFunc::Greater:
        case CompareFunc::GreaterEqual: return a > b;
        default: return a < b;
    }
}

}  // namespace engine::render
