// SPDX-License-Identifier: MIT
#pragma once
// Backend-agnostic conformance fixture (dEQP style). The suites in tests/conformance/suites
// are written against engine::render::Backend only; each backend's conformance executable
// instantiates them with a BackendCase that says how to make that backend (see
// SSAM_INSTANTIATE_CONFORMANCE_SUITES at the end of this file).
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "draws.hpp"         // tests/support
#include "expect_error.hpp"  // tests/support
#include "engine/core/error.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/vertex.hpp"

namespace ssam::test {

namespace render = engine::render;
// The vocabulary every suite uses.
using render::AlphaFailMode;
using render::AlphaTest;
using render::BlendFactor;
using render::BlendOp;
using render::BlendState;
using render::CompareFunc;
using render::DepthState;
using render::Format;
using ssam::testing::fullscreenDraw;
using ssam::testing::meshDraw;

struct BackendCase {
    std::string name;  // a valid gtest name: letters, digits and '_'
    std::function<std::unique_ptr<render::Backend>()> make;
    // Triangles the backend dropped since creation (degenerate, NaN, clipped away), where it
    // counts them; null when it cannot say.
    std::function<std::optional<std::uint64_t>(const render::Backend&)> trianglesDropped;
};

inline void PrintTo(const BackendCase& c, std::ostream* os) { *os << c.name; }

// The case of a backend that does not count the triangles it drops (GL, Vulkan).
template <class Make>
BackendCase uncountedCase(std::string name, Make make) {
    return {std::move(name), [make] { return std::unique_ptr<render::Backend>(make()); }, {}};
}

struct BackendCaseName {
    std::string operator()(const ::testing::TestParamInfo<BackendCase>& info) const { return info.param.name; }
};

// Pixel rectangle [x0,x1) x [y0,y1) (y down, row 0 at the top) of a w x h target as two
// triangles, counter-clockwise as displayed, at clip depth z (w = 1).
inline std::vector<render::Vertex> pixelRect(int width, int height, float x0, float y0, float x1, float y1,
                                             float z = 0.5f, glm::vec4 color = glm::vec4(1.0f)) {
    auto at = [&](float x, float y) {
        render::Vertex v;
        v.position = {2.0f * x / float(width) - 1.0f, 1.0f - 2.0f * y / float(height), z};
        v.uv = {(x - x0) / (x1 - x0), (y - y0) / (y1 - y0)};  // (0,0) at the top-left corner
        v.color = color;
        return v;
    };
    const render::Vertex tl = at(x0, y0), tr = at(x1, y0), bl = at(x0, y1), br = at(x1, y1);
    return {bl, br, tr, bl, tr, tl};
}

// A vertex at pixel position (x, y) of a w x h target (NDC from pixels), clip depth z.
inline render::Vertex pixelVertex(int width, int height, double x, double y, float z = 0.5f) {
    render::Vertex v;
    v.position = {float(2.0 * x / width - 1.0), float(1.0 - 2.0 * y / height), z};
    return v;
}

// `incoming <func> stored` as the depth and alpha test suites expect it, from the outcomes
// each function accepts rather than by calling render::compare, so a wrong mapping there
// would show. Bits: 1 less, 2 equal, 4 greater, 8 unordered (a NaN: only NOTEQUAL and ALWAYS
// pass, as IEEE != does), in CompareFunc's order from Never to Always.
inline bool referenceCompare(render::CompareFunc func, float incoming, float stored) {
    constexpr std::uint8_t kAccepted[] = {0b0000, 0b0001, 0b0010, 0b0011, 0b0100, 0b1101, 0b0110, 0b1111};
    const int outcome = incoming < stored ? 1 : incoming == stored ? 2 : incoming > stored ? 4 : 8;
    return (kAccepted[std::size_t(func)] & outcome) != 0;
}

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span<const T>(v));
}

class BackendTest : public ::testing::TestWithParam<BackendCase> {
protected:
    void SetUp() override { backend_ = GetParam().make(); }
    void TearDown() override { backend_.reset(); }

