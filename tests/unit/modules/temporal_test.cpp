// SPDX-License-Identifier: MIT
// The temporal pass (transparency/temporal.hpp): a static scene under a moving camera
// converges to the same image as under a still camera (the reprojection follows the camera),
// the history is dropped on a cut, and hashed+taa averages its per-frame thresholds towards
// the leaf's alpha.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/frame_targets.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "transparency/create_technique.hpp"
#include "transparency/temporal.hpp"
#include "run_technique.hpp"

namespace {

using namespace engine::render;
using namespace transparency;

constexpr int kSize = 64;
constexpr float kPixel = 2.0f / kSize;  // one pixel in NDC, exact
const glm::vec4 kBackground{0.1f, 0.2f, 0.3f, 1.0f};

glm::mat4 translation(float x, float y) {
    glm::mat4 m(1.0f);
    m[3] = {x, y, 0.0f, 1.0f};
    return m;
}

// A white card of alpha `alpha` with uv over it, drawn by a technique frame after frame.
class TemporalScene {
public:
    TemporalScene(Backend& backend, TechniqueKind kind, float alpha)
        : backend_(backend), technique_(createTechnique(kind, backend, {})),
          opaque_(backend, {kSize, kSize, technique_->opaqueSamples(), Format::RGBA32F, CompareFunc::Less}) {
        // Edges a quarter pixel off the pixel grid (0.5 - 1/128 in NDC), so that the jitter moves
        // them across pixel centres.
        constexpr float e = 0.5f - 1.0f / 128.0f;
        const glm::vec2 c[6] = {{-e, -e}, {e, -e}, {e, e}, {-e, -e}, {e, e}, {-e, e}};
        std::vector<Vertex> vertices;
        for (const glm::vec2& p : c) {
            Vertex v;
            v.position = {p, 0.5f};
            v.uv = (p + 0.5f) * 0.77f;
            v.color = {1.0f, 1.0f, 1.0f, alpha};
            vertices.push_back(v);
        }
        const auto bytes = std::as_bytes(std::span(vertices));
        buffer_ = backend.createBuffer({"card", BufferKind::Vertex, bytes.size()}, bytes);
        draw_.batch.vertices = buffer_;
        draw_.batch.count = 6;
        draw_.batch.worldBounds = {{-0.5f, -0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}};
        draw_.meshBounds = draw_.batch.worldBounds;
    }
    ~TemporalScene() { backend_.destroy(buffer_); }

    // Frame `index` under `camera`, jittered as the technique asks; returns the red channel.
    std::vector<float> frame(std::uint64_t index, const glm::mat4& camera, bool cut = false) {
        backend_.beginPass(opaque_.passDesc(kBackground));
        backend_.endPass();
        FoliageFrame f;
        f.viewProj = jitteredViewProj(camera, technique_->projectionJitter(index), kSize, kSize);
        f.light = unlitLight();
        f.draws = std::span(&draw_, 1);
        f.frameIndex = index;
        f.cut = cut;
        test_support::runTechnique(backend_, *technique_, opaque_, f);
        const Readback r = backend_.readback(opaque_.color());
        std::vector<float> red;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) red.push_back(r.at(x, y, 0));
        return red;
    }
    Technique& technique() { return *technique_; }

private:
    Backend& backend_;
    std::unique_ptr<Technique> technique_;
    FrameTargets opaque_;
    BufferHandle buffer_;
    FoliageDraw draw_;
};

TEST(Temporal, JitterIsHaltonWithinHalfAPixelAndRepeats) {
    // Halton index 1: (1/2, 1/3), index 2: (1/4, 2/3), to 1/256 pixel.
    EXPECT_EQ(haltonJitter(0, 8), glm::vec2(0.0f, std::round((1.0f / 3.0f - 0.5f) * 256.0f) / 256.0f));
    EXPECT_EQ(haltonJitter(1, 8), glm::vec2(0.25f - 0.5f, std::round((2.0f / 3.0f - 0.5f) * 256.0f) / 256.0f));
    EXPECT_EQ(haltonJitter(3, 8), haltonJitter(11, 8));
    for (std::uint64_t i = 0; i < 16; ++i) {
        const glm::vec2 j = haltonJitter(i, 16);
        EXPECT_GT(j.x, -0.5f);
        EXPECT_LT(j.x, 0.5f);
        EXPECT_GT(j.y, -0.5f);
        EXPECT_LT(j.y, 0.5f);
    }
    // The jitter moves every point by that many pixels, right and down.
    const glm::vec4 p = jitteredViewProj(glm::mat4(1.0f), {0.25f, 0.5f}, kSize, kSize) * glm::vec4(0, 0, 0.5f, 1);
    EXPECT_FLOAT_EQ(p.x, 0.25f * kPixel);
    EXPECT_FLOAT_EQ(p.y, -0.5f * kPixel);
}

// The same camera twice: each pixel fetches its own history texel.
TEST(Temporal, ReprojectionOfAStillCameraIsTheIdentityOnPixels) {
    glm::mat4 m;
    ASSERT_TRUE(reprojectionMatrix(glm::mat4(1.0f), glm::mat4(1.0f), kSize, kSize, m));
    const glm::vec4 p = m * glm::vec4(10.5f, 20.5f, 0.3f, 1.0f);
    EXPECT_FLOAT_EQ(p.x / p.w, 10.5f);
    EXPECT_FLOAT_EQ(p.y / p.w, 20.5f);
    EXPECT_FALSE(reprojectionMatrix(glm::mat4(0.0f), glm::mat4(1.0f), kSize, kSize, m)) << "not invertible";
}

