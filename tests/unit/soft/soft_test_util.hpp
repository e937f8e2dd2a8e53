// SPDX-License-Identifier: MIT
#pragma once
// Small helpers shared by the soft backend's unit tests.
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "draws.hpp"         // tests/support
#include "expect_error.hpp"  // tests/support
#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/render/vertex.hpp"

namespace ssam::test::soft {

namespace render = engine::render;
// The vocabulary every soft test uses.
using render::AlphaFailMode;
using render::BlendFactor;
using render::BlendState;
using render::CompareFunc;
using render::Format;
using engine::render::soft::createSoftBackend;
using engine::render::soft::softDriver;
using engine::render::soft::SoftOptions;
using ssam::testing::fullscreenDraw;
using ssam::testing::meshDraw;

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span<const T>(v));
}

inline render::TextureHandle makeTarget(render::Backend& gfx, int width, int height,
                                        render::Format format = render::Format::RGBA8_UNORM, int samples = 1,
                                        const std::string& name = "target") {
    return gfx.createTexture(render::renderTargetDesc(name, width, height, format, samples));
}

inline render::BufferHandle makeVertices(render::Backend& gfx, const std::vector<render::Vertex>& v,
                                         const std::string& name = "vertices") {
    return gfx.createBuffer({name, render::BufferKind::Vertex, v.size() * sizeof(render::Vertex)}, bytesOf(v));
}

inline render::BufferHandle makeIndices(render::Backend& gfx, const std::vector<std::uint32_t>& v,
                                        const std::string& name = "indices") {
    return gfx.createBuffer({name, render::BufferKind::Index, v.size() * sizeof(std::uint32_t)}, bytesOf(v));
}

// `count` random triangles in front of a camera at the origin looking down -z: centres at x, y in
// [-1.2, 1.2], z in [-5, -2], vertices within `size` of the centre on each axis, each vertex its own
// colour (so the colour planes of a wrong set-up would show in a float target).
inline std::vector<render::Vertex> randomTriangles(std::uint32_t count, std::uint32_t seed, float size) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), side(-1.2f, 1.2f);
    std::vector<render::Vertex> v(std::size_t(count) * 3);
    for (std::size_t t = 0; t < count; ++t) {
        const glm::vec3 centre(side(random), side(random), -2.0f - 3.0f * unit(random));
        for (std::size_t k = 0; k < 3; ++k) {
            render::Vertex& p = v[t * 3 + k];
            p.position = centre + glm::vec3(side(random), side(random), side(random)) * size;
            p.color = {unit(random), unit(random), unit(random), 1.0f};
        }
    }
    return v;
}

// The full target as two triangles (NDC), at depth z, colour white.
inline std::vector<render::Vertex> fullQuad(float z = 0.5f) {
    auto at = [z](float x, float y) {
        render::Vertex v;
        v.position = {x, y, z};
        v.uv = {(x + 1.0f) * 0.5f, (1.0f - y) * 0.5f};
        return v;
    };
    return {at(-1, -1), at(1, -1), at(1, 1), at(-1, -1), at(1, 1), at(-1, 1)};
}

inline render::DrawDesc flatDraw(render::PipelineHandle pipeline, render::BufferHandle vertices, std::uint32_t count,
                                 glm::vec4 color = glm::vec4(1.0f)) {
    return meshDraw(pipeline, render::FlatParams{glm::mat4(1.0f), color}, vertices, count);
}

inline render::PassDesc onePass(render::TextureHandle color, render::TextureHandle depth = {},
                                const std::string& name = "pass") {
    render::PassDesc p;
    p.name = name;
    p.color[0] = {color, render::LoadOp::Clear, glm::vec4(0.0f)};
    if (depth) p.depth = {depth, render::LoadOp::Clear, 1.0f};
    return p;
}

inline render::PipelineDesc pipelineDesc(const std::string& name,
                                         render::ProgramRef program = render::ProgramKind::Flat) {
    render::PipelineDesc d;
    d.name = name;
    d.program = program;
    return d;
}

using ssam::testing::expectError;

}  // namespace ssam::test::soft
