// SPDX-License-Identifier: MIT
#include "foliage_upload.hpp"

namespace racer {

using namespace engine::render;

std::span<const transparency::FoliageDraw> FoliageUpload::upload(const engine::scene::DrawLists& lists,
                                                                 const engine::scene::MeshLibrary& library) {
    instances_.beginFrame();
    draws_.clear();
    for (const engine::scene::DrawBatch& b : lists.mask) {
        const engine::scene::MeshPart& part = library.part(b.part);

        transparency::FoliageDraw d;
        d.batch.vertices = engine::scene::vertexBufferOf(b, part);  // deformed copy (modules/wind) or shared
        d.batch.indices = part.indices;
        d.batch.count = part.indexCount;
        d.batch.instances =
            instances_.upload("foliage instances", BufferKind::Instance, std::as_bytes(std::span(b.instances)));
        d.batch.instanceCount = static_cast<std::uint32_t>(b.instances.size());
        d.batch.baseColor = part.material.baseColor;
        d.batch.baseColorFactor = part.material.baseColorFactor;
        d.batch.worldBounds = {b.worldBounds.min, b.worldBounds.max};
        d.batch.unlit = part.material.unlit;
        d.batch.motionVertices = b.motionVertices;  // the wind's motion copy, for the temporal pass
        d.instances = b.instances;
        d.meshBounds = {part.bounds.min, part.bounds.max};
        d.alphaCutoff = part.material.alphaCutoff;
        d.lodLevel = b.level;
        d.crossfading = b.crossfading;
        draws_.push_back(d);
    }
    moving_.clear();
    for (const engine::scene::DrawBatch& b : lists.opaque) {
        if (!b.motionVertices) continue;
        const engine::scene::MeshPart& part = library.part(b.part);
        transparency::FoliageDraw d;
        d.batch.vertices = engine::scene::vertexBufferOf(b, part);
        d.batch.indices = part.indices;
        d.batch.count = part.indexCount;
        d.batch.instances =
            instances_.upload("moving instances", BufferKind::Instance, std::as_bytes(std::span(b.instances)));
        d.batch.instanceCount = static_cast<std::uint32_t>(b.instances.size());
        d.batch.worldBounds = {b.worldBounds.min, b.worldBounds.max};
        d.batch.motionVertices = b.motionVertices;  // opaque: no texture, alpha 1, never cut
        d.instances = b.instances;
        d.meshBounds = {part.bounds.min, part.bounds.max};
        d.alphaCutoff = 0.0f;
        moving_.push_back(d);
    }
    return draws_;
}

}  // namespace racer
