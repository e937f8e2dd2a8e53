// SPDX-License-Identifier: MIT
#pragma once
// ssam-bench's temporal measures: a technique that keeps history (the temporal pass) cannot be
// judged on one frame, nor one without history on its luck in one frame. So every technique
// draws the scene's sideways pan for `temporalFrames` frames, and each frame is compared with
// the exact reference of that same frame (soft backend), over the foliage pixels only (where
// the reference differs from the opaque-only frame: the rest is the same opaque pass for all).
// Reported per technique: ꟻLIP and RMSE converged (the median over the last half of the
// frames) and worst (the largest). A technique with history draws kHistoryFrames of the first
// view before the pan, so none is measured on its first frame.
//
// The frames are drawn frame by frame across all techniques at once (every technique keeps
// its targets and history for the whole pan), so each reference frame is drawn once and
// never stored.
#include <vector>

#include "bench_result.hpp"
#include "bench_runner.hpp"
#include "bench_scenes.hpp"
#include "engine/render/backend.hpp"

namespace bench {

struct TemporalBackend {
    std::string name;  // "soft", "gl"
    engine::render::Backend* backend = nullptr;
    BenchScene* scene = nullptr;  // the scene as uploaded to that backend
};

// Fills the temporal columns of `rows` (those of this scene, matched by technique and
// backend) for the scene of `backends.front()` (the soft backend, whose reference judges all).
// Prints one progress line per frame.
void measureTemporal(const std::vector<TemporalBackend>& backends, const BenchOptions& options,
                     std::vector<BenchRow>& rows);

}  // namespace bench
