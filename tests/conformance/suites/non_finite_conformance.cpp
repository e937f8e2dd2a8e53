// SPDX-License-Identifier: MIT
// The non-finite rules the full-screen programs document hold on every backend alike: a
// NaN or Inf colour component read from a float target composites as 0, never as NaN
// (ssam::compositeProgram, transparency's coverage composite and WBOIT resolve).
#include <cmath>
#include <limits>
#include <vector>

#include "../backend_fixture.hpp"
#include "ssam/composite_program.hpp"
#include "transparency/programs.hpp"

namespace ssam::test {
namespace {

constexpr int kSize = 4;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const glm::vec4 kOpaque{0.1f, 0.2f, 0.3f, 1.0f};

class NonFinite {
public:
    explicit NonFinite(render::Backend& gfx) : gfx_(gfx) {}

    // A sampled float target holding `texel` at every pixel.
    render::TextureHandle filled(glm::vec4 texel, Format format = Format::RGBA32F) {
        render::TextureDesc desc;
        desc.name = "input";
        desc.width = desc.height = kSize;
        desc.format = format;
        desc.usage = render::UsageSampled | render::UsageRenderTarget;
        std::vector<float> values(std::size_t(kSize) * kSize * 4);
        for (std::size_t i = 0; i < values.size(); i += 4)
            for (int c = 0; c < 4; ++c) values[i + c] = texel[c];
        const render::TextureData data{{std::as_bytes(std::span(values))}};
        return gfx_.createTexture(desc, &data);
    }

    // The centre pixel of an RGBA32F target cleared to kOpaque after one full-screen draw.
    template <typename Params>
    glm::vec4 draw(const render::ProgramDesc& program, const Params& params, render::BlendState blend) {
        const render::TextureHandle target = filled(kOpaque);
        const render::ProgramHandle handle = gfx_.createProgram(program);
        render::PipelineDesc desc;
        desc.name = program.name;
        desc.program = handle;
        desc.blend[0] = blend;
        const render::PipelineHandle pipeline = gfx_.createPipeline(desc);
        render::PassDesc pass;
        pass.name = "non-finite";
        pass.color[0] = {target, render::LoadOp::Load};
        gfx_.beginPass(pass);
        gfx_.draw(fullscreenDraw(pipeline, params));
        gfx_.endPass();
        gfx_.destroy(pipeline);
        gfx_.destroy(handle);
        const render::Readback r = gfx_.readback(target);
        return {r.at(1, 1, 0), r.at(1, 1, 1), r.at(1, 1, 2), r.at(1, 1, 3)};
    }

private:
    render::Backend& gfx_;
};

void expectNear(glm::vec4 got, glm::vec4 expected) {
    for (int c = 0; c < 4; ++c) {
        EXPECT_TRUE(std::isfinite(got[c])) << "channel " << c;
        EXPECT_NEAR(got[c], expected[c], 1e-5f) << "channel " << c;
    }
}

const render::BlendState kAlphaOver = render::BlendState::alphaOverKeepAlpha();

// Mask MAX = ADD = 1: the foliage fully covers the pixel, so the result is its colour with
// the NaN and Inf components as 0.
TEST_P(NonFiniteConformance, SsamCompositeOutputsNonFiniteFoliageAsZero) {
    NonFinite t(gfx());
    const ssam::CompositeParams params{t.filled({kNaN, kInf, 0.5f, 1.0f}), t.filled(glm::vec4(1.0f)), {}, 0.85f, true};
    expectNear(t.draw(ssam::compositeProgram(), params, kAlphaOver), {0.0f, 0.0f, 0.5f, 1.0f});
}

TEST_P(NonFiniteConformance, CoverageCompositeOutputsNonFiniteFoliageAsZero) {
    NonFinite t(gfx());
    const transparency::CoverageCompositeParams params{
        t.filled({-kInf, kNaN, 0.25f, 1.0f}), t.filled(glm::vec4(1.0f)), {}, transparency::CoverageModel::EqualLayers};
    expectNear(t.draw(transparency::coverageCompositeProgram(), params, kAlphaOver), {0.0f, 0.0f, 0.25f, 1.0f});
}

// Accumulated (NaN, Inf, 0.5) of weight 1 and revealage 0.5: the average's non-finite
// components are 0, so the result is 0.5 * (0, 0, 0.5) + 0.5 * opaque.
TEST_P(NonFiniteConformance, WboitResolveOutputsNonFiniteAveragesAsZero) {
    NonFinite t(gfx());
    const transparency::WboitResolveParams params{t.filled({kNaN, kInf, 0.5f, 1.0f}), t.filled(glm::vec4(0.5f))};
    const render::BlendState resolve{true,
                                     render::BlendFactor::InvSrcAlpha,
                                     render::BlendFactor::SrcAlpha,
                                     render::BlendOp::Add,
                                     render::BlendFactor::Zero,
                                     render::BlendFactor::One,
                                     render::BlendOp::Add,
                                     render::WriteRGB};
    expectNear(t.draw(transparency::wboitResolveProgram(), params, resolve),
               {0.5f * kOpaque.r, 0.5f * kOpaque.g, 0.25f + 0.5f * kOpaque.b, 1.0f});
}

}  // namespace
}  // namespace ssam::test
