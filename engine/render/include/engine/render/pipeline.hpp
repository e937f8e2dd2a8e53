// SPDX-License-Identifier: MIT
#pragma once
// A pipeline is a program kind plus all fixed-function state, validated and simplified
// once at creation ([PCSX2]: skip work that cannot change the result).
#include <array>
#include <string>

#include <glm/glm.hpp>

#include "engine/render/alpha_test.hpp"
#include "engine/render/blend_state.hpp"
#include "engine/render/depth_state.hpp"
#include "engine/render/format.hpp"
#include "engine/render/program.hpp"
#include "engine/render/raster_state.hpp"

namespace engine::render {

inline constexpr int kMaxColorTargets = 4;

struct PipelineDesc {
    std::string name;
    ProgramRef program;
    std::array<BlendState, kMaxColorTargets> blend{};
    glm::vec4 blendConstant{0.0f};
    DepthState depth;
    AlphaTest alphaTest;
    RasterState raster;
};

}  // namespace engine::render
