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
    for (const char* folder : {"models", "textures"})
        for (const auto& entry : fs::directory_iterator(kContent / folder))
            EXPECT_TRUE(expected.count(fs::relative(entry.path(), kContent))) << entry.path() << " is not generated";
}

// The generated assets' share of content/ (which must stay well under 2 MB in all).
TEST(Content, StaysSmall) {
    std::uintmax_t total = 0;
    for (const char* folder : {"models", "textures"})
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
