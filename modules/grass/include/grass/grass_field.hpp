// SPDX-License-Identifier: MIT
#pragma once
// Where grass grows and how it moves: root points (world space, on the ground) given by the
// game, and the parameters of the cards drawn there.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/render/vertex.hpp"

namespace grass {

struct GrassOptions {
    float drawDistance = 60.0f;   // metres from the eye; tufts beyond are not drawn
    float height = 0.55f;         // metres, card height at scale 1
    float width = 0.9f;           // metres
    float alphaReference = 0.5f;  // alpha test (cards are cut out, like Pure's foliage colour pass)
    glm::vec3 windDirection{1.0f, 0.0f, 0.35f};
    float sway = 0.18f;             // metres at the tip
    float swayFrequency = 0.7f;     // Hz
    std::size_t maxTufts = 200000;  // a field larger than this is refused
};

// Throws engine::Error naming the field when a value is NaN, infinite or out of range.
void validate(const GrassOptions& options);

// One tuft: where, which way it faces, how big.
struct Tuft {
    glm::vec3 root{0.0f};
    float yaw = 0.0f;
    float scale = 1.0f;
};

// The tufts to draw this frame: within drawDistance of `eye` and in the view volume, each
// as an instance matrix that shears the card's top downwind (sway at `time`). In root
// order, so the result is deterministic.
std::vector<engine::render::Instance> visibleTufts(std::span<const Tuft> tufts, const GrassOptions& options,
                                                   const glm::vec3& eye, const glm::mat4& viewProj, float time);

// The card mesh: three crossed quads, uv (0,0) top-left, normals up (grass lit like ground).
void buildCard(const GrassOptions& options, std::vector<engine::render::Vertex>& vertices,
               std::vector<std::uint32_t>& indices);

// The blade texture (RGBA8, straight alpha): `width` x `height`, blades cut out in alpha.
std::vector<std::uint8_t> bladeTexels(int width, int height, std::uint32_t seed);

}  // namespace grass
