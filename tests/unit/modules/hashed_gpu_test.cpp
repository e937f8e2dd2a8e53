// SPDX-License-Identifier: MIT
// Hashed alpha testing on GL and on Vulkan (gpu_backend.hpp) against the soft backend. The threshold is an integer hash of
// the cell and a polynomial of plain operations (`precise` in GLSL), so given the same uv and
// derivatives both backends compute the same bits: a card whose uv and derivatives are exact
// at every pixel centre shows it bit for bit. Elsewhere the inputs differ by rounding: GL
// (and lavapipe, llvmpipe behind Vulkan) interpolates uv its own way and its derivatives are per-quad differences of the
// interpolated uv/w and 1/w, where the soft backend evaluates the triangle's planes, so a
// pixel whose uv lies within rounding of a cell edge, or whose alpha is within rounding of
// its threshold, may flip. The test bounds how many do.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/render/frame_targets.hpp"
#include "gpu_backend.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "transparency/create_technique.hpp"
#include "transparency/hashed_alpha.hpp"
#include "program_card.hpp"
#include "run_technique.hpp"

namespace {

using namespace engine::render;
using namespace transparency;
using namespace transparency::testing;

constexpr int kSize = 64;

std::vector<Vertex> card(const glm::vec3 (&corners)[4], float uvMax, float alpha) {
    return test_support::cardVertices(corners, uvMax, {1.0f, 1.0f, 1.0f, alpha});
}

// HashedLit with outputThreshold: the threshold itself at every pixel.
Readback thresholds(Backend& backend, const std::vector<Vertex>& vertices, bool anisotropic) {
    HashedLitParams params;
    params.light = unlitLight();
    params.seed = 12345u;
    params.anisotropic = anisotropic;
    params.outputThreshold = true;
    return test_support::drawProgramCard(backend, hashedLitProgram(), params, vertices, kSize);
}

TEST(SSAM_GPU_SUITE(Hashed), ThresholdIsBitIdenticalWhereUvAndDerivativesAreExact) {
    // Screen-filling, w = 1, uv = 0.75 (x + 0.5) / 64 at pixel centres: exact in a float, and
    // a derivative of 3/256 per pixel, no power of two, so both hashes are blended.
    const glm::vec3 corners[4] = {{-1, -1, 0.5f}, {1, -1, 0.5f}, {1, 1, 0.5f}, {-1, 1, 0.5f}};
    for (bool anisotropic : {false, true}) {
        auto soft = soft::createSoftBackend({.threads = 1});
        auto gpu = gpuBackend();
        const Readback s = thresholds(*soft, card(corners, 0.75f, 1.0f), anisotropic);
        const Readback g = thresholds(*gpu, card(corners, 0.75f, 1.0f), anisotropic);
        int differ = 0;
        for (std::size_t i = 0; i < s.values.size(); ++i) differ += s.values[i] != g.values[i];
        EXPECT_EQ(differ, 0) << (anisotropic ? "anisotropic" : "isotropic");
    }
}

// A card tilted away under perspective: the frames may differ only in pixels that flip
// (kept on one backend, discarded on the other).
TEST(SSAM_GPU_SUITE(Hashed), TechniqueFrameMatchesTheSoftBackendButForRoundingFlips) {
    auto run = [](Backend& backend) {
        auto technique = createTechnique(TechniqueKind::Hashed, backend, {});
        const glm::vec3 corners[4] = {{-2, -1.5f, -3}, {2, -1.5f, -3}, {2, 1.5f, -9}, {-2, 1.5f, -9}};
        const test_support::OneDraw draw(backend, card(corners, 3.1f, 0.5f), {{-2, -1.5f, -9}, {2, 1.5f, -3}});
        return test_support::frameOverClear(
            backend, *technique, draw, glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f), kSize, {0, 0, 0, 1});
    };
    auto soft = soft::createSoftBackend({.threads = 1});
    auto gpu = gpuBackend();
    const Readback s = run(*soft), g = run(*gpu);
    int kept = 0, flipped = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            kept += s.at(x, y, 0) > 0.5f;
            flipped += (s.at(x, y, 0) > 0.5f) != (g.at(x, y, 0) > 0.5f);
        }
    ASSERT_GT(kept, 500) << "the card is in view, about half its pixels kept";
    std::printf("hashed soft vs %s: %d of %d kept pixels flip\n", kGpuName, flipped, kept);
    EXPECT_LE(flipped, kept / 50) << "at most 2% of the kept pixels";
}

}  // namespace
