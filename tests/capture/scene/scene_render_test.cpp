// SPDX-License-Identifier: MIT
// `racer --scene FILE` end to end (label capture): each crafted file of tests/data/scene is
// rendered headless at 64x64 on the soft backend and checked at known pixels against the
// glTF 2.0 §3.9.4 alpha rules; Draco variants are encoded here with the Draco library;
// bad indices and hostile files make racer exit non-zero with a message naming the file
// and the field. The files are unlit (KHR_materials_unlit), so a pixel is the material's
// colour, composited over the neutral background (linear 0.18) where the rules say so.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <glm/glm.hpp>

#include "engine/capture/image_read.hpp"
#include "engine/capture/srgb.hpp"
#include "gltf_scene.hpp"

namespace {

namespace fs = std::filesystem;
using engine::capture::encodeSrgb8;
using json = nlohmann::json;
using ::testing::HasSubstr;

fs::path sceneFile(const std::string& name) { return fs::path(SSAM_SOURCE_DIR) / "tests" / "data" / "scene" / name; }
fs::path hostileFile(const std::string& name) {
    return fs::path(SSAM_SOURCE_DIR) / "tests" / "data" / "gltf" / "hostile" / name;
}

fs::path outputDir() {
    const fs::path dir = fs::temp_directory_path() / ("ssam_capture_scene_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

using Rgb = std::array<int, 3>;

struct RacerRun {
    int exitCode = -1;
    std::string output;  // stdout and stderr
    engine::capture::Image8 image;

    Rgb at(int x, int y) const { return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)}; }
};

// Runs racer on `scene` with `flags` at 64x64, one frame, headless; on the soft backend,
// or the one SSAM_SCENE_BACKEND names (ctest RacerScene.GlBackend sets gl).
RacerRun racer(const fs::path& scene, const std::string& sceneFlags = "") {
    const char* backend = std::getenv("SSAM_SCENE_BACKEND");
    const std::string flags = sceneFlags + (backend ? std::string(" --backend ") + backend : std::string());
    static int runs = 0;
    const fs::path dir = outputDir();
    const std::string name = "run" + std::to_string(runs++);
    const fs::path png = dir / (name + ".png"), log = dir / (name + ".log");
    fs::remove(png);
    const std::string command = "env -u DISPLAY '" + std::string(RACER_PATH) +
                                "' --headless --size 64x64 --frames 1 --scene '" + scene.string() + "' " + flags +
                                " --capture '" + png.string() + "' > '" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    RacerRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    run.output = text.str();
    if (run.exitCode == 0 && fs::exists(png)) run.image = engine::capture::readImage8(png);
    return run;
}

Rgb srgb(glm::vec3 linear) { return {encodeSrgb8(linear.r), encodeSrgb8(linear.g), encodeSrgb8(linear.b)}; }
const glm::vec3 kBackground(0.18f);  // racer::kNeutralBackground

// Each channel within `tolerance` codes (sRGB rounding of the texture and the target).
MATCHER_P2(NearRgb, expected, tolerance, "") {
    for (int c = 0; c < 3; ++c)
        if (std::abs(arg[c] - expected[c]) > tolerance) {
            *result_listener << "is (" << arg[0] << ", " << arg[1] << ", " << arg[2] << ")";
            return false;
        }
    return true;
}
#define EXPECT_PIXEL(run, x, y, expected) \
    EXPECT_THAT((run).at(x, y), NearRgb(expected, 2)) << "pixel (" << (x) << ", " << (y) << ")"

// Pixels in the left and right halves of a quad framed by the automatic camera.
constexpr int kLeft = 16, kRight = 48, kMid = 32;

void expectOpaqueTextureAlphaIgnored(const RacerRun& run) {
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // Texel alpha 0.2 and 0, baseColorFactor alpha 0.3: the colour comes out whole.
    EXPECT_PIXEL(run, kLeft, kMid, (Rgb{200, 40, 40}));
    EXPECT_PIXEL(run, kRight, kMid, (Rgb{40, 200, 40}));
}

// mask_cutoff.gltf: black texels of alpha 0.3 | 0.55 | 0.9 in thirds of the quad, alphaCutoff 0.6.
constexpr int kAlpha030 = 12, kAlpha055 = 32, kAlpha090 = 51;

void expectMaskCoverage(const RacerRun& run) {
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_PIXEL(run, kAlpha030, kMid, srgb(kBackground));  // below the cutoff: discarded
    EXPECT_PIXEL(run, kAlpha090, kMid, (Rgb{0, 0, 0}));     // above: kept, opaque (black: under any light)
}

void expectBlendFactor(const RacerRun& run) {
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // Straight-alpha over: texel (1, 1, 1, 128/255) times factor (0.2, 0.6, 1.0, 0.8).
    const float alpha = 0.8f * 128.0f / 255.0f;
    const glm::vec3 colour(0.2f, 0.6f, 1.0f);
    EXPECT_PIXEL(run, kMid, kMid, srgb(alpha * colour + (1.0f - alpha) * kBackground));
}

TEST(RacerScene, OpaqueIgnoresTextureAndFactorAlpha) {
    expectOpaqueTextureAlphaIgnored(racer(sceneFile("opaque_texture_alpha.gltf")));
}

TEST(RacerScene, GlbLoadsLikeGltf) { expectOpaqueTextureAlphaIgnored(racer(sceneFile("opaque_texture_alpha.glb"))); }

TEST(RacerScene, AutomaticCameraFramesTheBoundsWithTenPercentMargin) {
    const RacerRun run = racer(sceneFile("opaque_texture_alpha.gltf"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_THAT(run.output, HasSubstr("camera automatic"));
    // The 2x2 quad spans 1/1.1 of the 64-pixel frame: pixels 2.9 .. 61.1.
    for (int y : {1, 62}) EXPECT_PIXEL(run, kMid, y, srgb(kBackground));
    for (int x : {1, 62}) EXPECT_PIXEL(run, x, kMid, srgb(kBackground));
    EXPECT_PIXEL(run, 4, kMid, (Rgb{200, 40, 40}));
    EXPECT_PIXEL(run, 59, kMid, (Rgb{40, 200, 40}));
    EXPECT_PIXEL(run, kLeft, 4, (Rgb{200, 40, 40}));
    EXPECT_PIXEL(run, kLeft, 59, (Rgb{200, 40, 40}));
}

TEST(RacerScene, MaskDiscardsBelowTheCutoffWithAlphaTest) {
    expectMaskCoverage(racer(sceneFile("mask_cutoff.gltf"), "--technique alpha-test"));
}

// The 0.55 texel is below the material's alphaCutoff 0.6 (not below glTF's default 0.5).
TEST(RacerScene, MaskUsesTheMaterialsAlphaCutoff) {
    const RacerRun run = racer(sceneFile("mask_cutoff.gltf"), "--technique alpha-test");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_PIXEL(run, kAlpha055, kMid, srgb(kBackground));
}

TEST(RacerScene, MaskIsTheFoliageSsamMasksAndBlends) {
    const RacerRun run = racer(sceneFile("mask_cutoff.gltf"), "--technique ssam");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // SSAM turns alpha into soft coverage ([Hathaway 2010] §3.5): more alpha, more foliage over the
    // background; the outside of the quad is untouched background.
    const int low = run.at(kAlpha030, kMid)[0], mid = run.at(kAlpha055, kMid)[0], high = run.at(kAlpha090, kMid)[0];
    const int background = srgb(kBackground)[0];
    EXPECT_LE(low, background);
    EXPECT_LT(mid, low);
    EXPECT_LT(high, mid);
    EXPECT_LT(high, background / 2);
    EXPECT_PIXEL(run, 1, 1, srgb(kBackground));
}

TEST(RacerScene, BlendIsStraightAlphaOverWithTheFactorsAlpha) {
    expectBlendFactor(racer(sceneFile("blend_factor.gltf")));
}

// OPAQUE and BLEND materials are never "the foliage": every technique draws them the same.
TEST(RacerScene, OpaqueAndBlendAreTheSameUnderEveryTechnique) {
    for (const char* technique :
         {"ssam", "ssam-plus", "alpha-test", "a2c", "blend-unsorted", "blend-sorted", "wboit", "reference"}) {
        SCOPED_TRACE(technique);
        const std::string flag = std::string("--technique ") + technique;
        const RacerRun blend = racer(sceneFile("blend_factor.gltf"), flag);
        if (blend.exitCode != 0 && blend.output.find("is not implemented yet") != std::string::npos) continue;
        expectBlendFactor(blend);
        expectOpaqueTextureAlphaIgnored(racer(sceneFile("opaque_texture_alpha.gltf"), flag));
    }
}

TEST(RacerScene, BlendPrimitivesAreSortedBackToFront) {
    const RacerRun run = racer(sceneFile("blend_sorted.gltf"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // The file lists the near red quad first; sorted, the far green one is drawn first.
    const glm::vec3 overGreen = 0.5f * glm::vec3(0, 1, 0) + 0.5f * kBackground;
    EXPECT_PIXEL(run, kMid, kMid, srgb(0.5f * glm::vec3(1, 0, 0) + 0.5f * overGreen));
}

TEST(RacerScene, DoubleSidedControlsCulling) {
    const RacerRun run = racer(sceneFile("double_sided.gltf"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_PIXEL(run, kLeft, kMid, srgb(kBackground));    // back face, single-sided: culled
    EXPECT_PIXEL(run, kRight, kMid, (Rgb{0, 255, 255}));  // back face, doubleSided: drawn
}

TEST(RacerScene, DoubleSidedControlsCullingOfBlend) {
    const RacerRun run = racer(sceneFile("blend_double_sided.gltf"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_PIXEL(run, kLeft, kMid, srgb(kBackground));
    EXPECT_PIXEL(run, kRight, kMid, srgb(0.75f * glm::vec3(0, 1, 1) + 0.25f * kBackground));
}

TEST(RacerScene, TextureTransformIsApplied) {
    const RacerRun run = racer(sceneFile("texture_transform.gltf"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_PIXEL(run, kLeft, kMid, (Rgb{30, 220, 30}));  // u' = 0.5 + 0.5 u: the right texel everywhere
    EXPECT_PIXEL(run, kRight, kMid, (Rgb{30, 220, 30}));
}

TEST(RacerScene, QuantizedAttributesAreDequantized) {
    const RacerRun run = racer(sceneFile("quantized.gltf"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_PIXEL(run, kMid, kMid, (Rgb{30, 30, 220}));
    EXPECT_PIXEL(run, 4, 4, (Rgb{30, 30, 220}));  // the SHORT corners are at +-1, framed like the float quad
    EXPECT_PIXEL(run, 1, 1, srgb(kBackground));
}

TEST(RacerScene, ExtensionOnlyUsedIsIgnoredWithAWarning) {
    const RacerRun run = racer(fs::path(SSAM_SOURCE_DIR) / "tests" / "data" / "gltf" / "used_extension.gltf");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_THAT(run.output,
                HasSubstr("extensionsUsed[0]: extension 'EXT_made_up_extension' is not supported and is ignored"));
}

// A committed content model: a Draco .glb whose leaves are MASK foliage, drawn by SSAM.
TEST(RacerScene, ContentTreeRendersFramed) {
    const RacerRun run = racer(fs::path(SSAM_SOURCE_DIR) / "content" / "models" / "tree_broadleaf.glb");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Rgb centre = run.at(kMid, kMid);
    EXPECT_GT(centre[1], centre[2] + 20) << "the crown's green";
    EXPECT_PIXEL(run, 1, 1, srgb(kBackground));
}

// ---------------------------------------------------------------------------------------
// Cameras and indices

const glm::vec3 kRed(1, 0, 0), kGreen(0, 1, 0), kBlue(0, 0, 1);

TEST(RacerScene, FirstCameraOfTheFileIsUsed) {
    const RacerRun run = racer(sceneFile("cameras.gltf"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_THAT(run.output, HasSubstr("camera cameras[0] 'red'"));
    EXPECT_PIXEL(run, kMid, kMid, srgb(kRed));
    EXPECT_PIXEL(run, 1, 1, srgb(kRed));  // yfov 0.5 at 3 m: the quad fills the frame
}

TEST(RacerScene, CameraIndexPicksAnInfinitePerspectiveCamera) {
    const RacerRun run = racer(sceneFile("cameras.gltf"), "--camera-index 1");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_PIXEL(run, kMid, kMid, srgb(kBlue));
    EXPECT_PIXEL(run, 1, 1, srgb(kBlue));
}

TEST(RacerScene, OrthographicCamera) {
    const RacerRun run = racer(sceneFile("cameras.gltf"), "--camera-index 2");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // ymag 2: the quad's [-1, 1] is the middle half of the frame.
    EXPECT_PIXEL(run, kMid, kMid, srgb(kRed));
    EXPECT_PIXEL(run, 20, 20, srgb(kRed));
    EXPECT_PIXEL(run, kMid, 8, srgb(kBackground));
    EXPECT_PIXEL(run, 8, kMid, srgb(kBackground));
}

TEST(RacerScene, SceneIndexWithoutCameraUsesTheAutomaticCamera) {
    const RacerRun run = racer(sceneFile("cameras.gltf"), "--scene-index 1");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_PIXEL(run, kMid, kMid, srgb(kGreen));
    EXPECT_PIXEL(run, 1, 1, srgb(kBackground));
}

// racer refuses the scene file with these flags: a non-zero exit and the message saying why.
void expectRefused(const char* file, const std::string& flags, const std::string& message) {
    const RacerRun run = racer(sceneFile(file), flags);
    EXPECT_NE(run.exitCode, 0);
    EXPECT_THAT(run.output, HasSubstr(message));
}

TEST(RacerScene, BadCameraIndexGivesTheValidRange) {
    expectRefused("cameras.gltf", "--camera-index 3",
                  "cameras.gltf: --camera-index 3 is out of range: the file has 3 cameras (valid: 0..2)");
}

TEST(RacerScene, CameraNotInTheSceneIsRefused) {
    expectRefused("cameras.gltf", "--scene-index 1 --camera-index 0", "no node of scene 1 carries cameras[0]");
}

TEST(RacerScene, BadSceneIndexGivesTheValidRange) {
    expectRefused("cameras.gltf", "--scene-index 2",
                  "cameras.gltf: scene: LoadOptions::scene 2 is out of range: the file has 2 scenes (valid: 0..1)");
}

TEST(RacerScene, CameraIndexWithoutCamerasSaysSo) {
    expectRefused("mask_cutoff.gltf", "--camera-index 0", "--camera-index 0 is out of range: the file has no cameras");
}

// ---------------------------------------------------------------------------------------
// Hostile files: non-zero exit, the message names the file and the field.

struct HostileCase {
    const char* file;
    const char* message;
};

class RacerSceneHostile : public ::testing::TestWithParam<HostileCase> {};

TEST_P(RacerSceneHostile, ExitsNonZeroNamingFileAndField) {
    const RacerRun run = racer(hostileFile(GetParam().file));
    EXPECT_NE(run.exitCode, 0);
    EXPECT_THAT(run.output, HasSubstr("racer: error: "));
    EXPECT_THAT(run.output, HasSubstr(GetParam().file));
    EXPECT_THAT(run.output, HasSubstr(GetParam().message));
}

INSTANTIATE_TEST_SUITE_P(
    Files, RacerSceneHostile,
    ::testing::Values(HostileCase{"nan_position.gltf", "attributes.POSITION): element 1 has a non-finite component"},
                      HostileCase{"required_extension.gltf",
                                  "'EXT_made_up_extension': required extension is not supported"},
                      HostileCase{"uri_traversal.gltf", "buffers[0].uri '../../etc/passwd': path traversal"},
                      HostileCase{"glb_truncated.glb", "GLB header: truncated"},
                      HostileCase{"no_such_file.gltf", "file does not exist"}),
    [](const auto& info) {
        std::string name = info.param.file;
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        return name;
    });

// ---------------------------------------------------------------------------------------
// Draco: the fixture's quad re-encoded with KHR_draco_mesh_compression (in an external
// .bin beside the fixture's data: URI buffer), rendered with the same expectations.

fs::path dracoVariant(const std::string& fixture) {
    std::ifstream in(sceneFile(fixture));
    json doc = json::parse(in);
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(2);
    const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int uv = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
    const glm::vec3 p[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const glm::vec2 t[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (std::uint32_t f = 0; f < 2; ++f) {
        const auto* c = faces[f];
        builder.SetAttributeValuesForFace(pos, draco::FaceIndex(f), &p[c[0]], &p[c[1]], &p[c[2]]);
        builder.SetAttributeValuesForFace(uv, draco::FaceIndex(f), &t[c[0]], &t[c[1]], &t[c[2]]);
    }
    const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
    draco::EncoderBuffer buffer;
    EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());

    const fs::path dir = outputDir() / ("draco_" + fixture);
    fs::create_directories(dir);
    std::ofstream(dir / "quad.bin", std::ios::binary).write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const int points = static_cast<int>(mesh->num_points());
    const std::size_t firstAccessor = doc["accessors"].size();
    doc["buffers"].push_back({{"uri", "quad.bin"}, {"byteLength", buffer.size()}});
    doc["bufferViews"].push_back({{"buffer", doc["buffers"].size() - 1}, {"byteLength", buffer.size()}});
    doc["accessors"].push_back(
        {{"componentType", 5126}, {"count", points}, {"type", "VEC3"}, {"min", {-1, -1, 0}}, {"max", {1, 1, 0}}});
    doc["accessors"].push_back({{"componentType", 5126}, {"count", points}, {"type", "VEC2"}});
    doc["accessors"].push_back({{"componentType", 5125}, {"count", 6}, {"type", "SCALAR"}});
    json& primitive = doc["meshes"][0]["primitives"][0];
    primitive["attributes"] = {{"POSITION", firstAccessor}, {"TEXCOORD_0", firstAccessor + 1}};
    primitive["indices"] = firstAccessor + 2;
    primitive["extensions"]["KHR_draco_mesh_compression"] = {
        {"bufferView", doc["bufferViews"].size() - 1},
        {"attributes",
         {{"POSITION", mesh->attribute(pos)->unique_id()}, {"TEXCOORD_0", mesh->attribute(uv)->unique_id()}}}};
    doc["extensionsUsed"].push_back("KHR_draco_mesh_compression");
    doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    const fs::path path = dir / fixture;
    std::ofstream(path) << doc.dump(1);
    return path;
}

TEST(RacerSceneDraco, Opaque) { expectOpaqueTextureAlphaIgnored(racer(dracoVariant("opaque_texture_alpha.gltf"))); }
TEST(RacerSceneDraco, Mask) { expectMaskCoverage(racer(dracoVariant("mask_cutoff.gltf"), "--technique alpha-test")); }
TEST(RacerSceneDraco, Blend) { expectBlendFactor(racer(dracoVariant("blend_factor.gltf"))); }

// ---------------------------------------------------------------------------------------
// The automatic camera directly: for boxes of any shape and viewport aspects, every corner
// projects inside the frame shrunk by the margin, and the fit is tight (some corner on it).

namespace framing {

TEST(AutomaticCamera, FitsEveryCornerWithTheMarginAndTouchesIt) {
    struct Case {
        glm::vec3 min, max;
        float aspect;
    };
    const Case cases[] = {{{-1, -1, 0}, {1, 1, 0}, 1.0f},
                          {{-3, 0, -2}, {5, 1, 7}, 16.0f / 9.0f},
                          {{10, 20, 30}, {10.5f, 29, 31}, 0.5f},
                          {{-100, -1, -1}, {100, 1, 1}, 1.0f},
                          {{0, 0, -50}, {1, 1, 50}, 2.0f}};
    for (const Case& c : cases) {
        engine::assets::Bounds bounds;
        bounds.add(c.min);
        bounds.add(c.max);
        const racer::SceneCamera camera = racer::framingCamera(bounds, c.aspect);
        EXPECT_GT(camera.view.eye.z, c.max.z) << "in front of the box, on +Z";
        float largest = 0.0f;
        for (int k = 0; k < 8; ++k) {
            const glm::vec3 p((k & 1) ? c.max.x : c.min.x, (k & 2) ? c.max.y : c.min.y, (k & 4) ? c.max.z : c.min.z);
            const glm::vec4 clip = camera.view.viewProj * glm::vec4(p, 1.0f);
            ASSERT_GT(clip.w, 0.0f);
            const glm::vec3 ndc = glm::vec3(clip) / clip.w;
            EXPECT_GT(ndc.z, 0.0f);  // between the planes (reverse-Z: 1 near, 0 far)
            EXPECT_LT(ndc.z, 1.0f);
            largest = std::max({largest, std::abs(ndc.x), std::abs(ndc.y)});
        }
        EXPECT_NEAR(largest, 1.0f / (1.0f + racer::kAutoCameraMargin), 1e-4f);
    }
}

TEST(AutomaticCamera, EmptySceneStillGivesAFiniteView) {
    const racer::SceneCamera camera = racer::framingCamera(engine::assets::Bounds{}, 1.0f);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(camera.view.viewProj[i][j]));
}

}  // namespace framing

}  // namespace
