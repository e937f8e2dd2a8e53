// SPDX-License-Identifier: MIT
#include "engine/scene/levels_of_detail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

LodBlend crossfadeLevels(float pixels, std::span<const float> belowPixels, float band) {
    LodBlend blend;
    // Finer: the level while not yet `band` below a threshold; coarser: once `band` above it.
    blend.levels = {chooseLevel(0, false, pixels / (1.0f - band), belowPixels, 0.0f),
                    chooseLevel(0, false, pixels / (1.0f + band), belowPixels, 0.0f)};
    if (!blend.crossfading()) return blend;
    // The finer level's own threshold: where its band is (overlapping bands blend the ends).
    const float threshold = belowPixels[std::size_t(blend.levels[0])];
    const float w = (threshold * (1.0f + band) - pixels) / (2.0f * band * threshold);
    blend.coarserWeight = std::clamp(w, 0.0f, 1.0f);
    return blend;
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
            // A band at least the hysteresis's: outside it the plain choice is the level kept.
            lod.blend = view.crossfade > 0.0f
                            ? crossfadeLevels(pixels, below, std::max(view.crossfade, view.hysteresis))
                            : LodBlend{};
            if (!lod.blend.crossfading()) lod.blend = {{lod.level, lod.level}, 0.0f};
            lod.chosen = true;
            lod.chosenFocal = view.focalPixels;
            // Level 0 is drawn alone at least while taller than its threshold plus the bands.
            const float band = std::max(view.hysteresis, view.crossfade);
            lod.fullDetailUntil = below.empty() || below[0] <= 0.0f ? std::numeric_limits<float>::infinity()
                                                                    : size / (below[0] * (1.0f + band));
        });
}

}  // namespace engine::scene
