// SPDX-License-Identifier: MIT
#include "engine/scene/mesh_library.hpp"

#include <map>

#include "engine/assets/mips.hpp"

namespace engine::scene {

using namespace engine::render;

MeshLibrary::~MeshLibrary() {
    for (const MeshPart& p : parts_) {
        backend_.destroy(p.vertices);
        backend_.destroy(p.indices);
    }
    for (TextureHandle t : textures_) backend_.destroy(t);
}

std::uint32_t MeshLibrary::addPart(MeshPart part, const std::vector<Vertex>& vertices,
                                   const std::vector<std::uint32_t>& indices) {
    const auto vb = std::as_bytes(std::span(vertices));
    const auto ib = std::as_bytes(std::span(indices));
    part.vertices = backend_.createBuffer({part.name + " vertices", BufferKind::Vertex, vb.size()}, vb);
    part.indices = backend_.createBuffer({part.name + " indices", BufferKind::Index, ib.size()}, ib);
    part.indexCount = static_cast<std::uint32_t>(indices.size());
    for (const Vertex& v : vertices) part.bounds.add(v.position);
    parts_.push_back(std::move(part));
    vertices_.push_back(vertices);
    return static_cast<std::uint32_t>(parts_.size() - 1);
}

ModelId MeshLibrary::add(const std::string& name, const std::vector<Vertex>& vertices,
                         const std::vector<std::uint32_t>& indices, const PartMaterial& material) {
    MeshPart part;
    part.name = name;
    part.material = material;
    models_.push_back({addPart(std::move(part), vertices, indices)});
    return static_cast<ModelId>(models_.size() - 1);
}

ModelId MeshLibrary::add(const assets::LoadedModel& model) {
    // (image, alpha mode) -> texture: one image can be uploaded once per way it is used.
    std::map<std::pair<int, assets::AlphaMode>, TextureHandle> uploaded;
    auto textureFor = [&](const assets::Material& m) -> TextureBinding {
        if (m.baseColorTexture.texture < 0) return {};
        const assets::Texture& t = model.textures.at(m.baseColorTexture.texture);
        if (t.image < 0 || model.images.at(t.image).pixels.pixels.empty()) return {};
        auto [it, fresh] = uploaded.try_emplace({t.image, m.alphaMode});
        if (fresh) {
            assets::RgbaImage pixels = model.images[t.image].pixels;
            // glTF 2.0 §3.9.4: OPAQUE ignores alpha entirely. Premultiplied filtering would
            // darken such a texel by its alpha (to black at 0), so its alpha becomes 1 here.
            if (m.alphaMode == assets::AlphaMode::Opaque)
                for (std::size_t i = 3; i < pixels.pixels.size(); i += 4) pixels.pixels[i] = 255;
            // Premultiplied mips filter correctly ([Hargreaves 2009]); masked ones also keep their
            // alpha-test coverage per level.
            const std::vector<assets::RgbaImage> levels =
                m.alphaMode == assets::AlphaMode::Mask
                    ? assets::generateCoveragePreservingMips(pixels, m.alphaCutoff)
                    : assets::generateMips(pixels, {AlphaMode::Premultiplied, -1.0f, 0});
            TextureDesc desc;
            desc.name = model.source.filename().string() + ":" + model.images[t.image].name;
            desc.width = pixels.width;
            desc.height = pixels.height;
            desc.format = pixels.srgb ? Format::RGBA8_SRGB : Format::RGBA8_UNORM;
            desc.mipLevels = static_cast<int>(levels.size());
            desc.alpha = levels.front().alpha;
            const TextureData data = assets::textureData(levels);
            it->second = backend_.createTexture(desc, &data);
            textures_.push_back(it->second);
        }
        return {it->second, t.sampler};
    };

    std::vector<std::uint32_t> parts;
    for (int nodeIndex : model.sceneNodes) {
        const assets::Node& node = model.nodes.at(nodeIndex);
        if (node.mesh < 0) continue;
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(node.world)));
        for (const assets::Primitive& prim : model.meshes.at(node.mesh).primitives) {
            const assets::Material fallback;
            const assets::Material& m = prim.material >= 0 ? model.materials.at(prim.material) : fallback;
            MeshPart part;
            part.name = model.source.filename().string() + ":" + model.meshes[node.mesh].name;
            part.material.surface = m.alphaMode == assets::AlphaMode::Mask    ? SurfaceClass::Mask
                                    : m.alphaMode == assets::AlphaMode::Blend ? SurfaceClass::Blend
                                                                              : SurfaceClass::Opaque;
            part.material.alphaCutoff = m.alphaCutoff;
            part.material.doubleSided = m.doubleSided;
            part.material.unlit = m.unlit;
            part.material.baseColorFactor = m.baseColorFactor;
            part.material.baseColor = textureFor(m);
            std::vector<Vertex> vertices = prim.vertices;
            for (Vertex& v : vertices) {
                v.position = glm::vec3(node.world * glm::vec4(v.position, 1.0f));
                v.normal = normalMatrix * v.normal;
            }
            parts.push_back(addPart(std::move(part), vertices, prim.indices));
        }
    }
    models_.push_back(std::move(parts));
    return static_cast<ModelId>(models_.size() - 1);
}

Aabb MeshLibrary::bounds(ModelId model) const {
    Aabb b;
    for (std::uint32_t p : partsOf(model)) b.add(parts_[p].bounds);
    return b;
}

}  // namespace engine::scene
