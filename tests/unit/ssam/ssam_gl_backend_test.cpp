// SPDX-License-Identifier: MIT
// The shared exact SSAM cases (ssam_cases.hpp) on the OpenGL backend (headless EGL; llvmpipe on
// CI), the same test bodies as on the soft backend.
#include "ssam_cases.hpp"

#include "engine/render/gl/gl_backend.hpp"

// The backend the shared cases run on; a global name so ctest lists Ssam.<case><OnGl>.
struct OnGl {
    static std::unique_ptr<engine::render::Backend> create() { return engine::render::gl::createGlBackend({}); }
    // 2 codes: llvmpipe blends RGBA8 targets in 8-bit fixed point (GL 4.5 §17.3.6 allows it;
    // README "Differential tolerances"), on top of the expected value's own rounding.
    static constexpr float kBlendTolerance = 2.0f / 255.0f + 1e-6f;
};

namespace ssam_cases {
namespace {

INSTANTIATE_TYPED_TEST_SUITE_P(Ssam, SsamCases, ::testing::Types<OnGl>);

}  // namespace
}  // namespace ssam_cases
