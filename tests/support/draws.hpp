// SPDX-License-Identifier: MIT
#pragma once
// The draws tests issue most: a pipeline, its parameters and a range of vertices, or a
// full-screen program's pipeline and parameters. Fields a test needs beyond these (indices,
// instances, a scissor) it sets on the result.
#include <cstdint>
#include <utility>

#include "engine/render/pass.hpp"

namespace ssam::testing {

// `count` vertices of `vertices` from the first, one instance.
inline engine::render::DrawDesc meshDraw(engine::render::PipelineHandle pipeline, engine::render::DrawParams params,
                                         engine::render::BufferHandle vertices, std::uint32_t count) {
    engine::render::DrawDesc d;
    d.pipeline = pipeline;
    d.params = std::move(params);
    d.vertices = vertices;
    d.count = count;
    return d;
}

// A full-screen program's draw: no vertex input.
inline engine::render::DrawDesc fullscreenDraw(engine::render::PipelineHandle pipeline,
                                               engine::render::DrawParams params) {
    engine::render::DrawDesc d;
    d.pipeline = pipeline;
    d.params = std::move(params);
    return d;
}

}  // namespace ssam::testing
