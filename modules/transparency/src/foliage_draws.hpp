// SPDX-License-Identifier: MIT
#pragma once
// What every technique does with a FoliageFrame: pick the draws in view, and turn a batch
// into a DrawDesc with the programs' parameters. Shared so that every technique shades
// the same fragments the same way and differs only in how it combines them.
#include <vector>

#include "engine/render/frame_targets.hpp"
#include "engine/render/masked_batch.hpp"
#include "transparency/technique.hpp"

namespace transparency::detail {

// The draws that can touch a width x height target, in submission order ([Hathaway 2010] §3.8).
std::vector<const FoliageDraw*> visibleDraws(const FoliageFrame& frame, int width, int height);

// The batches of every draw, for ssam::FoliageView.
std::vector<engine::render::MaskedBatch> batchesOf(const FoliageFrame& frame);

// MaskedLit's parameters for one batch under the frame's camera and light.
engine::render::SurfaceParams surfaceParams(const FoliageFrame& frame, const engine::render::MaskedBatch& batch);

// MaskedLit on both faces (foliage is double-sided), nothing else set: each technique
// adds its depth, blend and alpha state.
engine::render::PipelineDesc foliagePipeline(const char* name);

// The opaque targets' resolved colour and depth, loaded: for techniques that draw after
// the resolve.
engine::render::PassDesc resolvedPass(const engine::render::FrameTargets& opaque, const char* name);

// One draw of a batch (all its instances, or `instances`/`instanceCount` when given).
engine::render::DrawDesc batchDraw(const engine::render::MaskedBatch& batch, engine::render::PipelineHandle pipeline,
                                   engine::render::DrawParams params);

}  // namespace transparency::detail
