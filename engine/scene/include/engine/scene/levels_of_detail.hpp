// SPDX-License-Identifier: MIT
#pragma once
// Levels of detail per instance: the full model near, coarser models (fewer, larger cards; an
// impostor) when the instance is drawn small. Each level takes over below a height on screen
// in pixels, measured by the content generator as the height at which the level's deviation
// from the full model projects to at most a pixel ([Luebke et al. 2002] §4.2, screen-space
// error; content/generator/lod_levels.hpp), so the switch follows the view's resolution and
// field of view, not a distance set by hand.
//
// The frame's culling picks the level of each instance once per frame (selectLevelsOfDetail,
// before the systems that deform plants, so they know the level), with hysteresis: a level is
// left only when the instance's height is a band past the threshold, so an instance that
// hovers at a threshold does not flip every frame. Extraction then draws the chosen level's
// model and counts the instances drawn at each level (DrawLists::instancesAtLevel). Without a
// selection every instance stays at level 0: the full model, as without levels at all.
//
// With a crossfade band (LodView::crossfade) an instance whose height is within the band of a
// threshold draws both levels, the finer with weight 1 - w and the coarser with w, w rising
// linearly across the band, so no level change happens in one frame (SpeedTree's LOD
// crossfade; Unreal's dithered LOD transition). The weight rides in the instance's tint alpha
// (render::Instance::tint): under SSAM it multiplies the fragment's alpha, so the two levels
// blend through the mask ([Hathaway 2010] §3.5.2: MAX and ADD of the alphas).
#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "engine/core/ecs/registry.hpp"
#include "engine/scene/mesh_library.hpp"

namespace engine::scene {

inline constexpr int kMaxLodLevels = 3;

// On an entity with a Renderable whose model is models[0].
struct LevelsOfDetail {
    std::array<ModelId, kMaxLodLevels> models{};
    // Level k + 1 is drawn while the instance is shorter on screen than belowPixels[k]
    // (non-increasing); `levels` of models are used.
    std::array<float, kMaxLodLevels - 1> belowPixels{};
    int levels = 1;
    float height = 1.0f;  // model-space height the thresholds were measured at
    // Written by selectLevelsOfDetail each frame:
    int level = 0;
    // A level has been chosen for a view of `chosenFocal` (LodView::focalPixels). A choice
    // for another focal length (the frame resized, the field of view changed) is made afresh,
    // without hysteresis: the band damps motion, and a new view is not a motion.
    bool chosen = false;
    float chosenFocal = 0.0f;
    // Beyond this distance (metres) the instance may leave level 0 under the current view;
    // 0 before any selection. Deformation eases to rest before it (modules/wind).
    float fullDetailUntil = 0.0f;
    // The levels drawn this frame (LodView::crossfade > 0): see LodBlend.
    struct LodBlend {
        std::array<int, 2> levels{};  // finer, coarser; equal outside a band
        float coarserWeight = 0.0f;   // w; the finer level's weight is 1 - w
        bool crossfading() const { return levels[0] != levels[1]; }
    } blend;
};
using LodBlend = LevelsOfDetail::LodBlend;

// The view a selection is made for.
struct LodView {
    glm::vec3 eye{0.0f};
    // Pixels on screen per unit of size at unit distance: projection[1][1] * viewport height / 2.
    float focalPixels = 0.0f;
    // Leave a level only this fraction past its threshold (0.1: 10 %).
    float hysteresis = 0.1f;
    // Crossfade across this fraction either side of each threshold (0.1: from 10 % above it to
    // 10 % below; at least the hysteresis, so outside the band the level kept is the one
    // drawn); 0: no crossfade, each instance draws `level` alone.
    float crossfade = 0.0f;
};

// projection[1][1] * height / 2: what LodView::focalPixels needs from a perspective projection.
float focalPixels(const glm::mat4& projection, int viewportHeight);

// The level for an instance `pixels` tall on screen, now at `current`: coarser while it is
// shorter than the next level's threshold by the band, finer while it is taller than its
// own threshold by the band. `chosen` false: the plain choice, no band.
int chooseLevel(int current, bool chosen, float pixels, std::span<const float> belowPixels, float hysteresis);

// The levels an instance `pixels` tall draws with a crossfade band of `band` (in (0, 1)):
// within `band` of a threshold T (T (1 - band) < pixels < T (1 + band)) the levels either side,
// the coarser one's weight rising linearly from 0 at T (1 + band) to 1 at T (1 - band); else
// the one level. Overlapping bands (thresholds closer than the band) blend the outer levels
// by the finer one's threshold. The two weights sum to one.
LodBlend crossfadeLevels(float pixels, std::span<const float> belowPixels, float band);

// Picks every LevelsOfDetail instance's level for `view` (its height on screen from its
// Transform's scale and the distance from the eye to its full model's bounds centre).
void selectLevelsOfDetail(ecs::Registry& registry, const MeshLibrary& library, const LodView& view);

}  // namespace engine::scene
