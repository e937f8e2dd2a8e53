// SPDX-License-Identifier: MIT
#include "engine/scene/draw_lists.hpp"

#include <algorithm>

#include "engine/scene/components.hpp"

namespace engine::scene {

DrawLists extractDrawLists(ecs::Registry& registry, const MeshLibrary& library, const glm::mat4& viewProj,
                           const glm::vec3& cameraPosition) {
    // Per part, the batch it fills this frame (index into its list), so instances of one
    // mesh become one instanced draw.
    std::vector<int> batchOfPart(library.partCount(), -1);
    DrawLists lists;
    std::vector<DrawBatch> ownMask, ownOpaque;  // batches of overridden parts, one entity each
    registry.view<const Transform, const Renderable>().each([&](ecs::Entity e, const Transform& t,
                                                                const Renderable& r) {
        const glm::mat4 model = t.matrix();
        const LevelsOfDetail* lod = registry.tryGet<LevelsOfDetail>(e);
        // One level, or the two of a crossfade, each with its weight in the tint's alpha.
        auto drawLevel = [&](int chosen, float weight) {
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
                    lists.blend.push_back({partIndex, own, {instance}, world, distance, {}});
                    continue;
                }
                if (own) {
                    const render::BufferHandle motion =
                        i < override->motionBuffers.size() ? override->motionBuffers[i] : render::BufferHandle{};
                    (part.material.surface == SurfaceClass::Mask ? ownMask : ownOpaque)
                        .push_back({partIndex, own, {instance}, world, distance, motion});
                    continue;
                }
                std::vector<DrawBatch>& list = part.material.surface == SurfaceClass::Mask ? lists.mask : lists.opaque;
                int& slot = batchOfPart[partIndex];
                if (slot < 0) {
                    slot = static_cast<int>(list.size());
                    list.push_back({partIndex, {}, {}, {}, 0.0f, {}});
                }
                list[slot].instances.push_back(instance);
                list[slot].worldBounds.add(world);
            }
            if (lod && drawn) ++lists.instancesAtLevel[std::size_t(level)];
        };
        if (lod && lod->blend.crossfading()) {
            drawLevel(lod->blend.levels[0], 1.0f - lod->blend.coarserWeight);
            drawLevel(lod->blend.levels[1], lod->blend.coarserWeight);
        } else {
            drawLevel(lod ? lod->level : 0, 1.0f);
        }
    });
    auto byPart = [](const DrawBatch& a, const DrawBatch& b) { return a.part < b.part; };
    // Own-vertex batches follow the shared batch of their part, in view order (deterministic).
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
