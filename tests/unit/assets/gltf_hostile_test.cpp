// SPDX-License-Identifier: MIT
// Hostile and broken glTF files are refused with an engine::Error that names the file, the
// field and the problem. One committed fixture per rule (tests/data/gltf/hostile, made by
// make_fixtures.py), plus cases that need the file system (missing files, symbolic links).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "assets_test_util.hpp"
#include "engine/assets/gltf.hpp"

namespace {

using assets_test::errorOf;
using assets_test::fixture;
using assets_test::TempDir;
using engine::assets::loadGltf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

struct HostileCase {
    const char* file;
    std::vector<const char*> expected;  // substrings of the message, beyond the file name
};

void PrintTo(const HostileCase& c, std::ostream* os) { *os << c.file; }

class GltfHostile : public ::testing::TestWithParam<HostileCase> {};

TEST_P(GltfHostile, IsRefusedNamingFileFieldAndProblem) {
    const HostileCase& c = GetParam();
    const auto path = fixture(std::string("hostile/") + c.file);
    ASSERT_TRUE(std::filesystem::exists(path)) << path << " (run tests/data/gltf/make_fixtures.py)";
    const std::string message = errorOf([&] { loadGltf(path); });
    EXPECT_THAT(message, StartsWith(path.string() + ": "));
    for (const char* part : c.expected) EXPECT_THAT(message, HasSubstr(part));
}

const HostileCase kCases[] = {
    // URIs
    {"uri_traversal.gltf", {"buffers[0].uri '../../etc/passwd': path traversal is not allowed"}},
    {"uri_absolute.gltf", {"buffers[0].uri '/etc/passwd': absolute paths are not allowed"}},
    {"uri_scheme.gltf", {"buffers[0].uri 'https://example.com/triangle.bin'", "scheme 'https:' is not allowed"}},
    {"uri_file_scheme.gltf", {"buffers[0].uri", "scheme 'file:' is not allowed"}},
    {"uri_percent_traversal.gltf", {"buffers[0].uri '%2e%2e/%2E%2E/etc/passwd': path traversal is not allowed"}},
    {"uri_backslash_traversal.gltf", {"buffers[0].uri", "path traversal is not allowed"}},
    {"image_uri_traversal.gltf", {"images[0].uri 'textures/../../secret.png': path traversal is not allowed"}},
    {"missing_bin.gltf", {"buffers[0].uri 'missing.bin'", "does not exist"}},
    {"missing_image.gltf", {"images[0].uri 'missing.png'", "does not exist"}},
    // extensions
    {"required_extension.gltf", {"extensionsRequired[1] 'EXT_made_up_extension': required extension is not supported"}},
    // GLB container
    {"glb_length_mismatch.glb", {"GLB header length: 1828 does not match the file size of 1728 bytes"}},
    {"glb_json_chunk_overrun.glb", {"GLB chunk 0 length: ", "runs past the end of the file"}},
    {"glb_bin_chunk_overrun.glb", {"GLB chunk 1 length: ", "runs past the end of the file"}},
    {"glb_bin_chunk_huge.glb", {"GLB chunk 1 length: 4294967292 runs past the end of the file (204 bytes left)"}},
    {"glb_truncated.glb", {"GLB header: truncated"}},
    // buffers, bufferViews, accessors
    {"bufferview_out_of_range.gltf",
     {"bufferViews[1]: byteOffset 72 + byteLength 64 exceeds buffers[0].byteLength 104"}},
    {"bufferview_offset_overflow.gltf", {"bufferViews[2]: byteOffset 18446744073709551610 + byteLength 6 exceeds"}},
    {"bufferview_bad_buffer.gltf", {"bufferViews[2].buffer: 7 is out of range: the file has 1 buffers"}},
    {"stride_out_of_range.gltf", {"bufferViews[0].byteStride: 2: must be a multiple of 4 in [4, 252]"}},
    {"stride_too_small.gltf", {"bufferViews[0].byteStride: 8 is smaller than the 12-byte elements of accessors[0]"}},
    {"accessor_out_of_range.gltf",
     {"accessors[2] (meshes[0].primitives[0].attributes.TEXCOORD_0)", "exceeds bufferViews[1].byteLength 24"}},
    {"accessor_offset_past_view.gltf",
     {"accessors[1] (meshes[0].primitives[0].attributes.NORMAL): byteOffset 40",
      "exceeds bufferViews[0].byteLength 72"}},
    {"accessor_huge_count.gltf",
     {"accessors[0] (meshes[0].primitives[0].attributes.POSITION).count", "over the limit"}},
    {"accessor_misaligned.gltf",
     {"accessors[1] (meshes[0].primitives[0].attributes.NORMAL).byteOffset: 2 is not aligned"}},
    {"accessor_bad_bufferview.gltf", {"accessors[2]", ".bufferView: 9 is out of range"}},
    {"component_type_double.gltf", {"accessors[0]", ".componentType: 5130 is not a glTF 2.0 component type"}},
    {"component_type_not_allowed.gltf",
     {"accessors[3] (meshes[0].primitives[0].indices).componentType: FLOAT is not allowed"}},
    {"index_out_of_range.gltf",
     {"accessors[3] (meshes[0].primitives[0].indices): index 7 at position 2 is out of range for 3 vertices"}},
    {"nan_position.gltf",
     {"accessors[0] (meshes[0].primitives[0].attributes.POSITION): element 1 has a non-finite component"}},
    {"inf_position.gltf", {"attributes.POSITION): element 1 has a non-finite component"}},
    // materials, textures, images
    {"alpha_cutoff_negative.gltf", {"materials[0].alphaCutoff: -0.5", "must be a finite number >= 0"}},
    // JSON cannot spell NaN or infinity; a number too large for a double is refused by the parser.
    {"alpha_cutoff_infinite.gltf", {"JSON: not valid JSON", "number overflow parsing '1e400'"}},
    {"alpha_mode_unknown.gltf", {"materials[0].alphaMode: 'CUTOUT': must be OPAQUE, MASK or BLEND"}},
    {"texture_bad_source.gltf", {"textures[0].source: 3 is out of range: the file has 1 images"}},
    {"material_bad_texture.gltf", {"materials[0].pbrMetallicRoughness.baseColorTexture.index: 5 is out of range"}},
    {"image_too_large.gltf", {"images[0]: image is 20000x20000, over the size cap of 16384x16384"}},
    {"image_not_png.gltf", {"images[0]: not a PNG or JPEG image"}},
    // nodes, cameras, JSON
    {"node_bad_mesh.gltf", {"nodes[1].mesh: 4 is out of range: the file has 1 meshes"}},
    {"node_cycle.gltf", {"is part of a cycle in the node hierarchy"}},
    {"node_two_parents.gltf", {"nodes[2].children[0]: node 1 already has parent node 0"}},
    {"camera_bad_yfov.gltf", {"cameras[0].perspective.yfov"}},
    {"json_too_deep.gltf", {"JSON: nested deeper than 64 levels"}},
    // Draco
    {"draco_garbage.gltf", {"meshes[0].primitives[0].extensions.KHR_draco_mesh_compression", "Draco"}},
};

INSTANTIATE_TEST_SUITE_P(Fixtures, GltfHostile, ::testing::ValuesIn(kCases), [](const auto& info) {
    std::string name = info.param.file;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
});

TEST(GltfHostileFiles, MissingFileIsNamed) {
    const auto path = fixture("no_such_file.gltf");
    EXPECT_EQ(errorOf([&] { loadGltf(path); }), path.string() + ": file does not exist");
}

TEST(GltfHostileFiles, DirectoryIsRefused) {
    TempDir dir;
    std::filesystem::create_directories(dir / "scene.gltf");
    EXPECT_THAT(errorOf([&] { loadGltf(dir / "scene.gltf"); }), HasSubstr("is a directory"));
}

TEST(GltfHostileFiles, EmptyAndGarbageFilesAreRefused) {
    TempDir dir;
    assets_test::writeFile(dir / "empty.gltf", "");
    EXPECT_THAT(errorOf([&] { loadGltf(dir / "empty.gltf"); }), HasSubstr("empty.gltf: JSON: not valid JSON"));
    assets_test::writeFile(dir / "array.gltf", "[1, 2, 3]");
    EXPECT_THAT(errorOf([&] { loadGltf(dir / "array.gltf"); }), HasSubstr("JSON: the top level is not an object"));
    assets_test::writeFile(dir / "v1.gltf", R"({"asset": {"version": "1.0"}})");
    EXPECT_THAT(errorOf([&] { loadGltf(dir / "v1.gltf"); }), HasSubstr("asset.version: '1.0': only glTF 2.x"));
}

// A file that is not glTF is refused by what it is, its bytes never echoed into the message.
bool printableAscii(const std::string& text) {
    for (const char c : text)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) return false;
    return true;
}

