// SPDX-License-Identifier: MIT
// Differential test on GL: the random scenes of tests/support/differential_scenes.hpp on the soft
// backend and the GL backend (llvmpipe here), compared pixel by pixel with the tolerances
// written there.
#include <gtest/gtest.h>

#include "differential_scenes.hpp"
#include "engine/render/gl/gl_backend.hpp"

namespace ssam::test {
namespace {

namespace gl = engine::render::gl;

class GlDifferential : public ::testing::TestWithParam<differential::Case> {};

TEST_P(GlDifferential, RandomScenesMatchTheSoftBackend) {
    gl::GlOptions options;
    options.failModes = GetParam().perTriangle ? gl::FailModeStrategy::PerTriangle : gl::FailModeStrategy::TwoPass;
    auto backend = gl::createGlBackend(options);
    differential::expectRandomScenesMatchSoft(*backend, "gl", GetParam());
}

INSTANTIATE_TEST_SUITE_P(Scenes, GlDifferential, ::testing::ValuesIn(differential::cases()),
                         [](const auto& info) { return differential::caseName(info.param); });

}  // namespace
}  // namespace ssam::test
