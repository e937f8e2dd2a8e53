// SPDX-License-Identifier: MIT
// The parameter-block probe (tests/support/param_block_probe.hpp) on the GL driver: the
// declarations its block gives compile and link, and every member reaches the body with the
// value the struct holds (the same bits as the soft kernel, unit_param_block).
#include <gtest/gtest.h>

#include "engine/render/gl/gl_backend.hpp"
#include "param_block_probe.hpp"

namespace {

TEST(GlParamBlock, EveryMemberReachesTheBody) {
    const auto gl = engine::render::gl::createGlBackend();
    const ssam::testing::ProbeParams p = ssam::testing::probeValues();
    for (const bool withDetail : {false, true})
        EXPECT_EQ(ssam::testing::probeMismatches(ssam::testing::drawProbe(*gl, p, withDetail), p, withDetail), 0)
            << (withDetail ? "with" : "without") << " the detail texture";
}

}  // namespace
