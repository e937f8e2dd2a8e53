// SPDX-License-Identifier: MIT
// Occlusion queries and conditional rendering (PassDesc::countSamplesInto and
// drawOnlyIfSamplesIn): a query says whether any sample of a pass's draws passed the depth
// test; a conditional pass skips its draws, not its clears, when none did; misuse is refused.
#include <algorithm>

#include "../backend_fixture.hpp"

namespace ssam::test {
namespace {

constexpr int kSize = 16;

// A depth-only pass drawing a quad at clip depth z over a depth target holding `stored`,
// counting into `query`.
void countQuad(render::Backend& gfx, render::TextureHandle depth, render::PipelineHandle pipeline,
               render::BufferHandle quad, render::QueryHandle query) {
    render::PassDesc p;
    p.name = "count";
    p.depth = {depth, render::LoadOp::Load};
    p.countSamplesInto = query;
    gfx.beginPass(p);
    gfx.draw(meshDraw(pipeline, render::FlatParams{}, quad, 6));
    gfx.endPass();
}

TEST_P(OcclusionQueryConformance, CountsSamplesThatPassTheDepthTest) {
    const auto [color, depth] = colorAndClearedDepth(kSize, kSize, 0.5f);  // every pixel at depth 0.5
    const render::PipelineHandle less = flatPipeline({}, DepthState::testOnly(CompareFunc::Less));
    const render::QueryHandle query = gfx().createQuery("q");
    struct Case {
        float x0, y0, x1, y1, z;
        bool expected;
    };
    for (const Case& c : {Case{0, 0, kSize, kSize, 0.75f, false},  // behind everywhere
                          Case{0, 0, kSize, kSize, 0.25f, true},   // in front everywhere
                          Case{0, 0, kSize, kSize, 0.5f, false},   // equal: Less fails
                          Case{5, 5, 6, 6, 0.25f, true},           // one pixel in front
                          Case{20, 20, 30, 30, 0.25f, false}}) {   // off the target
        const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, c.x0, c.y0, c.x1, c.y1, c.z));
        countQuad(gfx(), depth, less, quad, query);
        EXPECT_EQ(gfx().anySamplesPassed(query), c.expected) << "quad " << c.x0 << "," << c.y0 << " z " << c.z;
        gfx().destroy(quad);
    }
    // The depth target is untouched by a test-only pass.
    const render::Readback d = gfx().readback(depth);
    EXPECT_TRUE(std::all_of(d.values.begin(), d.values.end(), [](float v) { return v == 0.5f; }));
    gfx().destroy(query);
}

TEST_P(OcclusionQueryConformance, ConditionalPassSkipsItsDrawsButNotItsClears) {
    const auto [color, depth] = colorAndClearedDepth(kSize, kSize, 0.5f);
    const render::PipelineHandle less = flatPipeline({}, DepthState::testOnly(CompareFunc::Less));
    const render::PipelineHandle plain = flatPipeline();
    const render::QueryHandle query = gfx().createQuery("sun");
    const render::BufferHandle full = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, 0.25f));
    const render::BufferHandle hidden = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, 0.75f));
    gfx().takeTimings();
    for (bool visible : {false, true, false}) {
        countQuad(gfx(), depth, less, visible ? full : hidden, query);
        render::PassDesc p;
        p.name = "conditional";
        p.color[0] = {color, render::LoadOp::Clear, {0, 0, 1, 1}};
        p.drawOnlyIfSamplesIn = query;
        gfx().beginPass(p);
        drawFlat(plain, full, 6, {1, 0, 0, 1});
        gfx().endPass();
        const render::Readback c = gfx().readback(color);
        for (int i = 0; i < kSize * kSize; ++i) {
            ASSERT_EQ(c.values[4 * i + 0], visible ? 1.0f : 0.0f) << "visible " << visible;
            ASSERT_EQ(c.values[4 * i + 2], visible ? 0.0f : 1.0f) << "the clear ran, visible " << visible;
        }
        const auto timings = gfx().takeTimings();
        const auto it =
            std::find_if(timings.begin(), timings.end(), [](const auto& t) { return t.pass == "conditional"; });
        ASSERT_NE(it, timings.end());
        EXPECT_EQ(it->skipped, !visible);
        for (const auto& t : timings) EXPECT_TRUE(t.pass == "conditional" || !t.skipped) << t.pass << " marked skipped";
    }
    gfx().destroy(query);
}

