// SPDX-License-Identifier: MIT
#pragma once
// A small exact rasterizer for the generator: a plant's surfaces seen from the side with an
// orthographic camera, each sample depth-tested and alpha-tested at the glTF MASK cutoff (0.5),
// the samples of a pixel averaged on premultiplied linear colour. It draws the far level's
// impostor texture from the full model and measures each level's screen-space error against
// the full model (lod_levels.hpp). Unlit: albedo and coverage, what the levels must agree on.
#include <vector>

#include <glm/glm.hpp>

#include "engine/assets/image.hpp"
#include "geometry.hpp"

namespace content {

struct Surface {
    const MeshData* mesh;
    const engine::assets::RgbaImage* texture;  // straight alpha, sRGB colour
    bool alphaTested;                          // MASK at 0.5; else opaque
};

// The camera looks horizontally along (sin yaw, 0, cos yaw); the picture's columns run along
// (cos yaw, 0, -sin yaw) from -halfWidth to +halfWidth, its rows from `top` down to `bottom`.
struct OrthoView {
    float yaw = 0.0f;
    float halfWidth = 1.0f;
    float bottom = 0.0f, top = 1.0f;
    int width = 1, height = 1;
    int samples = 4;  // per axis: samples x samples per pixel, on a regular grid
};

// Premultiplied linear RGBA per pixel, row-major from the top row.
std::vector<glm::vec4> renderOrtho(const std::vector<Surface>& surfaces, const OrthoView& view);

// The pixels as a straight-alpha sRGB texture. Transparent texels take the mean colour of
// the covered ones, as the leaf textures do, so filtering pulls in no dark fringe.
engine::assets::RgbaImage toTexture(const std::vector<glm::vec4>& pixels, int width, int height);

}  // namespace content
