// SPDX-License-Identifier: MIT
// Blend conformance: every RGB (src, dst) factor pair x every alpha (src, dst) factor pair x
// every (RGB op, alpha op) pair x the four colour formats, against the scalar reference in
// reference_blend.hpp (GL 4.5 §17.3.6). Also per-channel write masks.
//
// One combination is one pass into four 4x4 targets of one format, each cleared to its own
// destination value, with four 2x2 quadrants each drawn with its own source colour. So every
// combination checks 16 (source, destination) pairs: sources and destinations outside
// [0,1] (which UNORM/sRGB must clamp and float must not) and alphas that are neither 0 nor 1.
#include <cstdint>
#include <iostream>
#include <sstream>

#include "../backend_fixture.hpp"
#include "../reference_blend.hpp"

namespace ssam::test {
namespace {

namespace ref = reference;

constexpr int kSize = 4;
constexpr int kTargets = 4;

// Linear source colours, one per 2x2 quadrant (quadrant q: x in [2(q%2), +2), y in [2(q/2), +2)).
constexpr glm::vec4 kSources[4] = {
    {0.2f, 0.55f, 0.9f, 0.6f},
    {1.5f, -0.25f, 0.75f, 0.35f},
    {0.8f, 0.1f, 1.25f, 1.5f},
    {-0.25f, 0.4f, 0.05f, -0.25f},
};
// Destination clear values, one per target. UNORM clamps the last one on store.
constexpr glm::vec4 kDestinations[kTargets] = {
    {0.3f, 0.65f, 0.8f, 0.4f},
    {0.9f, 0.1f, 0.6f, 0.8f},
    {0.05f, 0.95f, 0.35f, 0.2f},
    {1.75f, -0.5f, 0.45f, 0.3f},
};
// Blend constants, alternated between combinations; the second is outside [0,1].
constexpr glm::vec4 kConstants[2] = {
    {0.3f, 0.6f, 0.9f, 0.45f},
    {1.25f, -0.5f, 0.7f, 0.65f},
};

ref::Rgba toRgba(glm::vec4 v) { return {v.r, v.g, v.b, v.a}; }

std::string describeState(const BlendState& s) {
    std::ostringstream out;
    out << "rgb " << render::blendFactorName(s.srcRgb) << "/" << render::blendFactorName(s.dstRgb) << " "
        << render::blendOpName(s.opRgb) << ", alpha " << render::blendFactorName(s.srcAlpha) << "/"
        << render::blendFactorName(s.dstAlpha) << " " << render::blendOpName(s.opAlpha) << ", mask "
        << int(s.writeMask);
    return out.str();
}

class BlendRig {
public:
    BlendRig(render::Backend& gfx, Format format) : gfx_(gfx), format_(format) {
        for (int t = 0; t < kTargets; ++t) {
            render::TextureDesc desc;
            desc.name = "blend" + std::to_string(t);
            desc.width = desc.height = kSize;
            desc.format = format;
            desc.usage = render::UsageRenderTarget;
            targets_[t] = gfx.createTexture(desc);
        }
        // One triangle over the whole target, drawn once per quadrant with the quadrant as
        // scissor: no pixel centre lies on an edge shared by two triangles, so the result does
        // not depend on the fill rule (tested on its own in fill_rule_conformance.cpp).
        std::vector<render::Vertex> vertices(3);
        vertices[0].position = {-1.0f, -1.0f, 0.5f};
        vertices[1].position = {3.0f, -1.0f, 0.5f};
        vertices[2].position = {-1.0f, 3.0f, 0.5f};
        triangle_ = gfx.createBuffer({"cover", render::BufferKind::Vertex, vertices.size() * sizeof(render::Vertex)},
                                     bytesOf(vertices));

        // What each target holds after the clear, checked against the reference store rule.
        run(nullptr);
        for (int t = 0; t < kTargets; ++t) {
            const render::Readback r = gfx.readback(targets_[t]);
            const ref::Rgba expected = ref::store(format, toRgba(kDestinations[t]));
            for (int c = 0; c < 4; ++c) {
                cleared_[t][c] = r.at(0, 0, c);
                EXPECT_TRUE(ref::matches(format, expected[c], cleared_[t][c]))
                    << formatName(format) << " clear of target " << t << " channel " << c << ": expected "
                    << expected[c] << ", stored " << cleared_[t][c];
            }
        }
    }

