// SPDX-License-Identifier: MIT
#pragma once
// One benchmark frame: the opaque pass (ground, trunks: OpaqueLit, reverse-Z, depth test
// Greater, as game/src/frame_renderer.cpp draws it) into engine::render::FrameTargets, then the
// technique's foliage (Technique::render, which resolves), or just the resolve for the
// opaque-only frame. The scene is extracted and its instances uploaded once per view
// (ViewUpload), outside the timed frame, so every technique gets the same input and the
// time is the rendering alone.
#include <memory>
#include <span>
#include <vector>

#include "bench_scenes.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/frame_graph/transient_texture_pool.hpp"
#include "engine/render/frame_targets.hpp"
#include "engine/scene/draw_lists.hpp"
#include "foliage_upload.hpp"
#include "transparency/create_technique.hpp"
#include "transparency/temporal.hpp"

namespace bench {

// Frames a technique that needs history (the temporal pass) is drawn before it is measured:
// with a blend of 0.1 the first frame's weight is then 0.9^16 = 0.19 of what it was.
inline constexpr int kHistoryFrames = 16;

inline constexpr engine::render::CompareFunc kDepthFunc = engine::render::CompareFunc::Greater;  // reverse-Z

// The scene seen from one camera: draw lists extracted, instance buffers uploaded.
class ViewUpload {
public:
    ViewUpload(engine::render::Backend& backend, BenchScene& scene, const BenchCamera& camera);
    ~ViewUpload();
    ViewUpload(const ViewUpload&) = delete;
    ViewUpload& operator=(const ViewUpload&) = delete;

    const BenchCamera& camera() const { return camera_; }
    const engine::scene::DrawLists& lists() const { return lists_; }
    std::span<const engine::render::BufferHandle> opaqueInstances() const { return opaqueInstances_; }
    transparency::FoliageFrame foliageFrame(const glm::mat4& viewProj) const;
    std::size_t foliageInstances() const;

private:
    engine::render::Backend& backend_;
    BenchCamera camera_;
    engine::scene::DrawLists lists_;
    std::vector<engine::render::BufferHandle> opaqueInstances_;
    racer::FoliageUpload foliage_;
    std::span<const transparency::FoliageDraw> draws_;
};

// Draws frames of one scene on one backend.
class FrameDrawer {
public:
    FrameDrawer(engine::render::Backend& backend, const engine::scene::MeshLibrary& library);
    ~FrameDrawer();
    FrameDrawer(const FrameDrawer&) = delete;
    FrameDrawer& operator=(const FrameDrawer&) = delete;

    // The frame as a frame graph, as racer builds it: the opaque pass, then the technique's
    // passes (or the plain resolve when technique is null), then a present pass. The
    // graph's transients (SSAM's mask and foliage, WBOIT's accumulators) come from a pool
    // kept across frames, so timed frames after the first create no texture. Frame
    // `frameIndex` of a sequence (temporal techniques: its projection jitter, and the history
    // kept from the frame before unless `cut`).
    void draw(engine::render::FrameTargets& targets, transparency::Technique* technique, const ViewUpload& view,
              std::uint64_t frameIndex = 0, bool cut = false);

private:
    void drawOpaque(engine::render::FrameTargets& targets, const ViewUpload& view, const glm::mat4& viewProj);

    engine::render::Backend& backend_;
    const engine::scene::MeshLibrary& library_;
    engine::render::PipelineHandle culled_, twoSided_;
    engine::render::TransientTexturePool transients_;
};

}  // namespace bench
