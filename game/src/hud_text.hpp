// SPDX-License-Identifier: MIT
#pragma once
// What racer's HUD says (key H in the window, --hud in captures): the technique, the
// backend, the render size, the frame time and each pass's time, as lines of text for
// modules/hud. Times are of frames already drawn (a frame cannot show its own), labelled
// with what they measure: racer's wall clock for the frame; for the passes the backend's
// own timings (soft: wall time of each pass on the CPU; GL: GPU time from GL_TIME_ELAPSED
// queries), and the bytes the frame graph's transient targets needed at once.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/scene/draw_lists.hpp"

namespace racer {

struct HudFacts {
    std::string technique;
    std::string backend;  // Backend::name()
    int width = 0, height = 0;
    std::string timeSpan;   // which frames the times are of, e.g. "previous frame"
    double frameMs = -1.0;  // < 0: none measured yet
    std::vector<engine::render::PassTiming> passes;
    std::string extra;  // one more line when not empty (the compare's pair, the driver)
    // The frame graph's peak transient bytes (FrameRenderer::peakTransientBytes) of the
    // frame before; < 0: no line.
    std::int64_t transientBytes = -1;
    std::string levelsOfDetail{};  // lodCountsLine() of a frame; empty: no line
};

std::vector<std::string> hudLines(const HudFacts& facts);

// How many plants drew each level of detail (engine/scene/levels_of_detail.hpp), for the HUD and
// the frame graph's dump: "levels of detail: 120 full, 40 middle, 300 impostor"; empty when no
// instance has levels.
std::string lodCountsLine(const engine::scene::DrawLists& lists);

// The compare's line for HudFacts::extra: which technique is on which side, and that the
// pass list holds both frames' passes (B's, rendered first, then A's).
std::string compareHudLine(const std::string& left, const std::string& right);

}  // namespace racer
