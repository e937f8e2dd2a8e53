// SPDX-License-Identifier: MIT
// The committed content/ is exactly what the generator writes (byte for byte, so a change to
// the generator without `make content` fails here), it loads with engine_assets, and it has
// the properties the renderer and SSAM rely on ([Hathaway 2010] §3.3 trees, MASK foliage, ...).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>

#include "assets_test_util.hpp"
#include "content.hpp"
#include "engine/assets/gltf.hpp"
#include "engine/assets/mips.hpp"

namespace {

namespace fs = std::filesystem;
using assets_test::TempDir;
using engine::assets::AlphaMode;
using engine::assets::LoadedModel;
using engine::assets::loadGltf;

const fs::path kContent = fs::path(SSAM_SOURCE_DIR) / "content";

std::vector<std::uint8_t> readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The JSON chunk of a GLB, for what the loader does not expose (extensions, extras).
nlohmann::json glbJson(const fs::path& path) {
    const auto bytes = readBytes(path);
    if (bytes.size() < 20) return {};
    const std::uint32_t length =
        bytes[12] | bytes[13] << 8 | bytes[14] << 16 | static_cast<std::uint32_t>(bytes[15]) << 24;
    return nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + length);
}

std::vector<fs::path> committedModels(const char* prefix) {
    std::vector<fs::path> out;
    for (const auto& entry : fs::directory_iterator(kContent / "models"))
        if (entry.path().filename().string().rfind(prefix, 0) == 0) out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

TEST(Content, CommittedFilesAreExactlyWhatTheGeneratorWrites) {
    TempDir dir;
    const std::vector<fs::path> generated = content::generateContent(dir.path());
    ASSERT_FALSE(generated.empty());
    std::set<fs::path> expected;
    for (const fs::path& file : generated) {
        expected.insert(file);
        const auto committed = kContent / file;
        ASSERT_TRUE(fs::exists(committed)) << file << " is not committed (run `make content`)";
        EXPECT_TRUE(readBytes(dir / file.string()) == readBytes(committed))
            << file << " differs from a fresh generation (run `make content` and commit the result)";
    }
    // No stale files the generator no longer writes.
    for (const char* folder : {"models", "textures", "lod"})
        for (const auto& entry : fs::directory_iterator(kContent / folder))
            EXPECT_TRUE(expected.count(fs::relative(entry.path(), kContent))) << entry.path() << " is not generated";
}

// The generated assets' share of content/ (which must stay well under 2 MB in all).
TEST(Content, StaysSmall) {
    std::uintmax_t total = 0;
    for (const char* folder : {"models", "textures", "lod"})
        for (const auto& entry : fs::recursive_directory_iterator(kContent / folder))
            if (entry.is_regular_file()) total += entry.file_size();
    EXPECT_LT(total, 1024u * 1024u);
}

TEST(Content, EveryModelLoadsCleanly) {
    int models = 0;
    for (const auto& entry : fs::directory_iterator(kContent / "models")) {
        SCOPED_TRACE(entry.path().string());
        const LoadedModel model = loadGltf(entry.path());
        ++models;
        EXPECT_TRUE(model.warnings.empty());
        ASSERT_FALSE(model.meshes.empty());
        ASSERT_FALSE(model.sceneNodes.empty());
        EXPECT_FALSE(model.bounds.empty());
        for (const auto& mesh : model.meshes)
            for (const auto& prim : mesh.primitives) {
                EXPECT_FALSE(prim.vertices.empty());
                EXPECT_EQ(prim.indices.size() % 3, 0u);
                EXPECT_TRUE(prim.hasNormals);
                EXPECT_TRUE(prim.hasTexCoords);
            }
        for (const auto& image : model.images) EXPECT_FALSE(image.pixels.empty());
    }
    EXPECT_GE(models, 9);
}

// [Hathaway 2010] §3.3: many randomly oriented, intersecting textured planes around a trunk,
// alpha-tested (MASK) and drawn from both sides, flagged for SSAM, Draco-compressed.
TEST(Content, TreesAndBushesAreBuiltLikePures) {
    const auto trees = committedModels("tree_");
    const auto bushes = committedModels("bush_");
    ASSERT_GE(trees.size(), 3u);
    ASSERT_GE(bushes.size(), 2u);
    for (const auto& list : {trees, bushes})
        for (const fs::path& path : list) {
            SCOPED_TRACE(path.string());
            const LoadedModel model = loadGltf(path);
            const bool isTree = path.filename().string().rfind("tree_", 0) == 0;
            int foliageParts = 0;
            int barkParts = 0;
            for (const auto& prim : model.meshes.at(0).primitives) {
                ASSERT_GE(prim.material, 0);
                const auto& m = model.materials[static_cast<std::size_t>(prim.material)];
                ASSERT_GE(m.baseColorTexture.texture, 0);
                if (m.foliage) {
                    ++foliageParts;
                    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
                    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.5f);
                    EXPECT_TRUE(m.doubleSided);
                    const std::size_t quads = prim.indices.size() / 6;
                    EXPECT_GE(quads, 24u);
                    EXPECT_LE(quads, 48u);
                    // The texture has soft edges: many texels strictly between 0 and 1 alpha,
                    // and nothing touches the border.
                    const auto& pixels =
                        model
                            .images[static_cast<std::size_t>(
                                model.textures[static_cast<std::size_t>(m.baseColorTexture.texture)].image)]
                            .pixels;
                    std::size_t soft = 0;
                    for (std::size_t t = 0; t < pixels.pixelCount(); ++t) soft += pixels.pixels[t * 4 + 3] % 255 != 0;
                    EXPECT_GT(soft, pixels.pixelCount() / 50);
                    for (int x = 0; x < pixels.width; ++x) EXPECT_EQ(pixels.texel(x, 0)[3], 0);
                    // Coverage-preserving mips keep the alpha-tested silhouette (see mips_test.cpp).
                    const auto mips = engine::assets::generateCoveragePreservingMips(pixels, m.alphaCutoff);
                    EXPECT_NEAR(engine::assets::alphaCoverage(mips[3], 0.5f),
                                engine::assets::alphaCoverage(pixels, 0.5f), 0.02f);
                } else {
                    ++barkParts;
                    EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
                    EXPECT_FALSE(m.doubleSided);
                }
            }
            EXPECT_EQ(foliageParts, 1);
            EXPECT_EQ(barkParts, isTree ? 1 : 0);
            const auto json = glbJson(path);
            EXPECT_EQ(json["extensionsRequired"], nlohmann::json::array({"KHR_draco_mesh_compression"}));
            for (const auto& prim : json["meshes"][0]["primitives"])
                EXPECT_TRUE(prim["extensions"].contains("KHR_draco_mesh_compression"));
        }
}

