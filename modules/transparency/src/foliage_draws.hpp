// SPDX-License-Identifier: MIT
#pragma once
// What every technique does with a FoliageFrame: pick the draws in view, and turn a batch
// into a DrawDesc with the programs' parameters. Shared so that every technique shades
// the same fragments the same way and differs only in how it combines them.
#include <span>
#include <vector>

#include "engine/render/frame_targets.hpp"
#include "engine/render/masked_batch.hpp"
#include "transparency/lod_dither.hpp"
#include "transparency/technique.hpp"

namespace transparency::detail {

// The draws that can touch a width x height target, in submission order ([Hathaway 2010] §3.8).
std::vector<const FoliageDraw*> visibleDraws(const FoliageFrame& frame, int width, int height);

// The union of the visible draws' screen bounds: the region a composite has to cover.
engine::render::Rect screenRegion(std::span<const FoliageDraw* const> visible, const FoliageFrame& frame, int width,
                                  int height);

// The batches of every draw, for ssam::FoliageView.
std::vector<engine::render::MaskedBatch> batchesOf(const FoliageFrame& frame);

// How a draw's crossfade is dithered by the techniques that cannot fade by alpha.
inline LodDither lodDitherOf(const FoliageDraw& draw) { return lodDitherFor(draw.lodLevel, draw.crossfading); }

// MaskedLit's parameters for one batch under the frame's camera and light.
engine::render::SurfaceParams surfaceParams(const FoliageFrame& frame, const engine::render::MaskedBatch& batch);

// MaskedLit on both faces (foliage is double-sided), nothing else set: each technique
// adds its depth, blend and alpha state.
engine::render::PipelineDesc foliagePipeline(const char* name);

// foliagePipeline blended straight-alpha "over" the frame ([Moore 2015]), depth-tested against
// the opaque depth and writing none, the frame's alpha kept: both blending techniques' state.
engine::render::PipelineDesc blendOverPipeline(const char* name, engine::render::CompareFunc depthFunc);

// The opaque targets' resolved colour and depth, loaded: for techniques that draw after
// the resolve.
engine::render::PassDesc resolvedPass(const engine::render::FrameTargets& opaque, const char* name);

// One full-screen draw of `pipeline` onto the opaque colour (loaded, no depth test) inside
// `region`, in its own pass: how the techniques that shade into intermediates end their frame.
void compositeOnto(engine::render::Backend& backend, const engine::render::FrameTargets& opaque, const char* name,
                   engine::render::PipelineHandle pipeline, engine::render::DrawParams params,
                   const engine::render::Rect& region);

// One draw of a batch (all its instances, or `instances`/`instanceCount` when given).
engine::render::DrawDesc batchDraw(const engine::render::MaskedBatch& batch, engine::render::PipelineHandle pipeline,
                                   engine::render::DrawParams params);

}  // namespace transparency::detail
