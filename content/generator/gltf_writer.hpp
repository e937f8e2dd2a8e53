// SPDX-License-Identifier: MIT
#pragma once
// A small glTF 2.0 writer for the generator: one GLB per model, everything embedded (geometry,
// PNG textures), so each file is self-contained. Primitives are stored either plainly or with
// KHR_draco_mesh_compression (encoded with the Draco library). Output is a pure function of
// the inputs: JSON keys in a fixed order, no timestamps.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry.hpp"

namespace content {

using ordered_json = nlohmann::ordered_json;

// Draco quantisation: 14 bits keep positions within 1/16384 of the model's extent (0.5 mm on an
// 8 m tree); 10 bits of normal and 12 of texture coordinate are below what 8-bit shading and a
// 256-texel texture can show.
struct DracoSettings {
    int positionBits = 14;
    int normalBits = 10;
    int texCoordBits = 12;
};

class GlbWriter {
public:
    GlbWriter();

    // PNG bytes stored in the BIN chunk; returns the image index.
    int addPngImage(const std::vector<std::uint8_t>& png, const std::string& name);
    // wrap: GL wrap mode for both axes (10497 REPEAT, 33071 CLAMP_TO_EDGE); trilinear filtering.
    int addTexture(int image, int wrap);
    int addMaterial(ordered_json material);
    struct Part {
        const MeshData* mesh;
        int material;
    };
    int addMesh(const std::string& name, const std::vector<Part>& parts, bool draco, ordered_json extras = nullptr);
    int addNode(ordered_json node);
    // Scene 0, the file's default scene.
    void setSceneNodes(std::vector<int> nodes);
    // One more scene (another level of detail); returns its index.
    int addScene(std::vector<int> nodes);

    std::vector<std::uint8_t> glb() const;

private:
    int addView(const void* data, std::size_t size, int target);
    int addAccessor(ordered_json accessor);
    ordered_json plainPrimitive(const MeshData& mesh);
    ordered_json dracoPrimitive(const MeshData& mesh);

    DracoSettings draco_;
    bool usesDraco_ = false;
    std::vector<std::uint8_t> bin_;
    ordered_json nodes_ = ordered_json::array();
    ordered_json meshes_ = ordered_json::array();
    ordered_json materials_ = ordered_json::array();
    ordered_json textures_ = ordered_json::array();
    ordered_json samplers_ = ordered_json::array();
    ordered_json images_ = ordered_json::array();
    ordered_json accessors_ = ordered_json::array();
    ordered_json views_ = ordered_json::array();
    std::vector<std::vector<int>> scenes_{{}};
};

}  // namespace content