// Each plant's levels of detail (content/generator/lod_levels.hpp): scene 1 of its file the
// middle level, fewer and larger cards over the same crown; scene 2 the impostor, two crossed
// cards whose texture is the full model drawn from their sides and keeps its coverage down the
// mips; each takes over below a measured height on screen, a coarser one never before a finer.
TEST(Content, PlantsHaveMeasuredLevelsOfDetail) {
    std::ifstream in(kContent / "lod" / "levels.json");
    const nlohmann::json table = nlohmann::json::parse(in);
    const float pixelError = table["pixelError"].get<float>();
    EXPECT_GT(pixelError, 0.0f);
    EXPECT_LE(pixelError, 1.0f) << "a level may be off by at most a pixel";
    ASSERT_EQ(table["plants"].size(), committedModels("tree_").size() + committedModels("bush_").size());
    auto sceneOf = [](const fs::path& path, int scene) {
        engine::assets::LoadOptions options;
        options.scene = scene;
        return loadGltf(path, options);
    };
    auto cardsOf = [](const LoadedModel& model, std::size_t mesh) {
        for (const auto& prim : model.meshes.at(mesh).primitives)
            if (model.materials.at(static_cast<std::size_t>(prim.material)).foliage) return prim.indices.size() / 6;
        return std::size_t{0};
    };
    for (const auto& plant : table["plants"]) {
        const fs::path path = kContent / "models" / plant["file"].get<std::string>();
        SCOPED_TRACE(path.string());
        const LoadedModel full = loadGltf(path);
        const LoadedModel middle = sceneOf(path, 1);
        const LoadedModel impostor = sceneOf(path, 2);
        EXPECT_TRUE(middle.warnings.empty());
        EXPECT_TRUE(impostor.warnings.empty());
        // The height the levels were measured at: the full model's, with the drawing's margin.
        const float height = full.bounds.max.y - full.bounds.min.y;
        EXPECT_GE(plant["height"].get<float>(), height);
        const float width = std::max(full.bounds.max.x - full.bounds.min.x, full.bounds.max.z - full.bounds.min.z);
        EXPECT_LE(plant["height"].get<float>(), height + 0.1f * std::max(width, height));
        const std::size_t fullCards = cardsOf(full, 0), middleCards = cardsOf(middle, 1);
        EXPECT_LE(middleCards * 2, fullCards) << "the middle level keeps at most half the cards";
        EXPECT_GE(middleCards, 3u);
        EXPECT_EQ(impostor.meshes.at(2).primitives.size(), 1u) << "the impostor is foliage alone, trunk included";
        EXPECT_EQ(cardsOf(impostor, 2), 2u);
        // The impostor spans the full model's outline (within the frame's margin).
        EXPECT_LE(impostor.bounds.min.y, full.bounds.min.y);
        EXPECT_GE(impostor.bounds.max.y, full.bounds.max.y);
        // Its texture: the full model's picture, soft-edged, with a transparent border, whose
        // coverage-preserving mips keep the alpha-tested silhouette [Castaño 2010].
        const auto& material =
            impostor.materials.at(static_cast<std::size_t>(impostor.meshes.at(2).primitives[0].material));
        EXPECT_EQ(material.alphaMode, AlphaMode::Mask);
        const auto& pixels =
            impostor.images
                .at(static_cast<std::size_t>(
                    impostor.textures.at(static_cast<std::size_t>(material.baseColorTexture.texture)).image))
                .pixels;
        const float coverage = engine::assets::alphaCoverage(pixels, 0.5f);
        EXPECT_GT(coverage, 0.1f);
        EXPECT_LT(coverage, 0.8f);
        for (int x = 0; x < pixels.width; ++x) EXPECT_EQ(pixels.texel(x, 0)[3], 0);
        const auto mips = engine::assets::generateCoveragePreservingMips(pixels, 0.5f);
        EXPECT_NEAR(engine::assets::alphaCoverage(mips[2], 0.5f), coverage, 0.03f);
        // Where they take over: measured, positive, a coarser level never at a larger height.
        ASSERT_EQ(plant["levels"].size(), 2u);
        float previous = 1e30f;
        for (std::size_t level = 0; level < 2; ++level) {
            const auto& l = plant["levels"][level];
            EXPECT_EQ(l["scene"], level + 1);
            EXPECT_GT(l["deviationMetres"].get<float>(), 0.0f);
            const float below = l["belowPixels"].get<float>();
            EXPECT_GT(below, 1.0f);
            EXPECT_LE(below, previous);
            EXPECT_LE(below, pixelError * plant["height"].get<float>() / l["deviationMetres"].get<float>() * 1.01f);
            previous = below;
        }
    }
}

