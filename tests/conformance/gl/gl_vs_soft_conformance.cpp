// SPDX-License-Identifier: MIT
// GL conformance against the soft backend as the reference: the same state on both, results
// compared with the GL tolerances (README "GL backend"):
//   UNORM: 2 codes (llvmpipe blends 8-bit targets in 8-bit fixed point, GL 4.5 §17.3.6 allows
//          blending at the destination's precision), sRGB: 2 codes or 2/255 in linear light,
//   RGBA16F: 1 half ULP per store (llvmpipe rounds toward zero; a resolve stores twice: 2),
//   RGBA32F: 1e-6 relative.
// Covered: every blend factor x op on RGBA8/sRGB/RGBA16F/RGBA32F, the SSAM mask blend, every
// alpha-test function x GS fail mode x depth set-up (exact emulations must match, inexact ones are
// reported as such), alpha-to-coverage at 2x and 4x, MSAA colour and closest-depth resolves.
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../backend_fixture.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/soft/soft_backend.hpp"

namespace ssam::test {
namespace {

namespace gl = engine::render::gl;

std::unique_ptr<render::Backend> softBackend() { return engine::render::soft::createSoftBackend({.threads = 1}); }
std::unique_ptr<render::Backend> glBackend(gl::FailModeStrategy failModes = gl::FailModeStrategy::TwoPass) {
    gl::GlOptions options;
    options.failModes = failModes;
    return gl::createGlBackend(options);
}

double srgbDecode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

double halfUlp(double magnitude) {
    int e;
    std::frexp(std::max(magnitude, std::ldexp(1.0, -14)), &e);
    return std::ldexp(1.0, e - 1 - 10);
}

struct Tally {
    std::uint64_t values = 0, beyondOneCode = 0, failures = 0;
};

// Whether a GL value matches the soft one within the GL tolerances above.
bool close(Format f, int channel, double soft, double glv, Tally& tally) {
    ++tally.values;
    const render::FormatInfo& info = render::formatInfo(f);
    if (std::isnan(soft) || std::isnan(glv)) return std::isnan(soft) && std::isnan(glv);
    if (std::isinf(soft) || std::isinf(glv)) return soft == glv;
    if (info.isNormalized()) {
        const long codes = std::labs(std::lround(soft * 255.0) - std::lround(glv * 255.0));
        tally.beyondOneCode += codes > 1;
        if (codes <= 2) return true;
        return info.isSrgb && channel < 3 && std::fabs(srgbDecode(soft) - srgbDecode(glv)) <= 2.0 / 255.0 + 1e-9;
    }
    if (f == Format::RGBA16F || f == Format::RG16F || f == Format::R16F)  // a resolve stores twice
        return std::fabs(soft - glv) <= 2.0 * halfUlp(std::fabs(soft)) * 1.0001;
    if (info.isDepth) return std::fabs(soft - glv) <= 1e-6;
    return std::fabs(soft - glv) <= std::max(1e-6, 1e-6 * std::fabs(soft));
}

// Compares readbacks; reports the first few differences under `what`.
void expectClose(const render::Readback& soft, const render::Readback& glr, const std::string& what, Tally& tally) {
    ASSERT_EQ(soft.values.size(), glr.values.size()) << what;
    int reported = 0;
    for (std::size_t i = 0; i < soft.values.size(); ++i) {
        if (close(soft.format, int(i % soft.channels), soft.values[i], glr.values[i], tally)) continue;
        ++tally.failures;
        if (++reported <= 4) {
            const std::size_t pixel = i / soft.channels;
            ADD_FAILURE() << what << ": pixel (" << pixel % soft.width << "," << pixel / soft.width << ") channel "
                          << i % soft.channels << ": soft " << soft.values[i] << ", gl " << glr.values[i];
        }
    }
}

// A scenario builds its resources and draws on one backend and returns the readbacks to compare.
using Scenario = std::function<std::vector<render::Readback>(render::Backend&)>;

void compareOn(render::Backend& soft, render::Backend& glb, const Scenario& scenario, const std::string& what,
               Tally& tally) {
    const std::vector<render::Readback> s = scenario(soft);
    const std::vector<render::Readback> g = scenario(glb);
    ASSERT_EQ(s.size(), g.size());
    for (std::size_t i = 0; i < s.size(); ++i) expectClose(s[i], g[i], what + " [" + std::to_string(i) + "]", tally);
}

render::TextureHandle target(render::Backend& b, int w, int h, Format f, int samples = 1,
                             const std::string& name = "t") {
    return b.createTexture(render::renderTargetDesc(name, w, h, f, samples));
}

render::BufferHandle vertices(render::Backend& b, const std::vector<render::Vertex>& v) {
    return b.createBuffer({"vertices", render::BufferKind::Vertex, v.size() * sizeof(render::Vertex)}, bytesOf(v));
}

std::string describe(const BlendState& s) {
    std::ostringstream out;
    out << render::blendFactorName(s.srcRgb) << "/" << render::blendFactorName(s.dstRgb) << " "
        << render::blendOpName(s.opRgb) << ", " << render::blendFactorName(s.srcAlpha) << "/"
        << render::blendFactorName(s.dstAlpha) << " " << render::blendOpName(s.opAlpha);
    return out.str();
}

// ---- blending ----------------------------------------------------------------------------

// Sources and destinations inside and outside [0,1], as the shared blend suite uses.
constexpr glm::vec4 kSources[4] = {
    {0.2f, 0.55f, 0.9f, 0.6f}, {1.5f, -0.25f, 0.75f, 0.35f}, {0.8f, 0.1f, 1.25f, 1.5f}, {-0.25f, 0.4f, 0.05f, -0.25f}};
constexpr glm::vec4 kDestinations[4] = {
    {0.3f, 0.65f, 0.8f, 0.4f}, {0.9f, 0.1f, 0.6f, 0.8f}, {0.05f, 0.95f, 0.35f, 0.2f}, {1.75f, -0.5f, 0.45f, 0.3f}};
constexpr glm::vec4 kConstants[2] = {{0.3f, 0.6f, 0.9f, 0.45f}, {1.25f, -0.5f, 0.7f, 0.65f}};

// One pass, four 4x4 targets of `format` cleared to the four destinations, four 2x2 quads with
// the four sources: 16 (source, destination) pairs per state.
Scenario blendScenario(Format format, const BlendState& state, glm::vec4 constant) {
    return [=](render::Backend& b) {
        render::PassDesc pass;
        pass.name = "blend";
        render::TextureHandle targets[4];
        for (int t = 0; t < 4; ++t) {
            targets[t] = target(b, 4, 4, format, 1, "blend" + std::to_string(t));
            pass.color[t] = {targets[t], render::LoadOp::Clear, kDestinations[t]};
        }
        std::vector<render::Vertex> v;
        for (int q = 0; q < 4; ++q) {
            const float x0 = float(2 * (q % 2)), y0 = float(2 * (q / 2));
            for (const render::Vertex& vertex : pixelRect(4, 4, x0, y0, x0 + 2, y0 + 2)) v.push_back(vertex);
        }
        const render::BufferHandle vb = vertices(b, v);
        render::PipelineDesc desc;
        desc.name = "blend";
        desc.blend.fill(state);
        desc.blendConstant = constant;
        const render::PipelineHandle p = b.createPipeline(desc);
        b.beginPass(pass);
        for (int q = 0; q < 4; ++q) {
            render::DrawDesc d;
            d.pipeline = p;
            d.params = render::FlatParams{glm::mat4(1.0f), kSources[q]};
            d.vertices = vb;
            d.first = std::uint32_t(6 * q);
            d.count = 6;
            b.draw(d);
        }
        b.endPass();
        std::vector<render::Readback> out;
        for (int t = 0; t < 4; ++t) out.push_back(b.readback(targets[t]));
        for (int t = 0; t < 4; ++t) b.destroy(targets[t]);
        b.destroy(vb);
        b.destroy(p);
        return out;
    };
}

class GlBlendVsSoft : public ::testing::TestWithParam<Format> {};

// Every (srcRgb, dstRgb) pair with every RGB op; the alpha half runs through every pair and op
// too (a bijection of the RGB index), so each factor and op is checked on both halves.
// 1125 states per format (llvmpipe compiles one shader variant per blend state).
TEST_P(GlBlendVsSoft, EveryFactorAndOp) {
    const Format format = GetParam();
    auto soft = softBackend();
    auto glb = glBackend();
    Tally tally;
    int states = 0;
    for (int op = 0; op < 5; ++op) {
        for (int pair = 0; pair < 225; ++pair) {
            const int alphaPair = (pair * 16 + op * 7) % 225;
            BlendState s;
            s.enabled = true;
            s.srcRgb = render::kAllBlendFactors[pair / 15];
            s.dstRgb = render::kAllBlendFactors[pair % 15];
            s.opRgb = render::kAllBlendOps[op];
            s.srcAlpha = render::kAllBlendFactors[alphaPair / 15];
            s.dstAlpha = render::kAllBlendFactors[alphaPair % 15];
            s.opAlpha = render::kAllBlendOps[(op + pair) % 5];
            const std::uint64_t before = tally.failures;
            compareOn(*soft, *glb, blendScenario(format, s, kConstants[states % 2]), describe(s), tally);
            if (tally.failures > before + 64) FAIL() << "stopping after too many differences";
            ++states;
        }
    }
    std::cout << "[ gl blend ] " << render::formatName(format) << ": " << states << " states, " << tally.values
              << " values, " << tally.beyondOneCode << " beyond one code, " << tally.failures << " beyond tolerance\n";
    EXPECT_EQ(tally.failures, 0u);
}

INSTANTIATE_TEST_SUITE_P(Formats, GlBlendVsSoft,
                         ::testing::Values(Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::RGBA16F, Format::RGBA32F),
                         [](const ::testing::TestParamInfo<Format>& info) {
                             return std::string(render::formatName(info.param));
                         });

// The SSAM mask ([Hathaway 2010] Table 3.1: RGB MAX, A ADD) accumulated over overlapping layers,
// into one RGBA target and into the split RG16F/R16F pair.
TEST(GlVsSoft, SsamMaskBlend) {
    auto soft = softBackend();
    auto glb = glBackend();
    Tally tally;
    for (Format f : {Format::RGBA16F, Format::RGBA32F, Format::RG16F, Format::R16F, Format::RGBA8_UNORM}) {
        compareOn(
            *soft, *glb,
            [f](render::Backend& b) {
                const auto t = target(b, 8, 8, f, 1, "mask");
                std::vector<render::Vertex> v;
                for (int layer = 0; layer < 5; ++layer) {
                    const float x0 = float(layer), y0 = float(layer % 3);
                    for (render::Vertex vertex : pixelRect(8, 8, x0, y0, x0 + 4, y0 + 5)) {
                        vertex.color = {0.15f * float(layer + 1), 0.1f, 0.3f, 0.2f + 0.15f * float(layer)};
                        v.push_back(vertex);
                    }
                }
                const auto vb = vertices(b, v);
                render::PipelineDesc desc;
                desc.name = "mask";
                desc.program = render::ProgramKind::AlphaOnly;
                desc.blend.fill(BlendState::maxRgbAddAlpha());
                const auto p = b.createPipeline(desc);
                render::PassDesc pass;
                pass.name = "mask";
                pass.color[0] = {t, render::LoadOp::Clear, glm::vec4(0.0f)};
                b.beginPass(pass);
                b.draw(meshDraw(p, render::AlphaOnlyParams{glm::mat4(1.0f), 0.9f, {}}, vb, std::uint32_t(v.size())));
                b.endPass();
                return std::vector<render::Readback>{b.readback(t)};
            },
            std::string("ssam mask ") + std::string(render::formatName(f)), tally);
    }
    EXPECT_EQ(tally.failures, 0u);
}

// ---- alpha test x fail modes ---------------------------------------------------------------

// Three overlapping triangles in one draw, in front of and behind an earlier one, with alphas
// on both sides of the reference; the draw writes colour, alpha and (maybe) depth.
Scenario alphaTestScenario(const render::PipelineDesc& desc, bool withDepth, float depthClear) {
    return [=](render::Backend& b) {
        const auto color = target(b, 12, 12, Format::RGBA8_UNORM, 1, "color");
        const auto depth = target(b, 12, 12, Format::D32F, 1, "depth");
        auto quad = [](float x0, float y0, float x1, float y1, float z, float a) {
            std::vector<render::Vertex> v = pixelRect(12, 12, x0, y0, x1, y1, z);
            for (render::Vertex& vertex : v) vertex.color = {0.9f * a + 0.05f, 0.3f, 1.0f - a, a};
            return v;
        };
        std::vector<render::Vertex> first = quad(0, 0, 8, 8, 0.5f, 0.9f);
        std::vector<render::Vertex> second;
        for (const auto& part :
             {quad(2, 2, 10, 10, 0.25f, 0.3f), quad(4, 1, 11, 7, 0.75f, 0.8f), quad(1, 5, 7, 11, 0.125f, 0.6f)})
            second.insert(second.end(), part.begin(), part.end());
        const auto vb1 = vertices(b, first), vb2 = vertices(b, second);
        render::PipelineDesc base;
        base.name = "base";
        base.depth = withDepth ? render::DepthState::testAndWrite(CompareFunc::Always) : render::DepthState::off();
        const auto p1 = b.createPipeline(base);
        const auto p2 = b.createPipeline(desc);
        render::PassDesc pass;
        pass.name = "alpha";
        pass.color[0] = {color, render::LoadOp::Clear, {0.1f, 0.2f, 0.3f, 0.4f}};
        if (withDepth) pass.depth = {depth, render::LoadOp::Clear, depthClear};
        b.beginPass(pass);
        for (auto [p, vb, n] : {std::tuple{p1, vb1, first.size()}, std::tuple{p2, vb2, second.size()}}) {
            b.draw(meshDraw(p, render::FlatParams{}, vb, std::uint32_t(n)));
        }
        b.endPass();
        std::vector<render::Readback> out{b.readback(color)};
        if (withDepth) out.push_back(b.readback(depth));
        return out;
    };
}

// Every alpha function x fail mode x depth set-up x blend: where GL reports the emulation exact,
// the result matches soft; where it reports it inexact, the per-triangle strategy is exact.
TEST(GlVsSoft, AlphaTestFuncsAndFailModes) {
    auto soft = softBackend();
    auto twoPass = glBackend(gl::FailModeStrategy::TwoPass);
    auto perTriangle = glBackend(gl::FailModeStrategy::PerTriangle);
    struct DepthCase {
        const char* name;
        render::DepthState state;
        bool target;
    };
    const DepthCase depths[] = {{"no depth", render::DepthState::off(), false},
                                {"test only", render::DepthState::testOnly(CompareFunc::LessEqual), true},
                                {"less+write", render::DepthState::testAndWrite(CompareFunc::Less), true},
                                {"always+write", render::DepthState::testAndWrite(CompareFunc::Always), true}};
    BlendState revSubtract = BlendState::alphaOver();
    revSubtract.opRgb = BlendOp::RevSubtract;
    BlendState dstAlphaRgb = BlendState::alphaOver();
    dstAlphaRgb.dstRgb = BlendFactor::InvDstAlpha;
    const BlendState blends[] = {BlendState::opaque(), BlendState::alphaOver(), revSubtract, dstAlphaRgb};
    Tally tally;
    int exact = 0, inexact = 0, inexactThatDiffer = 0;
    for (CompareFunc func : render::kAllCompareFuncs) {
        for (AlphaFailMode mode : render::kAllAlphaFailModes) {
            for (const DepthCase& depth : depths) {
                for (const BlendState& blend : blends) {
                    render::PipelineDesc desc;
                    desc.name = "alpha_test";
                    desc.blend.fill(blend);
                    desc.depth = depth.state;
                    desc.alphaTest = {true, func, 0.5f, mode, false};
                    std::ostringstream what;
                    what << render::compareFuncName(func) << " " << render::alphaFailModeName(mode) << " " << depth.name
                         << " " << describe(blend);
                    const Scenario scenario = alphaTestScenario(desc, depth.target, 1.0f);
                    const bool isExact = twoPass->pipelineInfo(twoPass->createPipeline(desc)).exact;
                    if (isExact) {
                        ++exact;
                        compareOn(*soft, *twoPass, scenario, what.str(), tally);
                    } else {
                        ++inexact;
                        EXPECT_FALSE(twoPass->pipelineInfo(twoPass->createPipeline(desc)).note.empty()) << what.str();
                        // The flag is not just caution: count the cases that really differ.
                        const auto s = scenario(*soft);
                        const auto g = scenario(*twoPass);
                        Tally scratch;
                        bool differs = false;
                        for (std::size_t i = 0; i < s.size(); ++i)
                            for (std::size_t k = 0; k < s[i].values.size(); ++k)
                                differs = differs || !close(s[i].format, int(k % s[i].channels), s[i].values[k],
                                                            g[i].values[k], scratch);
                        inexactThatDiffer += differs;
                    }
                    EXPECT_TRUE(perTriangle->pipelineInfo(perTriangle->createPipeline(desc)).exact) << what.str();
                    compareOn(*soft, *perTriangle, scenario, what.str() + " (per triangle)", tally);
                }
            }
        }
    }
    std::cout << "[ gl alpha ] " << exact << " exact two-pass emulations match, " << inexact << " reported inexact ("
              << inexactThatDiffer << " of them differ here); per-triangle: all match\n";
    EXPECT_EQ(tally.failures, 0u);
    EXPECT_GT(inexactThatDiffer, 0);
}

// ---- MSAA -----------------------------------------------------------------------------------

// Alpha-to-coverage covers round(alpha * samples) samples: full-pixel quads at alphas 0..1,
// resolved. 2x is 4x on llvmpipe; the shader covers the same fraction, so resolves agree.
TEST(GlVsSoft, AlphaToCoverageSampleCounts) {
    auto soft = softBackend();
    auto glb = glBackend();
    Tally tally;
    for (int samples : {2, 4}) {
        compareOn(
            *soft, *glb,
            [samples](render::Backend& b) {
                const auto color = target(b, 11, 1, Format::RGBA32F, samples, "a2c");
                std::vector<render::Vertex> v;
                for (int i = 0; i <= 10; ++i)
                    for (render::Vertex vertex : pixelRect(11, 1, float(i), 0, float(i + 1), 1)) {
                        vertex.color = {1.0f, 1.0f, 1.0f, float(i) / 10.0f};
                        v.push_back(vertex);
                    }
                const auto vb = vertices(b, v);
                render::PipelineDesc desc;
                desc.name = "a2c";
                desc.alphaTest.alphaToCoverage = true;
                const auto p = b.createPipeline(desc);
                render::PassDesc pass;
                pass.name = "a2c";
                pass.color[0] = {color, render::LoadOp::Clear, glm::vec4(0.0f)};
                b.beginPass(pass);
                b.draw(meshDraw(p, render::FlatParams{}, vb, std::uint32_t(v.size())));
                b.endPass();
                const auto resolved = target(b, 11, 1, Format::RGBA32F, 1, "resolved");
                b.resolve({color, resolved});
                return std::vector<render::Readback>{b.readback(resolved)};
            },
            "alpha to coverage x" + std::to_string(samples), tally);
    }
    EXPECT_EQ(tally.failures, 0u);
}

// Colour resolve = average (in linear for sRGB), depth resolve = closest sample, 4x, edges
// crossing pixels away from sample positions (where GL and soft may break ties differently).
TEST(GlVsSoft, MsaaColourAndClosestDepthResolve) {
    auto soft = softBackend();
    auto glb = glBackend();
    Tally tally;
    for (Format f : {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::RGBA16F, Format::RGBA32F}) {
        for (CompareFunc func : {CompareFunc::Less, CompareFunc::GreaterEqual}) {
            compareOn(
                *soft, *glb,
                [f, func](render::Backend& b) {
                    const auto color = target(b, 16, 16, f, 4, "msaa");
                    const auto depth = target(b, 16, 16, Format::D32F, 4, "msaa_depth");
                    // Vertices on quarter pixels (so both backends interpolate from the same
                    // positions) with no edge through a sample position: samples sit at odd
                    // eighths, and an edge (m, n) in quarter pixels meets one only when m and n
                    // have as many factors of 2.
                    std::vector<render::Vertex> v = {
                        pixelVertex(16, 16, 0.25, 1.0, 0.2f), pixelVertex(16, 16, 3.0, 15.5, 0.9f),
                        pixelVertex(16, 16, 15.0, 6.5, 0.6f), pixelVertex(16, 16, 14.75, 0.0, 0.3f),
                        pixelVertex(16, 16, 1.5, 9.0, 0.7f),  pixelVertex(16, 16, 13.5, 14.5, 0.1f)};
                    v[0].color = {1.0f, 0.2f, 0.1f, 1.0f};
                    v[3].color = {0.1f, 0.4f, 1.0f, 0.5f};
                    const auto vb = vertices(b, v);
                    render::PipelineDesc desc;
                    desc.name = "msaa";
                    desc.depth = render::DepthState::testAndWrite(func);
                    const auto p = b.createPipeline(desc);
                    render::PassDesc pass;
                    pass.name = "msaa";
                    pass.color[0] = {color, render::LoadOp::Clear, {0.25f, 0.5f, 0.75f, 1.0f}};
                    pass.depth = {depth, render::LoadOp::Clear, func == CompareFunc::Less ? 1.0f : 0.0f};
                    b.beginPass(pass);
                    b.draw(meshDraw(p, render::FlatParams{}, vb, 6));
                    b.endPass();
                    const auto c1 = target(b, 16, 16, f, 1, "resolved");
                    const auto d1 = target(b, 16, 16, Format::D32F, 1, "resolved_depth");
                    b.resolve({color, c1});
                    b.resolve({depth, d1, func});
                    return std::vector<render::Readback>{b.readback(c1), b.readback(d1)};
                },
                std::string("resolve ") + std::string(render::formatName(f)) + " " + render::compareFuncName(func),
                tally);
        }
    }
    EXPECT_EQ(tally.failures, 0u);
}

}  // namespace
}  // namespace ssam::test
