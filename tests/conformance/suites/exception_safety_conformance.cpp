// SPDX-License-Identifier: MIT
// Exception safety: after any error thrown by a draw, by code inside a pass, or by a create
// in a module's constructor or reconfiguration, the backend is usable and nothing leaks
// (PassScope, Backend::abortPass, engine::render::Owned; ScreenSpaceAlphaMask's strong
// guarantee in setSettings). Every backend runs these.
#include <stdexcept>

#include "../backend_fixture.hpp"
#include "engine/render/pass_scope.hpp"
#include "failing_backend.hpp"  // tests/support
#include "ssam/composite_program.hpp"
#include "ssam/ssam.hpp"

namespace ssam::test {
namespace {

constexpr int kSize = 8;

// The centre pixel of `target` after a pass that clears it to `clear` and draws `draws`.
glm::vec4 centreAfter(render::Backend& gfx, render::TextureHandle target, glm::vec4 clear) {
    render::PassDesc p;
    p.name = "after";
    p.color[0] = {target, render::LoadOp::Clear, clear};
    render::PassScope scope(gfx, p);
    scope.end();
    const render::Readback r = gfx.readback(target);
    return {r.at(kSize / 2, kSize / 2, 0), r.at(kSize / 2, kSize / 2, 1), r.at(kSize / 2, kSize / 2, 2),
            r.at(kSize / 2, kSize / 2, 3)};
}

TEST_P(ExceptionSafetyConformance, ARefusedDrawLeavesNoPassOpen) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA8_UNORM);
    const render::PipelineHandle pipeline = flatPipeline();
    render::PassDesc p;
    p.name = "refused";
    p.color[0] = {target, render::LoadOp::Clear, glm::vec4(1.0f)};
    EXPECT_THROW(
        {
            render::PassScope scope(gfx(), p);
            gfx().draw(meshDraw(pipeline, render::FlatParams{}, {}, 3));  // no vertex buffer: refused
            scope.end();
        },
        engine::Error);
    // The next pass begins, runs and shows its own clear.
    EXPECT_EQ(centreAfter(gfx(), target, {0.0f, 1.0f, 0.0f, 1.0f}), glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
}

TEST_P(ExceptionSafetyConformance, AnErrorInsideAPassDropsItsDraws) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA8_UNORM);
    const render::PipelineHandle pipeline = flatPipeline();
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize));
    pass(target, glm::vec4(0.0f), [] {});
    render::PassDesc p;
    p.name = "interrupted";
    p.color[0] = {target, render::LoadOp::Load};
    EXPECT_THROW(
        {
            render::PassScope scope(gfx(), p);
            drawFlat(pipeline, quad, 6, glm::vec4(1.0f));
            throw std::runtime_error("the caller's own error");
        },
        std::runtime_error);
    // The aborted pass's draw never ran (soft records draws until endPass; GL's ran into the
    // target already, so only the state is checked there: the next pass works).
    const render::Readback r = gfx().readback(target);
    if (gfx().name() == "soft") {
        EXPECT_EQ(r.at(kSize / 2, kSize / 2, 0), 0.0f);
    }
    EXPECT_EQ(centreAfter(gfx(), target, {0.0f, 0.0f, 1.0f, 1.0f}), glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
}

TEST_P(ExceptionSafetyConformance, SsamConstructorLeaksNothingWhenACreateFails) {
    testing::FailingBackend failing(gfx());
    int failures = 0;
    for (int n = 0;; ++n) {
        failing.failAt = n;
        failing.creates = 0;
        try {
            ScreenSpaceAlphaMask ssam(failing);
            break;  // every create succeeded: n is past the last one
        } catch (const engine::Error&) {
            ++failures;
        }
        EXPECT_EQ(failing.live, 0) << "after create call " << n << " failed";
    }
    EXPECT_GE(failures, 4);  // the composite program and three pipelines
    EXPECT_EQ(failing.live, 0);
}

TEST_P(ExceptionSafetyConformance, SsamSetConfigKeepsTheOldConfigurationWhenACreateFails) {
    testing::FailingBackend failing(gfx());
    ScreenSpaceAlphaMask ssam(failing);
    const int live = failing.live;
    ssam::Settings next;
    next.maskPrecision = MaskPrecision::Rg16f;
    next.maskLerp = 0.5f;
    for (int n = 0; n < 3; ++n) {
        failing.failAt = failing.creates + n;
        EXPECT_THROW(ssam.setSettings(next), engine::Error);
        EXPECT_EQ(failing.live, live) << "setSettings leaked or lost pipelines after create " << n << " failed";
        EXPECT_EQ(ssam.settings().maskPrecision, MaskPrecision::Rgba8);
        EXPECT_EQ(ssam.settings().maskLerp, 0.85f);
    }
    failing.failAt = -1;
    ssam.setSettings(next);
    EXPECT_EQ(ssam.settings().maskPrecision, MaskPrecision::Rg16f);
    EXPECT_EQ(failing.live, live);
}

// A program stays alive while a pipeline uses it: destroying it first is allowed.
TEST_P(ExceptionSafetyConformance, AProgramOutlivesItsHandleWhileAPipelineUsesIt) {
    const render::TextureHandle target = renderTarget(kSize, kSize, Format::RGBA8_UNORM);
    const render::TextureHandle foliage = renderTarget(kSize, kSize, Format::RGBA8_UNORM, 1, "foliage");
    const render::TextureHandle mask = renderTarget(kSize, kSize, Format::RGBA8_UNORM, 1, "mask");
    pass(foliage, {1.0f, 0.0f, 0.0f, 1.0f}, [] {});
    pass(mask, {1.0f, 0.0f, 0.0f, 1.0f}, [] {});  // MAX 1, ADD 0: lerp 0.85 -> 0.15, squared
    const render::ProgramHandle program = gfx().createProgram(compositeProgram());
    render::PipelineDesc desc;
    desc.name = "composite";
    desc.program = program;
    const render::PipelineHandle pipeline = gfx().createPipeline(desc);
    gfx().destroy(program);
    expectError([&] { gfx().destroy(program); }, "program");  // the handle is gone
    pass(target, glm::vec4(0.0f), [&] {
        gfx().draw(fullscreenDraw(pipeline, CompositeParams{foliage, mask, {}, 0.0f, false}));
    });
    const render::Readback r = gfx().readback(target);
    EXPECT_EQ(r.at(1, 1, 0), 1.0f);  // the foliage colour, written as is (no blend)
    gfx().destroy(pipeline);
}

}  // namespace
}  // namespace ssam::test