// A static card, 12 frames: under a still camera, and under a camera that moves a pixel left
// every frame and ends where the still one is. The reprojection fetches each pixel's history
// where the card was, so both end with the same image, bit for bit; fetching the history at
// the same pixel instead (no reprojection) smears the card over its path and fails this.
TEST(Temporal, StaticSceneUnderAMovingCameraConvergesToTheStillCamerasImage) {
    for (TechniqueKind kind : {TechniqueKind::HashedTaa, TechniqueKind::AlphaTestTaa, TechniqueKind::SsamTaa}) {
        auto backend = soft::createSoftBackend({.threads = 2});
        TemporalScene still(*backend, kind, 0.5f), moving(*backend, kind, 0.5f);
        constexpr int kFrames = 12;
        std::vector<float> a, b;
        for (int i = 0; i < kFrames; ++i) {
            a = still.frame(std::uint64_t(i), translation(float(kFrames - 1) * kPixel, 0.0f));
            b = moving.frame(std::uint64_t(i), translation(float(i) * kPixel, 0.0f));
        }
        EXPECT_EQ(a, b) << techniqueName(kind);
        // The average is at work: pixels neither background nor white (hashed: inside the
        // card; alpha testing keeps the whole card, so only along its jittered edges; SSAM: the
        // whole card, its mask 0.5 squared).
        int between = 0;
        for (float v : a) between += v > 0.15f && v < 0.95f;
        EXPECT_GT(between, kind == TechniqueKind::HashedTaa ? 500 : 40) << techniqueName(kind);
    }
}

// ssam+taa draws SSAM inside the temporal pass's own pass: SSAM's depth restore, which needs a
// copy of the depth among its targets, is refused by name rather than drawn without it.
TEST(Temporal, SsamTaaRefusesTheDepthRestore) {
    auto backend = soft::createSoftBackend({.threads = 1});
    TechniqueOptions options;
    options.ssam.depthMaskThreshold = 0.3f;
    try {
        createTechnique(TechniqueKind::SsamTaa, *backend, options);
        ADD_FAILURE() << "ssam+taa accepted depthMaskThreshold 0.3";
    } catch (const engine::Error& e) {
        EXPECT_NE(std::string(e.what()).find("ssam+taa: depthMaskThreshold"), std::string::npos) << e.what();
    }
    options.ssam.depthMaskThreshold = 0.0f;
    EXPECT_NE(createTechnique(TechniqueKind::SsamTaa, *backend, options), nullptr);
}

// hashed+taa: the threshold changes every frame, so the history averages the kept fraction
// towards the leaf's alpha: after 40 frames the card's pixels are on average within 0.03 of
// white over the background by 0.5, and most within 0.2 each, where one frame of hashed is
// all or nothing at each pixel. Not all: where the current frame's 3x3 neighbourhood happens
// to be all kept or all discarded, the clamp resets the history to it.
TEST(Temporal, HashedTaaAveragesTheThresholdTowardsTheAlpha) {
    auto backend = soft::createSoftBackend({.threads = 2});
    TemporalScene scene(*backend, TechniqueKind::HashedTaa, 0.5f);
    std::vector<float> image;
    for (int i = 0; i < 40; ++i) image = scene.frame(std::uint64_t(i), glm::mat4(1.0f));
    const float want = 0.5f * 1.0f + 0.5f * kBackground.r;
    double sum = 0.0;
    int n = 0, near = 0;
    for (int y = 20; y < 44; ++y)
        for (int x = 20; x < 44; ++x) {
            const float v = image[std::size_t(y * kSize + x)];
            sum += v, ++n;
            near += std::abs(v - want) < 0.2f;
        }
    EXPECT_NEAR(sum / n, want, 0.03);
    std::printf("hashed+taa after 40 frames: mean %.4f (want %.4f), %d of %d pixels within 0.2\n", sum / n, want, near,
                n);
    EXPECT_GT(near, n * 3 / 4) << "most pixels have averaged several thresholds";  // measured 479 of 576
}

// A cut (or a frame index that does not follow the last) drops the history: the frame is
// the technique's own, as on a first frame.
TEST(Temporal, ACutDropsTheHistory) {
    auto backend = soft::createSoftBackend({.threads = 1});
    TemporalScene scene(*backend, TechniqueKind::HashedTaa, 0.5f), fresh(*backend, TechniqueKind::HashedTaa, 0.5f);
    for (int i = 0; i < 5; ++i) scene.frame(std::uint64_t(i), glm::mat4(1.0f));
    EXPECT_EQ(scene.frame(5, glm::mat4(1.0f), /*cut=*/true), fresh.frame(5, glm::mat4(1.0f)));
    for (int i = 6; i < 9; ++i) scene.frame(std::uint64_t(i), glm::mat4(1.0f));
    EXPECT_EQ(scene.frame(20, glm::mat4(1.0f)), fresh.frame(20, glm::mat4(1.0f))) << "frame 20 after 8";
}

}  // namespace