    // Runs one combination; returns the number of mismatching channel values (and reports
    // the first few).
    int check(const BlendState& state, glm::vec4 constant) {
        render::PipelineDesc desc;
        desc.name = "blend";
        desc.program = render::ProgramKind::Flat;
        desc.blend.fill(state);
        desc.blendConstant = constant;
        const render::PipelineHandle pipeline = gfx_.createPipeline(desc);
        run(&pipeline);
        gfx_.destroy(pipeline);

        int failures = 0;
        for (int t = 0; t < kTargets; ++t) {
            const render::Readback r = gfx_.readback(targets_[t]);
            for (int y = 0; y < kSize; ++y) {
                for (int x = 0; x < kSize; ++x) {
                    const int q = (y / 2) * 2 + x / 2;
                    const ref::Rgba expected =
                        ref::blendStored(state, toRgba(kSources[q]), cleared_[t], toRgba(constant), format_);
                    for (int c = 0; c < 4; ++c) {
                        const double actual = r.at(x, y, c);
                        if (ref::matches(format_, expected[c], actual)) continue;
                        if (++failures <= 3 && ++reported_ <= 20)
                            ADD_FAILURE()
                                << formatName(format_) << " " << describeState(state) << ", constant "
                                << ref::describe(toRgba(constant)) << ": source " << ref::describe(toRgba(kSources[q]))
                                << " over stored " << ref::describe(cleared_[t]) << " channel " << c << " expected "
                                << expected[c] << " got " << actual;
                    }
                }
            }
        }
        return failures;
    }

private:
    void run(const render::PipelineHandle* pipeline) {
        render::PassDesc pass;
        pass.name = "blend";
        for (int t = 0; t < kTargets; ++t) pass.color[t] = {targets_[t], render::LoadOp::Clear, kDestinations[t]};
        gfx_.beginPass(pass);
        if (pipeline) {
            for (int q = 0; q < 4; ++q) {
                auto d = meshDraw(*pipeline, render::FlatParams{glm::mat4(1.0f), kSources[q]}, triangle_, 3);
                d.scissor = render::Rect{2 * (q % 2), 2 * (q / 2), 2, 2};
                gfx_.draw(d);
            }
        }
        gfx_.endPass();
    }

