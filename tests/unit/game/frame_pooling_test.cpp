// SPDX-License-Identifier: MIT
// The racing frame as racer builds it (frame graph, every living-scene module on) creates no
// texture or buffer once it runs steadily: per-frame instance buffers and the graph's
// transient targets come from pools (engine/render frame_buffer_pool.hpp,
// transient_texture_pool.hpp). Counted through a backend decorator; the GL case is
// frame_pooling_gl_test.cpp (label gl).
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "engine/render/soft/soft_backend.hpp"
#include "racing_frame.hpp"

namespace {

using namespace racer;
using racer::testing::RacingFrame;

TEST(FramePooling, SteadyRacingFramesCreateNothingOnSoft) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    racer::testing::expectNoCreationsInSteadyState(*soft);
}

// racer --dump-graph: SSAM's passes run in the chase view, and under the sky camera (no
// foliage in view) they are skipped as empty, as is the wheel dust that is out of view.
TEST(FramePooling, TheDumpedGraphMarksSsamEmptyWhenNoFoliageIsInView) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    RacingFrame frame(*soft);
    frame.run(0, 1);
    std::ostringstream chase;
    frame.renderer.dumpGraph(chase);
    for (const char* pass : {"\"ssam mask\"", "\"ssam colour\"", "\"ssam composite\"", "\"grass", "\"present\""})
        EXPECT_NE(chase.str().find(pass), std::string::npos) << pass << "\n" << chase.str();
    EXPECT_EQ(chase.str().find("ssam mask\\n(empty)"), std::string::npos) << chase.str();

    frame.run(1, 1, CameraMode::Sky);
    std::ostringstream sky;
    frame.renderer.dumpGraph(sky);
    EXPECT_NE(sky.str().find("ssam mask\\n(empty)"), std::string::npos) << sky.str();
    EXPECT_NE(sky.str().find("ssam composite\\n(empty)"), std::string::npos) << sky.str();
}

}  // namespace
