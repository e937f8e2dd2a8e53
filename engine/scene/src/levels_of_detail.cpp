// SPDX-License-Identifier: MIT
#include "engine/scene/levels_of_detail.hpp"

#include <cmath>

#include "engine/scene/components.hpp"

namespace engine::scene {

float focalPixels(const glm::mat4& projection, int viewportHeight) {
    return projection[1][1] * 0.5f * float(viewportHeight);
}

int chooseLevel(int current, bool chosen, float pixels, std::span<const float> belowPixels, float hysteresis) {
    const int last = int(belowPixels.size());
    if (!chosen) {
        int level = 0;
        while (level < last && pixels < belowPixels[std::size_t(level)]) ++level;
        return level;
    }
    int level = std::clamp(current, 0, last);
    while (level < last && pixels < belowPixels[std::size_t(level)] * (1.0f - hysteresis)) ++level;
    while (level > 0 && pixels > belowPixels[std::size_t(level - 1)] * (1.0f + hysteresis)) --level;
    return level;
}

void selectLevelsOfDetail(ecs::Registry& registry, const MeshLibrary& library, const LodView& view) {
    registry.view<const Transform, const Renderable, LevelsOfDetail>().each(
        [&](ecs::Entity, const Transform& t, const Renderable& r, LevelsOfDetail& lod) {
            const Aabb box = library.bounds(r.model);
            const glm::vec3 centre =
                box.empty() ? t.position : glm::vec3(t.matrix() * glm::vec4((box.min + box.max) * 0.5f, 1.0f));
            const float distance = glm::length(centre - view.eye);
            const float size = lod.height * std::abs(t.scale.y) * view.focalPixels;
            const float pixels = distance > 0.0f ? size / distance : std::numeric_limits<float>::infinity();
            const std::span<const float> below(lod.belowPixels.data(), std::size_t(std::max(0, lod.levels - 1)));
            lod.level = chooseLevel(lod.level, lod.chosen && lod.chosenFocal == view.focalPixels, pixels, below,
                                    view.hysteresis);
            lod.chosen = true;
            lod.chosenFocal = view.focalPixels;
            // Level 0 is kept at least while taller than its threshold plus the band.
            lod.fullDetailUntil = below.empty() || below[0] <= 0.0f ? std::numeric_limits<float>::infinity()
                                                                    : size / (below[0] * (1.0f + view.hysteresis));
        });
}

}  // namespace engine::scene