TEST(GltfHostileFiles, OtherFormatsAreNamedByTheirSignature) {
    TempDir dir;
    std::filesystem::copy_file(fixture("leaf4.png"), dir / "picture.gltf");
    const std::string png = errorOf([&] { loadGltf(dir / "picture.gltf"); });
    EXPECT_EQ(png, (dir / "picture.gltf").string() + ": starts with the PNG signature, not glTF JSON or GLB");
    assets_test::writeFile(dir / "archive.glb", std::string("PK\x03\x04\x14\x00\x00\x00", 8));
    EXPECT_THAT(errorOf([&] { loadGltf(dir / "archive.glb"); }),
                HasSubstr("archive.glb: starts with the ZIP signature, not glTF JSON or GLB"));
    assets_test::writeFile(dir / "noise.gltf", std::string("\x93\x01\xfe{}", 5));
    EXPECT_THAT(errorOf([&] { loadGltf(dir / "noise.gltf"); }),
                HasSubstr("noise.gltf: starts with the byte 0x93, not glTF JSON or GLB"));
    EXPECT_TRUE(printableAscii(png)) << png;
}

TEST(GltfHostileFiles, JsonParserMessagesCarryNoRawBytes) {
    TempDir dir;
    assets_test::writeFile(dir / "binary_inside.gltf", std::string("{\"asset\": \x89\x01}"));
    const std::string message = errorOf([&] { loadGltf(dir / "binary_inside.gltf"); });
    EXPECT_THAT(message, HasSubstr("JSON: not valid JSON"));
    EXPECT_THAT(message, HasSubstr("\\x89"));
    EXPECT_TRUE(printableAscii(message)) << message;
}