// The query keeps the last count while another pass reuses it before timings are taken
// (GL keeps a query object per pending read).
TEST_P(OcclusionQueryConformance, ReusedBeforeTimingsAreTaken) {
    const auto [color, depth] = colorAndClearedDepth(kSize, kSize, 0.5f);
    const render::PipelineHandle less = flatPipeline({}, DepthState::testOnly(CompareFunc::Less));
    const render::QueryHandle query = gfx().createQuery("q");
    const render::BufferHandle front = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, 0.25f));
    const render::BufferHandle back = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, 0.75f));
    gfx().takeTimings();
    std::vector<bool> expectedSkips;
    for (int frame = 0; frame < 4; ++frame) {
        const bool visible = frame % 2 == 1;
        countQuad(gfx(), depth, less, visible ? front : back, query);
        render::PassDesc p;
        p.name = "conditional";
        p.color[0] = {color, render::LoadOp::Load};
        p.drawOnlyIfSamplesIn = query;
        gfx().beginPass(p);
        gfx().endPass();
        expectedSkips.push_back(!visible);
    }
    std::vector<bool> skips;
    for (const auto& t : gfx().takeTimings())
        if (t.pass == "conditional") skips.push_back(t.skipped);
    EXPECT_EQ(skips, expectedSkips);
    EXPECT_TRUE(gfx().anySamplesPassed(query));  // the last count: in front
    gfx().destroy(query);
    EXPECT_TRUE(gfx().takeTimings().empty());
}

TEST_P(OcclusionQueryConformance, MisuseIsRefused) {
    const auto [color, depth] = colorAndDepthTargets(kSize, kSize);
    const render::QueryHandle query = gfx().createQuery("sun");
    expectError([&] { gfx().anySamplesPassed(query); }, "before any pass counted into it");
    render::PassDesc conditional;
    conditional.name = "conditional";
    conditional.color[0] = {color, render::LoadOp::Load};
    conditional.drawOnlyIfSamplesIn = query;
    expectError([&] { gfx().beginPass(conditional); }, "before any pass counted into it");

    render::PassDesc both = conditional;
    both.countSamplesInto = query;
    expectError([&] { gfx().beginPass(both); }, "occlusion query it counts into");

    // Counting passes may not discard: soft counts before the alpha test, GL after it.
    render::PassDesc counting;
    counting.name = "counting";
    counting.color[0] = {color, render::LoadOp::Load};
    counting.depth = {depth, render::LoadOp::Clear, 1.0f};
    counting.countSamplesInto = query;
    const render::PipelineHandle alphaTested =
        flatPipeline({}, DepthState::testOnly(), render::AlphaTest::discardBelow(0.5f));
    const render::BufferHandle quad = vertexBuffer(pixelRect(kSize, kSize, 0, 0, kSize, kSize, 0.25f));
    gfx().beginPass(counting);
    expectError([&] { drawFlat(alphaTested, quad, 6); }, "alpha test or alpha-to-coverage in a pass that counts");
    expectError([&] { gfx().anySamplesPassed(query); }, "read while pass 'counting' counts into it");
    expectError([&] { gfx().destroy(query); }, "destroyed while pass 'counting' counts into it");
    gfx().endPass();
    EXPECT_FALSE(gfx().anySamplesPassed(query));  // the pass drew nothing

    gfx().destroy(query);
    expectError([&] { gfx().anySamplesPassed(query); }, "occlusion query handle");
    counting.countSamplesInto = query;
    expectError([&] { gfx().beginPass(counting); }, "stale");
}

}  // namespace
}  // namespace ssam::test
