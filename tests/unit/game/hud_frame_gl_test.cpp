// SPDX-License-Identifier: MIT
// racer's HUD on the GL backend (EGL; Mesa llvmpipe without a GPU): hud_frame_check.hpp.
#include <gtest/gtest.h>

#include "engine/render/gl/gl_backend.hpp"
#include "hud_frame_check.hpp"

namespace {

TEST(HudFrameGl, ChangesItsBoxAndNothingElse) {
    auto gl = engine::render::gl::createGlBackend({});
    racer::testing::expectHudOnlyInsideItsBox(*gl);
}

}  // namespace
