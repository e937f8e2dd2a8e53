// SPDX-License-Identifier: MIT
// KHR_draco_mesh_compression: a mesh encoded here with the Draco library loads back with its
// geometry intact, and Draco output that disagrees with the accessors is refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>

#include "assets_test_util.hpp"
#include "engine/assets/gltf.hpp"

namespace {

using assets_test::errorOf;
using assets_test::TempDir;
using engine::assets::loadGltf;
using ::testing::HasSubstr;
using json = nlohmann::json;

// A 4x4-quad grid in the XZ plane, bent in Y, as a triangle soup: 32 triangles.
struct Soup {
    std::vector<std::array<glm::vec3, 3>> positions;
    std::vector<std::array<glm::vec2, 3>> uvs;
};

Soup makeGrid() {
    Soup soup;
    const auto p = [](int x, int z) { return glm::vec3(x * 0.5f, std::sin(x * 0.7f + z) * 0.25f, z * 0.5f); };
    const auto t = [](int x, int z) { return glm::vec2(x / 4.0f, z / 4.0f); };
    for (int z = 0; z < 4; ++z)
        for (int x = 0; x < 4; ++x) {
            soup.positions.push_back({p(x, z), p(x + 1, z), p(x + 1, z + 1)});
            soup.uvs.push_back({t(x, z), t(x + 1, z), t(x + 1, z + 1)});
            soup.positions.push_back({p(x, z), p(x + 1, z + 1), p(x, z + 1)});
            soup.uvs.push_back({t(x, z), t(x + 1, z + 1), t(x, z + 1)});
        }
    return soup;
}

struct Encoded {
    std::vector<char> bytes;
    int points = 0;
    int faces = 0;
    int positionId = -1;
    int uvId = -1;
};

Encoded encode(const Soup& soup) {
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(static_cast<int>(soup.positions.size()));
    const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int uv = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
    for (std::size_t f = 0; f < soup.positions.size(); ++f) {
        const draco::FaceIndex face(static_cast<std::uint32_t>(f));
        builder.SetAttributeValuesForFace(pos, face, &soup.positions[f][0], &soup.positions[f][1],
                                          &soup.positions[f][2]);
        builder.SetAttributeValuesForFace(uv, face, &soup.uvs[f][0], &soup.uvs[f][1], &soup.uvs[f][2]);
    }
    std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
    draco::EncoderBuffer buffer;
    const draco::Status status = encoder.EncodeMeshToBuffer(*mesh, &buffer);
    EXPECT_TRUE(status.ok()) << status.error_msg_string();
    Encoded out;
    out.bytes.assign(buffer.data(), buffer.data() + buffer.size());
    out.points = static_cast<int>(mesh->num_points());
    out.faces = static_cast<int>(mesh->num_faces());
    out.positionId = static_cast<int>(mesh->attribute(pos)->unique_id());
    out.uvId = static_cast<int>(mesh->attribute(uv)->unique_id());
    return out;
}

// The glTF a Draco exporter writes: accessors without bufferViews, the compressed data in
// one bufferView named by the primitive's extension.
json document(const Encoded& encoded) {
    return {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"KHR_draco_mesh_compression"}},
        {"extensionsRequired", {"KHR_draco_mesh_compression"}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
              {"indices", 2},
              {"extensions",
               {{"KHR_draco_mesh_compression",
                 {{"bufferView", 0},
                  {"attributes", {{"POSITION", encoded.positionId}, {"TEXCOORD_0", encoded.uvId}}}}}}}}}}}}},
        {"accessors",
         {{{"componentType", 5126}, {"count", encoded.points}, {"type", "VEC3"}},
          {{"componentType", 5126}, {"count", encoded.points}, {"type", "VEC2"}},
          {{"componentType", 5125}, {"count", encoded.faces * 3}, {"type", "SCALAR"}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", encoded.bytes.size()}}}},
        {"buffers", {{{"uri", "mesh.bin"}, {"byteLength", encoded.bytes.size()}}}},
    };
}

class GltfDraco : public ::testing::Test {
protected:
    void SetUp() override {
        soup = makeGrid();
        encoded = encode(soup);
        assets_test::writeFile(dir / "mesh.bin", encoded.bytes.data(), encoded.bytes.size());
    }
    std::filesystem::path write(const json& doc) {
        const auto path = dir / "mesh.gltf";
        assets_test::writeFile(path, doc.dump(1));
        return path;
    }

    TempDir dir;
    Soup soup;
    Encoded encoded;
};

TEST_F(GltfDraco, DecodesGeometryWithinQuantisationError) {
    const auto model = loadGltf(write(document(encoded)));
    ASSERT_EQ(model.meshes.size(), 1u);
    const auto& prim = model.meshes[0].primitives[0];
    EXPECT_EQ(prim.vertices.size(), static_cast<std::size_t>(encoded.points));
    ASSERT_EQ(prim.indices.size(), soup.positions.size() * 3);
    EXPECT_TRUE(prim.hasTexCoords);

    // Every decoded triangle is one of the originals (Draco may reorder faces and rotate
    // corners), to 14-bit position and 12-bit uv quantisation.
    const float posTolerance = 2.0f / (1 << 14) * 2.0f;
    const float uvTolerance = 1.0f / (1 << 12) * 2.0f;
    std::vector<bool> matched(soup.positions.size(), false);
    for (std::size_t t = 0; t < prim.indices.size(); t += 3) {
        bool found = false;
        for (std::size_t f = 0; f < soup.positions.size() && !found; ++f) {
            if (matched[f]) continue;
            for (int rot = 0; rot < 3 && !found; ++rot) {
                bool same = true;
                for (int k = 0; k < 3; ++k) {
                    const auto& v = prim.vertices[prim.indices[t + static_cast<std::size_t>(k)]];
                    const int corner = (k + rot) % 3;
                    same = same &&
                           glm::all(glm::lessThan(glm::abs(v.position - soup.positions[f][corner]),
                                                  glm::vec3(posTolerance))) &&
                           glm::all(glm::lessThan(glm::abs(v.uv - soup.uvs[f][corner]), glm::vec2(uvTolerance)));
                }
                if (same) found = matched[f] = true;
            }
        }
        EXPECT_TRUE(found) << "decoded triangle " << t / 3 << " is not an original one";
    }
    EXPECT_NEAR(model.bounds.max.x, 2.0f, posTolerance);
    EXPECT_NEAR(model.bounds.min.z, 0.0f, posTolerance);
}

TEST_F(GltfDraco, VertexCountMismatchIsRefused) {
    json doc = document(encoded);
    doc["accessors"][0]["count"] = encoded.points + 1;
    EXPECT_THAT(errorOf([&] { loadGltf(write(doc)); }),
                HasSubstr("accessors[0] (meshes[0].primitives[0].attributes.POSITION).count: " +
                          std::to_string(encoded.points + 1) + " does not match the " + std::to_string(encoded.points) +
                          " vertices Draco decoded (count mismatch)"));
}

TEST_F(GltfDraco, IndexCountMismatchIsRefused) {
    json doc = document(encoded);
    doc["accessors"][2]["count"] = encoded.faces * 3 - 3;
    EXPECT_THAT(
        errorOf([&] { loadGltf(write(doc)); }),
        HasSubstr("accessors[2] (meshes[0].primitives[0].indices).count: " + std::to_string(encoded.faces * 3 - 3) +
                  " does not match the " + std::to_string(encoded.faces * 3) + " indices Draco decoded"));
}

TEST_F(GltfDraco, ComponentCountMismatchIsRefused) {
    json doc = document(encoded);
    doc["accessors"][1]["type"] = "VEC3";
    EXPECT_THAT(errorOf([&] { loadGltf(write(doc)); }),
                HasSubstr("attributes.TEXCOORD_0).type: declares 3 components, Draco decoded 2"));
}

TEST_F(GltfDraco, UnknownDracoAttributeIdIsRefused) {
    json doc = document(encoded);
    doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["POSITION"] = 99;
    EXPECT_THAT(
        errorOf([&] { loadGltf(write(doc)); }),
        HasSubstr("KHR_draco_mesh_compression.attributes.POSITION: the Draco data has no attribute with id 99"));
}

TEST_F(GltfDraco, DracoAttributeWithoutPrimitiveAttributeIsRefused) {
    json doc = document(encoded);
    doc["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
    EXPECT_THAT(errorOf([&] { loadGltf(write(doc)); }),
                HasSubstr("attributes.TEXCOORD_0: the primitive has no attribute 'TEXCOORD_0'"));
}

TEST_F(GltfDraco, TruncatedDracoDataIsRefused) {
    json doc = document(encoded);
    const std::size_t half = encoded.bytes.size() / 2;
    doc["bufferViews"][0]["byteLength"] = half;
    EXPECT_THAT(errorOf([&] { loadGltf(write(doc)); }), HasSubstr("KHR_draco_mesh_compression: Draco decoding failed"));
}

TEST_F(GltfDraco, DracoBufferViewOutOfRangeIsRefused) {
    json doc = document(encoded);
    doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] = 3;
    EXPECT_THAT(errorOf([&] { loadGltf(write(doc)); }),
                HasSubstr("KHR_draco_mesh_compression.bufferView: 3 is out of range: the file has 1 bufferViews"));
}

}  // namespace
