// SPDX-License-Identifier: MIT
#pragma once
// The bridge from the scene's draw lists to the foliage techniques: each alpha-tested
// (Mask) batch becomes a transparency::FoliageDraw whose instances live in a buffer of the
// frame, from a pool: the next frame's upload reuses them (engine/render frame_buffer_pool.hpp).
#include <span>
#include <vector>

#include "engine/core/non_copyable.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/frame_buffer_pool.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/mesh_library.hpp"
#include "transparency/technique.hpp"

namespace racer {

class FoliageUpload : engine::NonCopyable {
public:
    explicit FoliageUpload(engine::render::Backend& backend) : instances_(backend) {}

    // Valid until the next call (the draws point into `lists`' instance vectors).
    std::span<const transparency::FoliageDraw> upload(const engine::scene::DrawLists& lists,
                                                      const engine::scene::MeshLibrary& library);
    // The opaque batches of the last upload() that carry a motion copy (a rigidly moving entity,
    // engine/scene rigid_motion.hpp), as FoliageFrame::movingOpaque: opaque, alpha 1, cutoff 0.
    std::span<const transparency::FoliageDraw> movingOpaque() const { return moving_; }

private:
    engine::render::FrameBufferPool instances_;
    std::vector<transparency::FoliageDraw> draws_;
    std::vector<transparency::FoliageDraw> moving_;
};

}  // namespace racer
