// SPDX-License-Identifier: MIT
#pragma once
// glTF 2.0 loading (.gltf + .bin, embedded data: URIs, .glb) into CPU-side data the
// renderer and the scene can use directly: triangle lists in the engine's one vertex
// layout, materials, decoded RGBA8 images, the node hierarchy with world transforms,
// cameras and the bounds of the chosen scene.
//
// Input is treated as hostile. Everything a file says is checked before it is used, and a
// file that breaks a rule is refused with an engine::Error naming the file, the field and
// the problem, e.g. "scene.gltf: buffers[0].uri '../../etc/passwd': path traversal is not
// allowed". See gltf_loader.cpp for the full list of checks.
//
// Extensions: KHR_draco_mesh_compression, KHR_mesh_quantization, KHR_materials_unlit and
// KHR_texture_transform are supported. Any other extension listed in extensionsRequired
// is an error; one only listed in extensionsUsed is a warning and is ignored.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/assets/image.hpp"
#include "engine/render/texture.hpp"
#include "engine/render/vertex.hpp"

namespace engine::assets {

enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };  // glTF material.alphaMode
const char* alphaModeName(AlphaMode mode);                    // "OPAQUE", "MASK", "BLEND"

// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv.
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;  // radians
    glm::vec2 scale{1.0f};
    glm::mat3 matrix() const;
    glm::vec2 apply(glm::vec2 uv) const { return glm::vec2(matrix() * glm::vec3(uv, 1.0f)); }
};

struct TextureRef {
    int texture = -1;  // into LoadedModel::textures; -1: none
    int texCoord = 0;  // which TEXCOORD_n set was read into Vertex::uv
    bool hasTransform = false;
    TextureTransform transform;  // informational: already applied to Vertex::uv (see LoadOptions)
};

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};  // linear RGBA
    TextureRef baseColorTexture;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;  // used by Mask only
    bool doubleSided = false;
    bool unlit = false;    // KHR_materials_unlit
    bool foliage = false;  // extras.foliage: drawn by SSAM ([Hathaway 2010])
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f};
};

struct Texture {
    std::string name;
    int image = -1;  // into LoadedModel::images; -1: none given
    render::SamplerState sampler;
};

struct Image {
    std::string name;
    std::string uri;   // the external file's URI as written; empty when embedded
    RgbaImage pixels;  // straight alpha, sRGB codes, as glTF stores them (empty if images were not loaded)
};

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::infinity()};
    glm::vec3 max{-std::numeric_limits<float>::infinity()};
    bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    void add(glm::vec3 p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void add(const Bounds& other, const glm::mat4& transform);  // the 8 transformed corners
};

struct Primitive {
    std::vector<render::Vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangle list; generated for non-indexed primitives
    int material = -1;                   // into LoadedModel::materials; -1: the glTF default material
    Bounds bounds;                       // of the positions, in mesh space
    bool hasNormals = false;             // else Vertex::normal holds its default
    bool hasTexCoords = false;
    bool hasColors = false;
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
};

struct Camera {
    enum class Type : std::uint8_t { Perspective, Orthographic };
    std::string name;
    Type type = Type::Perspective;
    float yfov = 0.0f;         // perspective: vertical field of view in radians
    float aspectRatio = 0.0f;  // perspective: 0 when the file leaves it to the viewport
    float xmag = 0.0f;         // orthographic half extents
    float ymag = 0.0f;
    float znear = 0.0f;
    float zfar = std::numeric_limits<float>::infinity();  // perspective may be infinite
};

struct Node {
    std::string name;
    int parent = -1;
    std::vector<int> children;
    int mesh = -1;
    int camera = -1;
    glm::mat4 local{1.0f};  // from matrix, or T * R * S
    glm::mat4 world{1.0f};  // parent.world * local
};

struct LoadedModel {
    std::filesystem::path source;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Image> images;
    std::vector<Camera> cameras;
    std::vector<Node> nodes;  // all nodes of the file; world transforms for every one
    int scene = -1;           // the scene loaded; -1 when the file has none (then every root node is used)
    std::vector<int> sceneRoots;
    std::vector<int> sceneNodes;        // every node of the scene, parents before children
    Bounds bounds;                      // world-space bounds of the scene's meshes
    std::vector<std::string> warnings;  // also logged
};

struct LoadOptions {
    int scene = -1;          // -1: the file's default scene (scene 0 if it names none)
    bool loadImages = true;  // false: Image::pixels stay empty (no decoding)
    // Apply KHR_texture_transform of the base colour texture to Vertex::uv, so renderers
    // need not know the extension (the transform stays on the material for reference).
    bool bakeTextureTransform = true;
    ImageLimits imageLimits;
    std::uint64_t maxFileBytes = std::uint64_t{1} << 30;  // any one file read: .gltf, .glb, .bin, image
    std::uint64_t maxVertices = std::uint64_t{1} << 26;   // per primitive, after decoding (Draco included)
};

// Throws engine::Error("<file>: <field>: <problem>") for missing, unreadable, malformed or
// hostile files (see the header comment).
LoadedModel loadGltf(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace engine::assets
