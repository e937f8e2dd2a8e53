// SPDX-License-Identifier: MIT
#pragma once
// Hand-made plants for the wind tests: a crown of intersecting vertical cards around the y
// axis ([Hathaway 2010] §3.3, Figure 3.2), as one alpha-tested (Mask) part, from y = 0 to `height`;
// and the world every wind test starts from, one such plant in a soft backend's library.
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/render/vertex.hpp"
#include "engine/scene/mesh_library.hpp"
#include "wind/wind_system.hpp"

namespace wind::testing {

inline engine::scene::ModelId addCardPlant(engine::scene::MeshLibrary& library, int cards = 6, float height = 4.0f,
                                           float radius = 1.5f, int rows = 4,
                                           glm::vec4 color = glm::vec4(0.3f, 0.6f, 0.2f, 0.8f)) {
    using engine::render::Vertex;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    for (int c = 0; c < cards; ++c) {
        const float angle = 3.14159265f * float(c) / float(cards) + 0.2f * float(c % 2);
        const glm::vec3 across(std::cos(angle) * radius, 0.0f, std::sin(angle) * radius);
        const glm::vec3 normal = glm::normalize(glm::vec3(-across.z, 0.0f, across.x));
        const std::uint32_t base = static_cast<std::uint32_t>(vertices.size());
        for (int r = 0; r <= rows; ++r) {
            const float y = height * float(r) / float(rows);
            for (int s = 0; s < 2; ++s) {
                Vertex v;
                v.position = (s ? across : -across) + glm::vec3(0.0f, y, 0.0f);
                v.normal = normal;
                v.uv = {float(s), float(r) / float(rows)};
                v.color = color;
                vertices.push_back(v);
            }
        }
        for (int r = 0; r < rows; ++r) {
            const std::uint32_t a = base + 2 * r;
            for (std::uint32_t i : {a, a + 1, a + 3, a, a + 3, a + 2}) indices.push_back(i);
        }
    }
    engine::scene::PartMaterial material;
    material.surface = engine::scene::SurfaceClass::Mask;
    material.doubleSided = true;
    return library.add("card plant", vertices, indices, material);
}

// A card plant's model (not yet placed), an empty registry and the wind system; each test
// adds the Wind and its plants in the order its entities need.
struct CardPlantWorld {
    std::unique_ptr<engine::render::Device> backend = engine::render::soft::createSoftBackend({1, 64, false});
    engine::scene::MeshLibrary library{*backend};
    engine::ecs::Registry registry;
    engine::scene::ModelId plant = addCardPlant(library);
    WindSystem system{library};
};

}  // namespace wind::testing