// A relative URI naming a symbolic link that points outside the glTF's directory.
TEST(GltfHostileFiles, SymbolicLinkOutOfTheDirectoryIsRefused) {
    TempDir dir;
    std::filesystem::create_directories(dir / "scene");
    std::filesystem::copy_file(fixture("triangle.bin"), dir / "outside.bin");
    std::filesystem::copy_file(fixture("leaf4.png"), dir / "scene" / "leaf4.png");
    std::filesystem::create_symlink(dir / "outside.bin", dir / "scene" / "triangle.bin");
    std::filesystem::copy_file(fixture("triangle.gltf"), dir / "scene" / "triangle.gltf");
    EXPECT_THAT(errorOf([&] { loadGltf(dir / "scene" / "triangle.gltf"); }),
                HasSubstr("buffers[0].uri 'triangle.bin': resolves outside the glTF file's directory"));
}

TEST(GltfHostileFiles, ExternalBinOfTheWrongSizeIsRefused) {
    TempDir dir;
    std::filesystem::copy_file(fixture("triangle.gltf"), dir / "triangle.gltf");
    std::filesystem::copy_file(fixture("leaf4.png"), dir / "leaf4.png");
    assets_test::writeFile(dir / "triangle.bin", std::string(100, '\0'));
    EXPECT_THAT(errorOf([&] { loadGltf(dir / "triangle.gltf"); }),
                HasSubstr("buffers[0].byteLength: 104 does not match the size of 'triangle.bin' (100 bytes)"));
}

TEST(GltfHostileFiles, OversizeFileIsRefusedBeforeReading) {
    engine::assets::LoadOptions options;
    options.maxFileBytes = 100;
    EXPECT_THAT(errorOf([&] { loadGltf(fixture("triangle.gltf"), options); }), HasSubstr("over the limit of 100"));
}

}  // namespace
