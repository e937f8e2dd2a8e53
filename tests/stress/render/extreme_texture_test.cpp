// SPDX-License-Identifier: MIT
// The largest texture a backend accepts, 16384x16384 (1 GiB of RGBA8), on the soft backend
// (stress_extreme_texture, label stress) or GL (stress_extreme_texture_gl, label gl; built with
// SSAM_EXTREME_GL): created and drawn into where there is the memory, refused before it is
// allocated, naming what it needs and what is available, where there is not. The second case
// is made certain with an address-space limit (RLIMIT_AS) in a child process, which the
// backend's memory figure counts (engine/render/memory_budget.hpp): without the check, the
// allocation fails (std::bad_alloc, or GL_OUT_OF_MEMORY) or, under the kernel's overcommit
// with no limit, the out-of-memory killer ends the process.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/memory_budget.hpp"
#include "engine/render/vertex.hpp"
#ifdef SSAM_EXTREME_GL
#include "engine/render/gl/gl_backend.hpp"
#else
#include "engine/render/soft/soft_backend.hpp"
#endif

namespace {

namespace render = engine::render;
using ::testing::HasSubstr;

constexpr int kLargest = render::kMaxTextureDimension;
constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;

std::unique_ptr<render::Backend> makeBackend() {
#ifdef SSAM_EXTREME_GL
    return render::gl::createGlBackend({});
#else
    return render::soft::createSoftBackend({.threads = 2});
#endif
}

render::TextureDesc largestTarget() {
    return render::renderTargetDesc("largest", kLargest, kLargest, render::Format::RGBA8_UNORM);
}

// Draws a triangle over the target's top-left pixels, counting samples: true when it landed.
bool drawsInto(render::Backend& gfx, render::TextureHandle target) {
    const float pixel = 2.0f / float(gfx.describe(target).width);
    std::vector<render::Vertex> corner(3);
    corner[0].position = {-1.0f, -1.0f, 0.5f};
    corner[1].position = {-1.0f + 8 * pixel, -1.0f, 0.5f};
    corner[2].position = {-1.0f, -1.0f + 8 * pixel, 0.5f};
    const render::BufferHandle vertices =
        gfx.createBuffer({"corner", render::BufferKind::Vertex, corner.size() * sizeof(render::Vertex)},
                         std::as_bytes(std::span(corner)));
    render::PipelineDesc flat;
    flat.name = "flat";
    const render::PipelineHandle pipeline = gfx.createPipeline(flat);
    const render::QueryHandle query = gfx.createQuery("landed");
    render::PassDesc pass;
    pass.name = "corner";
    pass.color[0] = {target, render::LoadOp::Clear, glm::vec4(0.0f)};
    pass.countSamplesInto = query;
    gfx.beginPass(pass);
    render::DrawDesc draw;
    draw.pipeline = pipeline;
    draw.params = render::FlatParams{glm::mat4(1.0f), glm::vec4(1.0f)};
    draw.vertices = vertices;
    draw.count = 3;
    gfx.draw(draw);
    gfx.endPass();
    const bool landed = gfx.anySamplesPassed(query);
    gfx.destroy(query);
    gfx.destroy(pipeline);
    gfx.destroy(vertices);
    return landed;
}

std::uint64_t vmSize() {
    std::ifstream in("/proc/self/status");
    std::stringstream text;
    text << in.rdbuf();
    return render::parseVmSize(text.str()).value_or(0);
}

// Where the memory is there, the texture is made and drawn into; where it is not, the refusal
// says what it needs and what is available. Either way the process lives and the backend
// still works.
TEST(ExtremeTexture, LargestTargetIsDrawnIntoOrRefusedByItsNeed) {
    const std::unique_ptr<render::Backend> gfx = makeBackend();
    try {
        const render::TextureHandle target = gfx->createTexture(largestTarget());
        EXPECT_TRUE(drawsInto(*gfx, target));
        gfx->destroy(target);
        std::printf("%s: 16384x16384 RGBA8 created and drawn into\n", gfx->name().c_str());
    } catch (const engine::Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("texture 'largest': 16384x16384 RGBA8_UNORM needs 1024 MiB and as much again "
                                        "free beside it, but "));
        EXPECT_THAT(e.what(), HasSubstr(" is available ("));
        std::printf("%s: refused: %s\n", gfx->name().c_str(), e.what());
    }
    const render::TextureHandle small =
        gfx->createTexture(render::renderTargetDesc("small", 64, 64, render::Format::RGBA8_UNORM));
    EXPECT_TRUE(drawsInto(*gfx, small));
}

// 1.5 GiB of address space left: the 1 GiB texture, with as much again to stay free, is
// refused before anything is allocated, by name, and a small one still works. Run in a child
// process (the limit must not outlive it): exits 0 when all of that holds, printing the refusal.
[[noreturn]] void exitAfterLargestTargetUnderAddressSpaceLimit() {
    const std::unique_ptr<render::Backend> gfx = makeBackend();
    const rlim_t limit = vmSize() + 1536 * kMiB;
    const rlimit as{limit, limit};
    if (::setrlimit(RLIMIT_AS, &as) != 0) std::_Exit(3);
    try {
        gfx->createTexture(largestTarget());
        std::fprintf(stderr, "not refused\n");
        std::_Exit(1);
    } catch (const engine::Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
    }
    const render::TextureHandle small =
        gfx->createTexture(render::renderTargetDesc("small", 64, 64, render::Format::RGBA8_UNORM));
    std::_Exit(drawsInto(*gfx, small) ? 0 : 2);
}

TEST(ExtremeTexture, LargestTargetIsRefusedBeforeAllocatingWhereMemoryIsShort) {
    // The child runs this test alone in a fresh process: a fork of one whose TBB or llvmpipe
    // threads already run would inherit their locks.
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(exitAfterLargestTargetUnderAddressSpaceLimit(), ::testing::ExitedWithCode(0),
                "texture 'largest': 16384x16384 RGBA8_UNORM needs 1024 MiB and as much again free beside it, but "
                "[0-9]+ MiB is available \\(address space left under RLIMIT_AS \\(ulimit -v\\)\\)");
}

}  // namespace
