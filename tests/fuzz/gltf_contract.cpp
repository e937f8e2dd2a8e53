// SPDX-License-Identifier: MIT
#include "gltf_contract.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include "engine/core/error.hpp"
#include "fuzz_support.hpp"

namespace ssam::fuzz {

namespace {

using engine::assets::LoadedModel;

bool inRange(int index, std::size_t count, bool optional = true) {
    return (optional && index == -1) || (index >= 0 && static_cast<std::size_t>(index) < count);
}

template <typename Vec>
bool finite(const Vec& v) {
    for (int i = 0; i < Vec::length(); ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        if (!finite(m[c])) return false;
    return true;
}

bool finite(const engine::assets::Bounds& b) { return b.empty() || (finite(b.min) && finite(b.max)); }

void checkImagesAndMaterials(const LoadedModel& model) {
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        const auto& pixels = model.images[i].pixels;
        if (pixels.pixels.empty() && pixels.width == 0 && pixels.height == 0) continue;  // not decoded
        require(pixels.width > 0 && pixels.height > 0 &&
                    pixels.pixels.size() ==
                        static_cast<std::size_t>(pixels.width) * static_cast<std::size_t>(pixels.height) * 4,
                "images[" + std::to_string(i) + "]: " + std::to_string(pixels.pixels.size()) + " bytes for " +
                    std::to_string(pixels.width) + "x" + std::to_string(pixels.height) + " RGBA8");
    }
    for (std::size_t i = 0; i < model.textures.size(); ++i)
        require(inRange(model.textures[i].image, model.images.size()),
                "textures[" + std::to_string(i) + "].image out of range");
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        const auto& m = model.materials[i];
        const std::string field = "materials[" + std::to_string(i) + "]";
        require(finite(m.baseColorFactor) && std::isfinite(m.metallicFactor) && std::isfinite(m.roughnessFactor) &&
                    finite(m.emissiveFactor) && std::isfinite(m.alphaCutoff),
                field + ": a non-finite factor was accepted");
        const auto& ref = m.baseColorTexture;
        require(inRange(ref.texture, model.textures.size()), field + ".baseColorTexture out of range");
        require(ref.texCoord >= 0 && ref.texCoord <= 7, field + ".baseColorTexture.texCoord out of [0, 7]");
        require(finite(ref.transform.offset) && std::isfinite(ref.transform.rotation) && finite(ref.transform.scale),
                field + ": a non-finite texture transform was accepted");
    }
}

void checkMeshes(const LoadedModel& model) {
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const auto& primitive = model.meshes[m].primitives[p];
            const std::string field = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
            require(inRange(primitive.material, model.materials.size()), field + ".material out of range");
            require(primitive.indices.size() % 3 == 0,
                    field + ": " + std::to_string(primitive.indices.size()) + " indices are not whole triangles");
            for (std::size_t i = 0; i < primitive.indices.size(); ++i)
                require(primitive.indices[i] < primitive.vertices.size(),
                        field + ": index " + std::to_string(primitive.indices[i]) + " at " + std::to_string(i) +
                            " is out of range for " + std::to_string(primitive.vertices.size()) + " vertices");
            for (std::size_t v = 0; v < primitive.vertices.size(); ++v) {
                const auto& vertex = primitive.vertices[v];
                require(finite(vertex.position) && finite(vertex.normal) && finite(vertex.uv) && finite(vertex.color),
                        field + ": vertex " + std::to_string(v) + " has a non-finite attribute");
            }
            require(finite(primitive.bounds), field + ": non-finite bounds");
        }
}

void checkCamerasAndNodes(const LoadedModel& model) {
    for (std::size_t i = 0; i < model.cameras.size(); ++i) {
        const auto& c = model.cameras[i];
        const bool zfarOk = std::isfinite(c.zfar) || (c.type == engine::assets::Camera::Type::Perspective &&
                                                      std::isinf(c.zfar) && c.zfar > 0.0f);
        require(std::isfinite(c.yfov) && std::isfinite(c.aspectRatio) && std::isfinite(c.xmag) &&
                    std::isfinite(c.ymag) && std::isfinite(c.znear) && zfarOk,
                "cameras[" + std::to_string(i) + "]: a non-finite parameter was accepted");
    }
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const auto& node = model.nodes[i];
        const std::string field = "nodes[" + std::to_string(i) + "]";
        require(inRange(node.parent, model.nodes.size()), field + ".parent out of range");
        require(inRange(node.mesh, model.meshes.size()), field + ".mesh out of range");
        require(inRange(node.camera, model.cameras.size()), field + ".camera out of range");
        for (int child : node.children)
            require(inRange(child, model.nodes.size(), false), field + ": child out of range");
        require(finite(node.local), field + ": non-finite local transform");
        require(finite(node.world), field + ": non-finite world transform");
    }
    require(model.scene >= -1, "scene index below -1");
    for (int n : model.sceneRoots) require(inRange(n, model.nodes.size(), false), "sceneRoots: node out of range");
    for (int n : model.sceneNodes) require(inRange(n, model.nodes.size(), false), "sceneNodes: node out of range");
    require(finite(model.bounds), "non-finite scene bounds");
}

}  // namespace

void checkLoadedModel(const LoadedModel& model) {
    checkImagesAndMaterials(model);
    checkMeshes(model);
    checkCamerasAndNodes(model);
}

void loadAndCheck(const std::filesystem::path& path) {
    try {
        checkLoadedModel(engine::assets::loadGltf(path));
    } catch (const engine::Error& e) {
        requireMessageNames(e, path.string() + ": ");
    }
}

}  // namespace ssam::fuzz
