// SPDX-License-Identifier: MIT
// The depth block bounds (SoftOptions::depthBlockBounds, kernel/detail/depth_block_bounds.hpp): in
// a pass whose draws test depth and none writes it, a triangle's 8x8 block behind every stored
// depth is skipped before its rows. Each test renders the same passes with the bounds on and off
// and wants the same bits, and checks from SoftStats::depthBlocksSkipped that blocks were (or
// were not) skipped, so that neither a wrong skip nor a skip that never runs can pass.
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "soft_test_util.hpp"

namespace ssam::test::soft {
namespace {

constexpr int kWidth = 96, kHeight = 64;
constexpr std::uint32_t kTriangles = 1500;

std::vector<render::Vertex> randomTriangles(std::uint32_t seed) {
    return soft::randomTriangles(kTriangles, seed, 0.2f);
}

struct Result {
    std::vector<float> color;
    std::uint64_t skipped = 0;
};

// Pass 1 draws `occluders` writing depth (LessEqual; GreaterEqual from 0 under the Greater
// functions); pass 2 draws `tested` with `func`, adding
// its colours (ONE/ONE) into a float target, writing depth only when `secondWrites`.
Result render(bool bounds, render::CompareFunc func, const std::vector<render::Vertex>& occluders,
              const std::vector<render::Vertex>& tested, bool secondWrites = false) {
    auto gfx = createSoftBackend({.threads = 2, .depthBlockBounds = bounds});
    const render::TextureHandle color = makeTarget(*gfx, kWidth, kHeight, Format::RGBA32F, 1, "color");
    const render::TextureHandle depth = makeTarget(*gfx, kWidth, kHeight, Format::D32F, 1, "depth");
    const glm::mat4 viewProj = glm::perspective(1.0f, float(kWidth) / kHeight, 0.5f, 20.0f);
    const render::BufferHandle first = makeVertices(*gfx, occluders), second = makeVertices(*gfx, tested);

    const bool reverse = func == render::CompareFunc::Greater || func == render::CompareFunc::GreaterEqual;
    render::PipelineDesc write = pipelineDesc("occluders");
    write.depth =
        render::DepthState::testAndWrite(reverse ? render::CompareFunc::GreaterEqual : render::CompareFunc::LessEqual);
    const render::PipelineHandle writing = gfx->createPipeline(write);
    render::PipelineDesc test = pipelineDesc("tested");
    test.depth = secondWrites ? render::DepthState::testAndWrite(func) : render::DepthState::testOnly(func);
    using render::BlendFactor, render::BlendOp;
    test.blend[0] = {true,         BlendFactor::One, BlendFactor::One, BlendOp::Add, BlendFactor::One, BlendFactor::One,
                     BlendOp::Add, render::WriteAll};
    const render::PipelineHandle testing = gfx->createPipeline(test);

    render::PassDesc pass = onePass(color, depth);
    if (reverse) pass.depth.clear = 0.0f;  // the occluders keep their largest depth
    gfx->beginPass(pass);
    gfx->draw(meshDraw(writing, render::FlatParams{viewProj, glm::vec4(1.0f)}, first, kTriangles * 3));
    gfx->endPass();
    render::PassDesc again = onePass(color, depth);
    again.depth.load = render::LoadOp::Load;
    gfx->beginPass(again);
    gfx->draw(meshDraw(testing, render::FlatParams{viewProj, glm::vec4(1.0f)}, second, kTriangles * 3));
    gfx->endPass();
    return {gfx->readback(color).values, softDriver(*gfx).stats().depthBlocksSkipped};
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// The same bits with the bounds on and off, blocks skipped with them on; `passes`: some fragment
// passes the test (else the comparison would be between two empty targets).
void expectSameBitsAndSkips(render::CompareFunc func, const std::vector<render::Vertex>& occluders,
                            const std::vector<render::Vertex>& tested, bool passes = true) {
    const Result on = render(true, func, occluders, tested), off = render(false, func, occluders, tested);
    EXPECT_GT(on.skipped, 0u) << "no block was skipped";
    EXPECT_EQ(off.skipped, 0u);
    EXPECT_TRUE(sameBits(on.color, off.color)) << "the tested pass differs with the bounds";
    const auto empty = std::count(on.color.begin(), on.color.end(), 0.0f);
    if (passes) EXPECT_NE(empty, std::ptrdiff_t(on.color.size())) << "nothing passed";
    else EXPECT_EQ(empty, std::ptrdiff_t(on.color.size())) << "a fragment on the stored depth passed Less";
}

TEST(DepthBlockBounds, EachOrderingFunctionSkipsBlocksAndKeepsTheBits) {
    for (render::CompareFunc func : {render::CompareFunc::Less, render::CompareFunc::LessEqual,
                                     render::CompareFunc::Greater, render::CompareFunc::GreaterEqual}) {
        SCOPED_TRACE(int(func));
        expectSameBitsAndSkips(func, randomTriangles(1), randomTriangles(2));
    }
}

// The same triangles again: their planes equal the stored depth wherever they won, the case a
// bound without its rounding margin would get wrong (LessEqual passes there, Less fails).
TEST(DepthBlockBounds, TrianglesOnTheStoredDepthKeepTheBits) {
    const std::vector<render::Vertex> same = randomTriangles(3);
    expectSameBitsAndSkips(render::CompareFunc::LessEqual, same, same);
    expectSameBitsAndSkips(render::CompareFunc::Less, same, same, /*passes=*/false);
}

// A pass whose draws write depth changes the depth while it runs: no bounds.
TEST(DepthBlockBounds, APassThatWritesDepthSkipsNothing) {
    const Result r = render(true, render::CompareFunc::Less, randomTriangles(4), randomTriangles(5), true);
    EXPECT_EQ(r.skipped, 0u);
}

}  // namespace
}  // namespace ssam::test::soft
