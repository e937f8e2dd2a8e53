// SPDX-License-Identifier: MIT
#pragma once
// One program drawn straight into a float target: the tests that read a program's output
// itself, pixel by pixel (hashed alpha's thresholds, sharpened coverage's alpha), on any
// backend. Both faces drawn, no blend, no depth; every object made is destroyed again.
#include <span>

#include "engine/render/backend.hpp"
#include "engine/render/draw_params.hpp"

namespace test_support {

inline engine::render::Readback drawProgramCard(engine::render::Backend& backend,
                                                const engine::render::ProgramDesc& programDesc,
                                                const engine::render::DrawParams& params,
                                                std::span<const engine::render::Vertex> vertices, int size) {
    using namespace engine::render;
    const auto bytes = std::as_bytes(vertices);
    const BufferHandle buffer = backend.createBuffer({"card", BufferKind::Vertex, bytes.size()}, bytes);
    const ProgramHandle program = backend.createProgram(programDesc);
    PipelineDesc p;
    p.name = programDesc.name;
    p.program = program;
    p.raster.cull = CullMode::None;
    const PipelineHandle pipeline = backend.createPipeline(p);
    const TextureHandle target = backend.createTexture(renderTargetDesc(programDesc.name, size, size, Format::RGBA32F));
    PassDesc pass;
    pass.name = programDesc.name;
    pass.color[0] = {target, LoadOp::Clear, {0, 0, 0, 0}};
    backend.beginPass(pass);
    DrawDesc d;
    d.pipeline = pipeline;
    d.params = params;
    d.vertices = buffer;
    d.count = std::uint32_t(vertices.size());
    backend.draw(d);
    backend.endPass();
    Readback r = backend.readback(target);
    backend.destroy(target);
    backend.destroy(pipeline);
    backend.destroy(program);
    backend.destroy(buffer);
    return r;
}

}  // namespace test_support