    render::Backend& gfx_;
    Format format_;
    render::TextureHandle targets_[kTargets];
    render::BufferHandle triangle_;
    ref::Rgba cleared_[kTargets]{};
    int reported_ = 0;
};

// Every (srcRgb, dstRgb) pair for every (opRgb, opAlpha) pair, with the alpha factor pair
// running through all 225 pairs too (a bijection of the RGB pair index), so each half sees
// every factor pair with every op of its own and every op of the other half.
std::uint64_t runAllCombinations(render::Backend& gfx, Format format, int& failures) {
    BlendRig rig(gfx, format);
    std::uint64_t combinations = 0;
    constexpr int kFactors = 15;
    for (BlendOp opRgb : render::kAllBlendOps) {
        for (BlendOp opAlpha : render::kAllBlendOps) {
            for (int pair = 0; pair < kFactors * kFactors; ++pair) {
                const int alphaPair = (pair * 16 + int(opRgb) * 7 + int(opAlpha) * 3) % (kFactors * kFactors);
                BlendState state;
                state.enabled = true;
                state.srcRgb = render::kAllBlendFactors[pair / kFactors];
                state.dstRgb = render::kAllBlendFactors[pair % kFactors];
                state.opRgb = opRgb;
                state.srcAlpha = render::kAllBlendFactors[alphaPair / kFactors];
                state.dstAlpha = render::kAllBlendFactors[alphaPair % kFactors];
                state.opAlpha = opAlpha;
                failures += rig.check(state, kConstants[combinations % 2]);
                ++combinations;
            }
        }
    }
    return combinations;
}

void runFormat(render::Backend& gfx, Format format) {
    int failures = 0;
    const std::uint64_t combinations = runAllCombinations(gfx, format, failures);
    std::cout << "[ blend    ] " << formatName(format) << ": " << combinations << " combinations x 16 "
              << "(source, destination) pairs, " << failures << " channel mismatches\n";
    ::testing::Test::RecordProperty("combinations", std::to_string(combinations));
    EXPECT_EQ(failures, 0);
    EXPECT_EQ(combinations, 5u * 5u * 15u * 15u);
}

TEST_P(BlendConformance, AllFactorsAndOpsRgba8Unorm) { runFormat(gfx(), Format::RGBA8_UNORM); }
TEST_P(BlendConformance, AllFactorsAndOpsRgba8Srgb) { runFormat(gfx(), Format::RGBA8_SRGB); }
TEST_P(BlendConformance, AllFactorsAndOpsRgba16F) { runFormat(gfx(), Format::RGBA16F); }
TEST_P(BlendConformance, AllFactorsAndOpsRgba32F) { runFormat(gfx(), Format::RGBA32F); }

// Blending disabled: the source is stored as the format's rules say (clamped for UNORM,
// untouched for float).
TEST_P(BlendConformance, DisabledStoresSource) {
    for (Format format : {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::RGBA16F, Format::RGBA32F}) {
        BlendRig rig(gfx(), format);
        EXPECT_EQ(rig.check(BlendState{}, kConstants[0]), 0) << formatName(format);
    }
}

// Every write mask (16) x a few blend states x all formats: masked channels keep the
// destination bit for bit, the others get the blended value.
TEST_P(BlendConformance, PerChannelWriteMasks) {
    const BlendState states[] = {BlendState::opaque(), BlendState::alphaOver(), BlendState::premultipliedOver(),
                                 BlendState::maxRgbAddAlpha()};
    std::uint64_t combinations = 0;
    for (Format format : {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::RGBA16F, Format::RGBA32F}) {
        BlendRig rig(gfx(), format);
        for (BlendState state : states) {
            for (int mask = 0; mask < 16; ++mask) {
                state.writeMask = std::uint8_t(mask);
                EXPECT_EQ(rig.check(state, kConstants[1]), 0) << formatName(format) << " " << describeState(state);
                ++combinations;
            }
        }
    }
    std::cout << "[ blend    ] write masks: " << combinations << " combinations\n";
    RecordProperty("combinations", std::to_string(combinations));
}

// A target whose mask is 0 is not touched at all, while another target of the same pass is
// written; the masked target's stored bytes (including sRGB codes) stay as cleared.
TEST_P(BlendConformance, FullyMaskedTargetUntouched) {
    for (Format format : {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::RGBA16F, Format::RGBA32F}) {
        const render::TextureHandle written = renderTarget(kSize, kSize, format, 1, "written");
        const render::TextureHandle masked = renderTarget(kSize, kSize, format, 1, "masked");
        render::PipelineDesc desc;
        desc.name = "masked";
        desc.blend[0] = BlendState::alphaOver();
        desc.blend[1] = BlendState::alphaOver();
        desc.blend[1].writeMask = 0;
        const render::PipelineHandle pipeline = gfx().createPipeline(desc);
        const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize));
        const glm::vec4 clear{0.3f, 0.65f, 0.8f, 0.4f};
        render::PassDesc pass;
        pass.name = "masked";
        pass.color[0] = {written, render::LoadOp::Clear, clear};
        pass.color[1] = {masked, render::LoadOp::Clear, clear};
        gfx().beginPass(pass);
        drawFlat(pipeline, quad, 6, {0.9f, 0.2f, 0.1f, 0.7f});
        gfx().endPass();
        const render::Readback w = gfx().readback(written);
        const render::Readback m = gfx().readback(masked);
        const ref::Rgba stored = ref::store(format, toRgba(clear));
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                for (int c = 0; c < 4; ++c) {
                    EXPECT_TRUE(ref::matches(format, stored[c], m.at(x, y, c)))
                        << formatName(format) << " masked target changed at " << x << "," << y;
                    EXPECT_EQ(m.at(x, y, c), m.at(0, 0, c));
                    EXPECT_NE(w.at(x, y, c), m.at(x, y, c))
                        << formatName(format) << " the other target was not written";
                }
            }
        }
    }
}

}  // namespace
}  // namespace ssam::test