    render::Backend& gfx() { return *backend_; }

    std::optional<std::uint64_t> trianglesDropped() const {
        if (!GetParam().trianglesDropped) return std::nullopt;
        return GetParam().trianglesDropped(*backend_);
    }

    render::TextureHandle renderTarget(int width, int height, render::Format format, int samples = 1,
                                       const std::string& name = "target") {
        return gfx().createTexture(render::renderTargetDesc(name, width, height, format, samples));
    }

    render::TextureHandle depthTarget(int width, int height, int samples = 1, const std::string& name = "depth") {
        return renderTarget(width, height, render::Format::D32F, samples, name);
    }

    // An RGBA8 colour target and a depth target of one size: what depth-tested suites draw into.
    struct ColorAndDepth {
        render::TextureHandle color, depth;
    };
    ColorAndDepth colorAndDepthTargets(int width, int height, int samples = 1) {
        return {renderTarget(width, height, render::Format::RGBA8_UNORM, samples), depthTarget(width, height, samples)};
    }

    // The same targets, the colour cleared to 0 and the depth to `depth` by an empty pass.
    ColorAndDepth colorAndClearedDepth(int width, int height, float depth) {
        const ColorAndDepth targets = colorAndDepthTargets(width, height);
        pass(
            targets.color, glm::vec4(0.0f), [] {}, targets.depth, depth);
        return targets;
    }

    // A pixel rectangle [x0,x1) x [y0,y1) at clip depth z (pixelRect).
    struct DepthRect {
        float x0, y0, x1, y1, z;
    };
    // A depth target of `samples` per pixel cleared to `clear`, then `rects` drawn into it in
    // order through depth function `func` (beside a scratch colour target).
    render::TextureHandle drawnDepth(int width, int height, int samples, float clear, render::CompareFunc func,
                                     std::initializer_list<DepthRect> rects) {
        const ColorAndDepth targets = colorAndDepthTargets(width, height, samples);
        const render::PipelineHandle pipeline = flatPipeline({}, render::DepthState::testAndWrite(func));
        std::vector<render::BufferHandle> quads;
        for (const DepthRect& r : rects)
            quads.push_back(vertexBuffer(pixelRect(width, height, r.x0, r.y0, r.x1, r.y1, r.z)));
        pass(
            targets.color, glm::vec4(0.0f),
            [&] {
                for (render::BufferHandle quad : quads) drawFlat(pipeline, quad, 6);
            },
            targets.depth, clear);
        return targets.depth;
    }

    // A colour and a depth target read back, in that order.
    struct ColorAndDepthReadback {
        render::Readback color, depth;
    };
    ColorAndDepthReadback readBoth(render::TextureHandle color, render::TextureHandle depth) {
        render::Readback c = gfx().readback(color);
        return {std::move(c), gfx().readback(depth)};
    }

    render::BufferHandle vertexBuffer(const std::vector<render::Vertex>& vertices,
                                      const std::string& name = "vertices") {
        render::BufferDesc desc{name, render::BufferKind::Vertex, vertices.size() * sizeof(render::Vertex)};
        return gfx().createBuffer(desc, bytesOf(vertices));
    }

    render::BufferHandle indexBuffer(const std::vector<std::uint32_t>& indices, const std::string& name = "indices") {
        render::BufferDesc desc{name, render::BufferKind::Index, indices.size() * sizeof(std::uint32_t)};
        return gfx().createBuffer(desc, bytesOf(indices));
    }

    render::PipelineHandle flatPipeline(render::BlendState blend = {}, render::DepthState depth = {},
                                        render::AlphaTest alphaTest = {}, glm::vec4 constant = glm::vec4(0.0f)) {
        render::PipelineDesc desc;
        desc.name = "flat";
        desc.program = render::ProgramKind::Flat;
        desc.blend.fill(blend);
        desc.blendConstant = constant;
        desc.depth = depth;
        desc.alphaTest = alphaTest;
        return gfx().createPipeline(desc);
    }

