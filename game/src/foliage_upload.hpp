// SPDX-License-Identifier: MIT
#pragma once
// The bridge from the scene's draw lists to the foliage techniques: each alpha-tested
// (Mask) batch becomes a transparency::FoliageDraw whose instances live in a buffer of the
// frame. The buffers of one frame are released when the next frame is uploaded.
#include <span>
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/mesh_library.hpp"
#include "transparency/technique.hpp"

namespace racer {

class FoliageUpload {
public:
    explicit FoliageUpload(engine::render::Backend& backend) : backend_(backend) {}
    ~FoliageUpload();
    FoliageUpload(const FoliageUpload&) = delete;
    FoliageUpload& operator=(const FoliageUpload&) = delete;

    // Valid until the next call (the draws point into `lists`' instance vectors).
    std::span<const transparency::FoliageDraw> upload(const engine::scene::DrawLists& lists,
                                                      const engine::scene::MeshLibrary& library);

private:
    void release();

    engine::render::Backend& backend_;
    std::vector<engine::render::BufferHandle> buffers_;
    std::vector<transparency::FoliageDraw> draws_;
};

}  // namespace racer
