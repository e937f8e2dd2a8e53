// SPDX-License-Identifier: MIT
#pragma once
// clamp01: a value clamped to [0, 1] with NaN to 0 (the comparisons' order does that), as a UNORM
// store would make it. The blend unit, the rasterizer's depth and the modules' kernels all use
// this one.
#include <glm/glm.hpp>

namespace engine::render::soft {

inline float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }
inline glm::vec4 clamp01(const glm::vec4& v) { return {clamp01(v.x), clamp01(v.y), clamp01(v.z), clamp01(v.w)}; }

}  // namespace engine::render::soft
