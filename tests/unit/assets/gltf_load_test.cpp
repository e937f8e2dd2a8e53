// SPDX-License-Identifier: MIT
// Valid glTF files load into the expected CPU-side data: geometry, materials, images,
// samplers, node transforms, cameras, scenes and bounds. The three containers (.gltf + .bin,
// embedded data: URIs, .glb) of one triangle must load identically.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "assets_test_util.hpp"
#include "engine/assets/gltf.hpp"

namespace {

using assets_test::errorOf;
using assets_test::fixture;
using engine::assets::AlphaMode;
using engine::assets::Camera;
using engine::assets::LoadedModel;
using engine::assets::LoadOptions;
using engine::assets::loadGltf;
using ::testing::HasSubstr;

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

void expectNear(glm::vec2 actual, glm::vec2 expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
}

// The model has one camera, `expected` in every field (the fixtures name none), carried by node `node`.
void expectOneCamera(const LoadedModel& model, const Camera& expected, std::size_t node) {
    ASSERT_EQ(model.cameras.size(), 1u);
    const Camera& camera = model.cameras[0];
    EXPECT_EQ(camera.name, expected.name);
    EXPECT_EQ(camera.type, expected.type);
    for (auto field :
         {&Camera::yfov, &Camera::aspectRatio, &Camera::xmag, &Camera::ymag, &Camera::znear, &Camera::zfar})
        EXPECT_FLOAT_EQ(camera.*field, expected.*field);
    ASSERT_LT(node, model.nodes.size());
    EXPECT_EQ(model.nodes[node].camera, 0);
}

// What make_fixtures.py wrote: a triangle under a translated root, scaled by 2 and rotated
// 90 degrees about +Z, with a 4x4 RGBA texture, a clamp/mirror sampler and a camera.
void expectTriangle(const LoadedModel& model) {
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
    const auto& prim = model.meshes[0].primitives[0];
    ASSERT_EQ(prim.vertices.size(), 3u);
    EXPECT_EQ(prim.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_TRUE(prim.hasNormals);
    EXPECT_TRUE(prim.hasTexCoords);
    EXPECT_FALSE(prim.hasColors);
    expectNear(prim.vertices[1].position, {1, 0, 0});
    expectNear(prim.vertices[2].normal, {0, 0, 1});
    expectNear(prim.vertices[1].uv, {1, 0});
    EXPECT_EQ(prim.vertices[0].color, glm::vec4(1.0f));  // default when COLOR_0 is absent
    EXPECT_EQ(prim.material, 0);

    ASSERT_EQ(model.materials.size(), 1u);
    const auto& material = model.materials[0];
    EXPECT_EQ(material.name, "leaf");
    EXPECT_EQ(material.alphaMode, AlphaMode::Opaque);
    EXPECT_FLOAT_EQ(material.alphaCutoff, 0.5f);  // the glTF default
    EXPECT_FALSE(material.doubleSided);
    EXPECT_FALSE(material.foliage);
    EXPECT_EQ(material.baseColorFactor, glm::vec4(1.0f, 0.5f, 0.25f, 1.0f));
    EXPECT_EQ(material.baseColorTexture.texture, 0);

    ASSERT_EQ(model.textures.size(), 1u);
    EXPECT_EQ(model.textures[0].image, 0);
    EXPECT_EQ(model.textures[0].sampler.filter, engine::render::Filter::Trilinear);
    EXPECT_EQ(model.textures[0].sampler.addressU, engine::render::AddressMode::Clamp);
    EXPECT_EQ(model.textures[0].sampler.addressV, engine::render::AddressMode::Mirror);

    ASSERT_EQ(model.images.size(), 1u);
    const auto& image = model.images[0].pixels;
    ASSERT_EQ(image.width, 4);
    ASSERT_EQ(image.height, 4);
    EXPECT_EQ(image.alpha, engine::render::AlphaMode::Straight);
    EXPECT_EQ(image.texel(0, 0)[3], 0);  // transparent corner
    const std::uint8_t* centre = image.texel(1, 1);
    EXPECT_EQ(centre[0], 40);
    EXPECT_EQ(centre[1], 160);
    EXPECT_EQ(centre[2], 30);
    EXPECT_EQ(centre[3], 255);
    EXPECT_EQ(image.texel(1, 0)[3], 128);  // soft edge

    ASSERT_EQ(model.nodes.size(), 3u);
    EXPECT_EQ(model.scene, 0);
    EXPECT_EQ(model.sceneRoots, (std::vector<int>{0, 2}));
    EXPECT_EQ(model.sceneNodes, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(model.nodes[1].parent, 0);
    // (1,0,0): scaled to (2,0,0), rotated to (0,2,0), translated to (1,4,3).
    expectNear(glm::vec3(model.nodes[1].world * glm::vec4(1, 0, 0, 1)), {1, 4, 3});
    expectNear(model.bounds.min, {-1, 2, 3});
    expectNear(model.bounds.max, {1, 4, 3});

    expectOneCamera(model,
                    {.name = "",
                     .type = Camera::Type::Perspective,
                     .yfov = 0.8f,
                     .aspectRatio = 1.5f,
                     .znear = 0.1f,
                     .zfar = 100.0f},
                    2);
    expectNear(glm::vec3(model.nodes[2].world[3]), {0, 1, 5});  // from the node's matrix
    EXPECT_TRUE(model.warnings.empty());
}

TEST(GltfLoad, TriangleWithExternalBinAndImage) {
    expectTriangle(loadGltf(fixture("triangle.gltf")));
    EXPECT_EQ(loadGltf(fixture("triangle.gltf")).images[0].uri, "leaf4.png");
}

TEST(GltfLoad, TriangleWithDataUris) { expectTriangle(loadGltf(fixture("embedded.gltf"))); }

TEST(GltfLoad, TriangleAsGlbWithImageInBufferView) { expectTriangle(loadGltf(fixture("triangle.glb"))); }

TEST(GltfLoad, RelativePathWorksFromAnyWorkingDirectory) {
    const auto previous = std::filesystem::current_path();
    std::filesystem::current_path(fixture(""));
    LoadedModel model;
    EXPECT_NO_THROW(model = loadGltf("triangle.gltf"));
    std::filesystem::current_path(previous);
    expectTriangle(model);
}

TEST(GltfLoad, AlphaModesAndMaterialExtensions) {
    const LoadedModel model = loadGltf(fixture("alpha_modes.gltf"));
    ASSERT_EQ(model.materials.size(), 4u);
    EXPECT_EQ(model.materials[0].alphaMode, AlphaMode::Opaque);
    EXPECT_FALSE(model.materials[0].foliage);

    const auto& mask = model.materials[1];
    EXPECT_EQ(mask.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(mask.alphaCutoff, 0.3f);
    EXPECT_TRUE(mask.doubleSided);
    EXPECT_TRUE(mask.foliage);

    const auto& blend = model.materials[2];
    EXPECT_EQ(blend.alphaMode, AlphaMode::Blend);
    EXPECT_EQ(blend.baseColorFactor, glm::vec4(0.2f, 0.4f, 0.8f, 0.5f));
    EXPECT_FALSE(blend.unlit);

    const auto& unlit = model.materials[3];
    EXPECT_TRUE(unlit.unlit);
    EXPECT_TRUE(unlit.baseColorTexture.hasTransform);
    expectNear(unlit.baseColorTexture.transform.offset, {0.5f, 0.0f});
    expectNear(unlit.baseColorTexture.transform.scale, {2.0f, 2.0f});
    EXPECT_NEAR(unlit.baseColorTexture.transform.rotation, 1.5707963f, 1e-6f);
    EXPECT_STREQ(engine::assets::alphaModeName(mask.alphaMode), "MASK");
}

TEST(GltfLoad, TextureTransformIsBakedIntoUvs) {
    const LoadedModel model = loadGltf(fixture("alpha_modes.gltf"));
    const auto& unlitQuad = model.meshes[3].primitives[0];
    // uv' = T(0.5, 0) * R(90 deg) * S(2) * uv (KHR_texture_transform's matrix).
    expectNear(unlitQuad.vertices[0].uv, {0.5f, 0.0f});
    expectNear(unlitQuad.vertices[1].uv, {0.5f, 2.0f});   // (1,0) -> (2,0) -> (0,2) -> (0.5,2)
    expectNear(unlitQuad.vertices[3].uv, {-1.5f, 0.0f});  // (0,1) -> (0,2) -> (-2,0) -> (-1.5,0)
    // Other materials' UVs are untouched.
    expectNear(model.meshes[0].primitives[0].vertices[1].uv, {1.0f, 0.0f});

    LoadOptions options;
    options.bakeTextureTransform = false;
    const LoadedModel raw = loadGltf(fixture("alpha_modes.gltf"), options);
    expectNear(raw.meshes[3].primitives[0].vertices[1].uv, {1.0f, 0.0f});
}

TEST(GltfLoad, NonIndexedStripQuantizedAndSparse) {
    const LoadedModel model = loadGltf(fixture("alpha_modes.gltf"));
    const auto& soup = model.meshes[4].primitives[0];
    EXPECT_EQ(soup.vertices.size(), 6u);
    EXPECT_EQ(soup.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));  // generated
    EXPECT_FALSE(soup.hasNormals);
    EXPECT_EQ(soup.material, -1);

    // Triangle strip of 4 vertices -> 2 triangles with alternating winding (glTF §3.7.2.1).
    const auto& strip = model.meshes[5].primitives[0];
    EXPECT_EQ(strip.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));

    // Sparse accessor: vertex 2 of accessor 0 replaced by (5,5,5).
    expectNear(strip.vertices[2].position, {5, 5, 5});
    expectNear(strip.vertices[1].position, {1, 0, 0});

    // KHR_mesh_quantization: normalised SHORT positions.
    const auto& quantized = model.meshes[6].primitives[0];
    expectNear(quantized.vertices[2].position, {1, 1, 0});
    expectNear(quantized.vertices[3].position, {0, 1, 0});
}

TEST(GltfLoad, ChosenSceneAndItsBounds) {
    LoadOptions options;
    options.scene = 1;
    const LoadedModel model = loadGltf(fixture("alpha_modes.gltf"), options);
    EXPECT_EQ(model.scene, 1);
    EXPECT_EQ(model.sceneNodes, (std::vector<int>{6, 7}));
    expectNear(model.bounds.min, {12, 0, 0});
    expectNear(model.bounds.max, {13, 1, 0});

    options.scene = 2;
    EXPECT_THAT(errorOf([&] { loadGltf(fixture("alpha_modes.gltf"), options); }),
                HasSubstr("LoadOptions::scene 2 is out of range: the file has 2 scenes"));
}

TEST(GltfLoad, OrthographicCamera) {
    const LoadedModel model = loadGltf(fixture("alpha_modes.gltf"));
    expectOneCamera(
        model,
        {.name = "", .type = Camera::Type::Orthographic, .xmag = 2.0f, .ymag = 1.5f, .znear = 0.01f, .zfar = 50.0f}, 7);
}

TEST(GltfLoad, ExtensionOnlyUsedIsAWarning) {
    const LoadedModel model = loadGltf(fixture("used_extension.gltf"));
    ASSERT_EQ(model.warnings.size(), 1u);
    EXPECT_THAT(model.warnings[0], HasSubstr("extensionsUsed[0]"));
    EXPECT_THAT(model.warnings[0], HasSubstr("EXT_made_up_extension"));
    EXPECT_EQ(model.meshes[0].primitives[0].vertices.size(), 3u);
}

TEST(GltfLoad, ImagesCanBeSkipped) {
    LoadOptions options;
    options.loadImages = false;
    const LoadedModel model = loadGltf(fixture("triangle.gltf"), options);
    ASSERT_EQ(model.images.size(), 1u);
    EXPECT_TRUE(model.images[0].pixels.empty());
    EXPECT_EQ(model.images[0].uri, "leaf4.png");
}

TEST(GltfLoad, ImageLimitsApplyToEveryImageSource) {
    LoadOptions options;
    options.imageLimits.maxDimension = 2;
    for (const char* file : {"triangle.gltf", "embedded.gltf", "triangle.glb"}) {
        const std::string message = errorOf([&] { loadGltf(fixture(file), options); });
        EXPECT_THAT(message, HasSubstr(file));
        EXPECT_THAT(message, HasSubstr("images[0]"));
        EXPECT_THAT(message, HasSubstr("4x4, over the size cap of 2x2"));
    }
    options.imageLimits = {};
    options.imageLimits.maxDecodedBytes = 63;  // 4 * 4 * 4 = 64 bytes decoded
    EXPECT_THAT(errorOf([&] { loadGltf(fixture("triangle.gltf"), options); }), HasSubstr("over the cap of 63 bytes"));
}

TEST(GltfLoad, BoundsTransformCorners) {
    engine::assets::Bounds box;
    EXPECT_TRUE(box.empty());
    box.add(glm::vec3(-1.0f));
    box.add(glm::vec3(1.0f));
    engine::assets::Bounds world;
    world.add(box,
              glm::mat4(glm::vec4(2, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0), glm::vec4(10, 0, 0, 1)));
    expectNear(world.min, {8, -1, -1});
    expectNear(world.max, {12, 1, 1});
}

}  // namespace
