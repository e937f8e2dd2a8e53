// SPDX-License-Identifier: MIT
// racer's HUD on the soft backend (hud_frame_check.hpp) and its text (hud_text.hpp).
#include <gtest/gtest.h>

#include "engine/render/soft/soft_backend.hpp"
#include "hud_frame_check.hpp"

namespace {

TEST(HudFrame, ChangesItsBoxAndNothingElse) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    racer::testing::expectHudOnlyInsideItsBox(*soft);
}

TEST(HudText, SaysTechniqueBackendSizeAndWhatTheTimesAre) {
    racer::HudFacts f{
        "ssam", "soft", 1280, 720, "previous frame", 40.0, {{"opaque", 3.25, false}, {"light shafts", 0.0, true}}, ""};
    const std::vector<std::string> lines = racer::hudLines(f);
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_EQ(lines[0], "ssam | soft | 1280x720");
    EXPECT_EQ(lines[1], "frame 40.0 ms (25.0 fps), previous frame, wall clock");
    EXPECT_EQ(lines[2], "passes, ms: CPU wall time of each pass");
    EXPECT_EQ(lines[3], "     3.25  opaque");
    EXPECT_EQ(lines[4], "  skipped  light shafts");
    f.backend = "gl";
    f.extra = "camera chase";
    EXPECT_EQ(racer::hudLines(f)[1], "camera chase");
    EXPECT_EQ(racer::hudLines(f)[3], "passes, ms: GPU time of each pass (GL_TIME_ELAPSED)");
    f.backend = "gles (WebGL2)";  // the web page's; the GLES driver has CPU times only
    EXPECT_EQ(racer::hudLines(f)[3], "passes, ms: CPU time recording each pass (ES: no timer query)");
    f.backend = "gl";
    EXPECT_EQ(racer::compareHudLine("ssam", "alpha-test"),
              "side by side: ssam | alpha-test (passes: alpha-test's frame, then ssam's)");
    f.transientBytes = 115200;  // the previous frame's peak (FrameRenderer::peakTransientBytes)
    EXPECT_EQ(racer::hudLines(f)[3], "transient targets: peak 115200 bytes (112.5 KiB), previous frame");
    f.frameMs = -1.0;
    EXPECT_EQ(racer::hudLines(f).back(), "frame time: none yet (first frame)");
}

}  // namespace
