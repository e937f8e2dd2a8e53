// SPDX-License-Identifier: MIT
#include "engine/scene/draw_lists.hpp"

#include <algorithm>

#include "engine/scene/components.hpp"

namespace engine::scene {

DrawLists extractDrawLists(ecs::Registry& registry, const MeshLibrary& library, const glm::mat4& viewProj,
                           const glm::vec3& cameraPosition) {
    // Per part, the batch it fills this frame (index into its list), so instances of one
    // mesh become one instanced draw.
    // Crossfading instances (weight < 1) have batches of their own (DrawBatch::crossfading).
    std::vector<int> batchOfPart(library.partCount(), -1), fadingBatchOfPart(library.partCount(), -1);
    DrawLists lists;
    std::vector<DrawBatch> ownMask, ownOpaque;  // batches of overridden parts, one entity each
    registry.view<const Transform, const Renderable>().each([&](ecs::Entity e, const Transform& t,
                                                                const Renderable& r) {
        const glm::mat4 model = t.matrix();
        const LevelsOfDetail* lod = registry.tryGet<LevelsOfDetail>(e);
        // One level, or the two of a crossfade, each with its weight in the tint's alpha.
        auto drawLevel = [&](int chosen, float weight, bool crossfading) {
            const int level = lod ? std::clamp(chosen, 0, lod->levels - 1) : 0;
            const VertexOverride* override = level == 0 ? registry.tryGet<VertexOverride>(e) : nullptr;
            const std::vector<std::uint32_t>& parts =
                library.partsOf(level > 0 ? lod->models[std::size_t(level)] : r.model);
            bool drawn = false;
            for (std::size_t i = 0; i < parts.size(); ++i) {
                const std::uint32_t partIndex = parts[i];
                const MeshPart& part = library.part(partIndex);
                const render::BufferHandle own =
                    override && i < override->buffers.size() ? override->buffers[i] : render::BufferHandle{};
                const bool ownBounds = own && i < override->bounds.size() && !override->bounds[i].empty();
                const Aabb world = (ownBounds ? override->bounds[i] : part.bounds).transformed(model);
                if (!intersectsViewVolume(world, viewProj)) continue;
                drawn = true;
                const render::Instance instance{model, glm::vec4(1.0f, 1.0f, 1.0f, weight)};
                const float distance = glm::length((world.min + world.max) * 0.5f - cameraPosition);
                if (part.material.surface == SurfaceClass::Blend) {
                    lists.blend.push_back({partIndex, own, {instance}, world, distance, {}, level, crossfading});
                    continue;
                }
                if (own) {
                    const render::BufferHandle motion =
                        i < override->motionBuffers.size() ? override->motionBuffers[i] : render::BufferHandle{};
                    (part.material.surface == SurfaceClass::Mask ? ownMask : ownOpaque)
                        .push_back({partIndex, own, {instance}, world, distance, motion, level, crossfading});
                    continue;
                }
                std::vector<DrawBatch>& list = part.material.surface == SurfaceClass::Mask ? lists.mask : lists.opaque;
                int& slot = (crossfading ? fadingBatchOfPart : batchOfPart)[partIndex];
                if (slot < 0) {
                    slot = static_cast<int>(list.size());
                    list.push_back({partIndex, {}, {}, {}, 0.0f, {}, level, crossfading});
                }
                list[slot].instances.push_back(instance);
                list[slot].worldBounds.add(world);
            }
            if (lod && drawn) ++lists.instancesAtLevel[std::size_t(level)];
        };
        if (lod && lod->blend.crossfading()) {
            drawLevel(lod->blend.levels[0], 1.0f - lod->blend.coarserWeight, true);
            drawLevel(lod->blend.levels[1], lod->blend.coarserWeight, true);
        } else {
            drawLevel(lod ? lod->level : 0, 1.0f, false);
        }
    });
    // A part's steady batch, then its crossfading one, then its own-vertex batches in view
    // order (deterministic).
    auto byPart = [](const DrawBatch& a, const DrawBatch& b) {
        auto group = [](const DrawBatch& d) { return d.vertices ? 2 : (d.crossfading ? 1 : 0); };
        return a.part != b.part ? a.part < b.part : group(a) < group(b);
    };
    lists.opaque.insert(lists.opaque.end(), ownOpaque.begin(), ownOpaque.end());
    lists.mask.insert(lists.mask.end(), ownMask.begin(), ownMask.end());
    std::stable_sort(lists.opaque.begin(), lists.opaque.end(), byPart);
    std::stable_sort(lists.mask.begin(), lists.mask.end(), byPart);
    // Straight-alpha "over" needs back-to-front order (glTF BLEND, [Moore 2015]).
    std::stable_sort(lists.blend.begin(), lists.blend.end(),
                     [](const DrawBatch& a, const DrawBatch& b) { return a.viewDistance > b.viewDistance; });
    return lists;
}

}  // namespace engine::scene