TEST(Content, PropsHaveTheirMaterials) {
    const LoadedModel water = loadGltf(kContent / "models" / "water.glb");
    EXPECT_EQ(water.materials.at(0).alphaMode, AlphaMode::Blend);
    EXPECT_LT(water.materials.at(0).baseColorFactor.a, 1.0f);

    const LoadedModel car = loadGltf(kContent / "models" / "car.glb");
    EXPECT_EQ(car.materials.at(0).alphaMode, AlphaMode::Opaque);
    EXPECT_GT(car.bounds.max.z - car.bounds.min.z, car.bounds.max.x - car.bounds.min.x);  // long along +Z
    EXPECT_NEAR(car.bounds.min.y, 0.0f, 1e-4f);                                           // wheels on the ground

    // The track is a closed loop whose centre line travels with it (mesh extras).
    const auto track = glbJson(kContent / "models" / "track.glb");
    const auto& centre = track["meshes"][0]["extras"]["centreLine"];
    EXPECT_EQ(centre["closed"], true);
    EXPECT_EQ(centre["samples"].size(), 240u);
    EXPECT_EQ(centre["controlPoints"].size(), 10u);
    const LoadedModel ribbon = loadGltf(kContent / "models" / "track.glb");
    const auto& vertices = ribbon.meshes.at(0).primitives.at(0).vertices;
    EXPECT_EQ(vertices.front().position, vertices[vertices.size() - 2].position);  // the loop closes

    for (const char* name : {"ground.png", "track.png"}) {
        const auto image = engine::assets::decodeImage(readBytes(kContent / "textures" / name), name);
        EXPECT_EQ(image.width, 256);
        EXPECT_EQ(engine::assets::alphaCoverage(image, 1.0f), 1.0f);  // opaque
    }
}

}  // namespace
