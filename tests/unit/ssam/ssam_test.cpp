// SPDX-License-Identifier: MIT
// SSAM on the soft backend: the shared exact synthetic cases (ssam_cases.hpp, [Hathaway 2010] §3.5),
// plus what only the soft backend can show (its work counters).
#include "ssam_cases.hpp"

#include "engine/render/soft/soft_backend.hpp"

// The backend the shared cases run on; a global name so ctest lists Ssam.<case><OnSoft>.
struct OnSoft {
    static std::unique_ptr<engine::render::Backend> create() { return engine::render::soft::createSoftBackend({}); }
    // The expected composite is itself rounded to 8 bits: 1 code (the soft backend's blend is exact).
    static constexpr float kBlendTolerance = 1.0f / 255.0f + 1e-6f;
};

namespace ssam_cases {
namespace {

INSTANTIATE_TYPED_TEST_SUITE_P(Ssam, SsamCases, ::testing::Types<OnSoft>);

TEST(SsamSoft, CompositeTouchesOnlyTheFoliageRegion) {
    Frame<OnSoft> f;
    f.opaquePass();
    auto& backend = static_cast<engine::render::Device&>(*f.backend);
    ssam::ScreenSpaceAlphaMask ssam(backend);
    // A small quad in one corner: 4x4 pixels of a 16x16 screen.
    QuadBatches q(backend, {{-1.0f, 0.5f, -0.5f, 1.0f, 0.5f, {1, 1, 1, 0.5f}}});
    const ssam::FramePlan plan = ssam.cull(kSize, kSize, viewOf(q));
    ASSERT_FALSE(plan.empty());
    // The composite alone, over targets of the frame's size (what the graph's transients would be).
    const ssam::IntermediateDescs descs = ssam.intermediateDescs(kSize, kSize, Format::RGBA8_UNORM);
    const TextureHandle mask = backend.createTexture(descs.mask), foliage = backend.createTexture(descs.foliage);
    const auto shadedBefore = soft::softDriver(backend).stats().pixelsShaded;
    ssam.compositePass(plan, f.opaque.color(), {mask, {}, foliage, {}});
    const auto shaded = soft::softDriver(backend).stats().pixelsShaded - shadedBefore;
    backend.destroy(mask);
    backend.destroy(foliage);
    EXPECT_LE(shaded, std::uint64_t(plan.compositeRegion.width * plan.compositeRegion.height));
    EXPECT_LT(shaded, std::uint64_t(kSize * kSize / 4));
}

TEST(SsamSoft, NoFoliageInViewCountsNoPass) {
    Frame<OnSoft> f;
    f.opaquePass();
    auto& backend = static_cast<engine::render::Device&>(*f.backend);
    ssam::ScreenSpaceAlphaMask ssam(backend);
    QuadBatches q(backend, {{-1, -1, 1, 1, -0.5f, glm::vec4(1.0f)}, {3, 3, 4, 4, 0.5f, glm::vec4(1.0f)}});
    const auto before = soft::softDriver(backend).stats();
    test_support::runSsam(ssam, f.targets(), viewOf(q));
    EXPECT_EQ(soft::softDriver(backend).stats().passes, before.passes);
    EXPECT_EQ(soft::softDriver(backend).stats().draws, before.draws);
}

}  // namespace
}  // namespace ssam_cases
