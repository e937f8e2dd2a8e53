// SPDX-License-Identifier: MIT
// racer --compare on the GL backend (EGL; Mesa llvmpipe without a GPU): compare_frame_check.hpp.
#include <gtest/gtest.h>

#include "compare_frame_check.hpp"
#include "engine/render/gl/gl_backend.hpp"

namespace {

TEST(CompareFrameGl, HalvesAreEachTechniquesOwnFrame) {
    auto gl = engine::render::gl::createGlBackend({});
    racer::testing::expectHalvesAreEachTechniquesOwnFrame(*gl);
}

}  // namespace
