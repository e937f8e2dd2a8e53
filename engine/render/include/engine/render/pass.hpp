// SPDX-License-Identifier: MIT
#pragma once
// A render pass: the targets drawn into, how they start (load or clear), and draws.
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "engine/render/draw_params.hpp"
#include "engine/render/handles.hpp"
#include "engine/render/pipeline.hpp"
#include "engine/render/program.hpp"
#include "engine/render/raster_state.hpp"

namespace engine::render {

enum class LoadOp : std::uint8_t { Load, Clear };

struct ColorAttachment {
    TextureHandle texture;
    LoadOp load = LoadOp::Clear;
    glm::vec4 clear{0.0f};
};

struct DepthAttachment {
    TextureHandle texture;
    LoadOp load = LoadOp::Clear;
    float clear = 1.0f;  // 0 for reverse-Z
};

struct PassDesc {
    std::string name;
    std::array<ColorAttachment, kMaxColorTargets> color{};
    DepthAttachment depth;
    // Occlusion query (GL_ANY_SAMPLES_PASSED): records whether any sample of the pass's draws
    // passed the depth test. Its draws may not alpha test: soft counts a pixel before its
    // alpha test and GL after the discard, which agree only when nothing is discarded.
    QueryHandle countSamplesInto;
    // Conditional rendering: the pass's draws are skipped when the last pass that counted
    // into this query found no sample (clears still happen). The backend decides where the
    // draws run (GL: glBeginConditionalRender, GL_QUERY_WAIT), so the CPU never waits for it.
    QueryHandle drawOnlyIfSamplesIn;
};

struct DrawDesc {
    PipelineHandle pipeline;
    DrawParams params;        // the program's parameter struct
    BufferHandle vertices;    // Vertex[]; unused by full-screen programs
    BufferHandle indices;     // uint32 indices; null: non-indexed
    std::uint32_t first = 0;  // first index (or vertex when non-indexed)
    std::uint32_t count = 0;  // index (or vertex) count, a multiple of 3
    BufferHandle instances;   // Instance[]; null: one instance with the identity transform
    std::uint32_t instanceCount = 1;
    std::optional<Rect> scissor;
};

}  // namespace engine::render
