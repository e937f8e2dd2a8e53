// SPDX-License-Identifier: MIT
#pragma once
// The draws tests issue most: a pipeline, its parameters and a range of vertices, or a
// full-screen program's pipeline and parameters. Fields a test needs beyond these (indices,
// instances, a scissor) it sets on the result. And the whole of a full-screen program's one draw.
#include <cstdint>
#include <string>
#include <utility>

#include "engine/render/backend.hpp"
#include "engine/render/pass.hpp"
#include "engine/render/pass_scope.hpp"

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

// `program` drawn full screen once into `target`, cleared to zero first, in a pass of its own
// named `name`, through a pipeline made for it and destroyed again (also when the draw throws).
inline void drawFullscreenInto(engine::render::Backend& backend, engine::render::ProgramRef program,
                               engine::render::DrawParams params, engine::render::TextureHandle target,
                               const std::string& name = "fullscreen") {
    using namespace engine::render;
    PipelineDesc pd;
    pd.name = name;
    pd.program = program;
    const PipelineHandle pipeline = backend.createPipeline(pd);
    PassDesc pass;
    pass.name = name;
    pass.color[0] = {target, LoadOp::Clear, glm::vec4(0.0f)};
    try {
        PassScope scope(backend, pass);
        backend.draw(fullscreenDraw(pipeline, std::move(params)));
        scope.end();
    } catch (...) {
        backend.destroy(pipeline);
        throw;
    }
    backend.destroy(pipeline);
}

}  // namespace ssam::testing
