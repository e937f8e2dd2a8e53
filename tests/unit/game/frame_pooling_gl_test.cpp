// SPDX-License-Identifier: MIT
// frame_pooling_test.cpp's steady-state count on the GL backend (EGL; Mesa llvmpipe without a GPU).
#include <gtest/gtest.h>

#include "engine/render/gl/gl_backend.hpp"
#include "racing_frame.hpp"

namespace {

TEST(FramePoolingGl, SteadyRacingFramesCreateNothingOnGl) {
    auto gl = engine::render::gl::createGlBackend({});
    racer::testing::expectNoCreationsInSteadyState(*gl);
}

}  // namespace