    // Draws `count` vertices from `first` of a non-indexed vertex buffer with the Flat program.
    void drawFlat(render::PipelineHandle pipeline, render::BufferHandle vertices, std::uint32_t count,
                  glm::vec4 color = glm::vec4(1.0f), std::uint32_t first = 0, glm::mat4 viewProj = glm::mat4(1.0f)) {
        auto d = meshDraw(pipeline, render::FlatParams{viewProj, color}, vertices, count);
        d.first = first;
        gfx().draw(d);
    }

    // One pass into a single colour target (and optionally a depth target).
    template <typename Draws>
    void pass(render::TextureHandle color, glm::vec4 clear, Draws&& draws, render::TextureHandle depth = {},
              std::optional<float> depthClear = 1.0f, bool loadColor = false) {
        render::PassDesc p;
        p.name = "test";
        p.color[0] = {color, loadColor ? render::LoadOp::Load : render::LoadOp::Clear, clear};
        if (depth)
            p.depth = {depth, depthClear ? render::LoadOp::Clear : render::LoadOp::Load, depthClear.value_or(1.0f)};
        gfx().beginPass(p);
        draws();
        gfx().endPass();
    }

    render::TextureHandle resolved(render::TextureHandle source,
                                   render::CompareFunc depthFunc = render::CompareFunc::Less,
                                   render::DepthResolve depthResolve = render::DepthResolve::Closest) {
        const render::TextureDesc& desc = gfx().describe(source);
        const render::TextureHandle destination =
            renderTarget(desc.width, desc.height, desc.format, 1, desc.name + "_resolved");
        gfx().resolve({source, destination, depthFunc, depthResolve});
        return destination;
    }

    std::unique_ptr<render::Backend> backend_;
};

using ssam::testing::expectError;

// The suites, one fixture class each so their names say what they test; listed once here
// for both their declaration and their instantiation (SSAM_INSTANTIATE_CONFORMANCE_SUITES).
// Laid out by hand (clang-format 14 cannot lay out an X-macro list stably).
// clang-format off
#define SSAM_CONFORMANCE_SUITES(X, ...)                                                                    \
    X(BlendConformance, __VA_ARGS__) X(AlphaTestConformance, __VA_ARGS__)                                 \
    X(AlphaToCoverageConformance, __VA_ARGS__) X(DepthConformance, __VA_ARGS__)                           \
    X(FillRuleConformance, __VA_ARGS__) X(ClippingConformance, __VA_ARGS__)                               \
    X(MsaaResolveConformance, __VA_ARGS__) X(TextureConformance, __VA_ARGS__)                             \
    X(RasterConformance, __VA_ARGS__) X(OcclusionQueryConformance, __VA_ARGS__)                           \
    X(ExceptionSafetyConformance, __VA_ARGS__) X(NonFiniteConformance, __VA_ARGS__)
// clang-format on

#define SSAM_DECLARE_CONFORMANCE_SUITE(suite, ...) \
    class suite : public BackendTest {};
SSAM_CONFORMANCE_SUITES(SSAM_DECLARE_CONFORMANCE_SUITE)
#undef SSAM_DECLARE_CONFORMANCE_SUITE

}  // namespace ssam::test

// Instantiates every suite for the backend cases `generator` yields (a gtest generator such
// as ::testing::Values(case...)). Use once per conformance executable.
#define SSAM_INSTANTIATE_CONFORMANCE_SUITE(suite, prefix, generator) \
    INSTANTIATE_TEST_SUITE_P(prefix, suite, generator, ::ssam::test::BackendCaseName());
#define SSAM_INSTANTIATE_CONFORMANCE_SUITES(prefix, generator) \
    SSAM_CONFORMANCE_SUITES(SSAM_INSTANTIATE_CONFORMANCE_SUITE, prefix, generator) static_assert(true)
