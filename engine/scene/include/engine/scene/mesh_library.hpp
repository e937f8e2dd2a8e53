// SPDX-License-Identifier: MIT
#pragma once
// Models uploaded to a backend: each glTF primitive becomes one part with its own buffers
// and material, node transforms baked into the vertices. Entities refer to a model by id;
// extraction expands a model into its parts.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/assets/gltf.hpp"
#include "engine/render/backend.hpp"
#include "engine/scene/bounds.hpp"

namespace engine::scene {

// How a part is drawn, from glTF's alphaMode (glTF 2.0 §3.9.4): Opaque ignores alpha,
// Mask is alpha-tested foliage (SSAM's input), Blend is straight-alpha "over", sorted.
enum class SurfaceClass : std::uint8_t { Opaque, Mask, Blend };

struct PartMaterial {
    SurfaceClass surface = SurfaceClass::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    bool unlit = false;
    glm::vec4 baseColorFactor{1.0f};
    render::TextureBinding baseColor;
};

struct MeshPart {
    std::string name;
    render::BufferHandle vertices;
    render::BufferHandle indices;
    std::uint32_t indexCount = 0;
    PartMaterial material;
    Aabb bounds;  // model space
};

using ModelId = std::uint32_t;

class MeshLibrary {
public:
    explicit MeshLibrary(render::Backend& backend) : backend_(backend) {}
    ~MeshLibrary();
    MeshLibrary(const MeshLibrary&) = delete;
    MeshLibrary& operator=(const MeshLibrary&) = delete;

    // Uploads every mesh of the model's scene; foliage (Mask) textures get mips that keep
    // their alpha-test coverage (Castaño) so trees don't thin out with distance.
    ModelId add(const assets::LoadedModel& model);
    // A model built in code: one part.
    ModelId add(const std::string& name, const std::vector<render::Vertex>& vertices,
                const std::vector<std::uint32_t>& indices, const PartMaterial& material);

    const std::vector<std::uint32_t>& partsOf(ModelId model) const { return models_.at(model); }
    const MeshPart& part(std::uint32_t index) const { return parts_.at(index); }
    // The part's vertices as uploaded (model space): the rest pose deformation starts from.
    const std::vector<render::Vertex>& vertices(std::uint32_t index) const { return vertices_.at(index); }
    std::size_t partCount() const { return parts_.size(); }
    Aabb bounds(ModelId model) const;
    render::Backend& backend() const { return backend_; }

private:
    std::uint32_t addPart(MeshPart part, const std::vector<render::Vertex>& vertices,
                          const std::vector<std::uint32_t>& indices);

    render::Backend& backend_;
    std::vector<MeshPart> parts_;
    std::vector<std::vector<render::Vertex>> vertices_;  // CPU copy per part (rest pose)
    std::vector<std::vector<std::uint32_t>> models_;
    std::vector<render::TextureHandle> textures_;
};

}  // namespace engine::scene
