// SPDX-License-Identifier: MIT
// Fuzz target: engine::assets::loadGltf on a JSON glTF (.gltf) whose relative URIs can reach
// real files: the directory it is loaded from also holds triangle.bin and leaf4.png (copies
// of tests/data/gltf), a sub-directory, and escape.bin, a symbolic link to a file outside
// the directory, which the loader must refuse to follow. Seeds: tests/fuzz/corpus/gltf_text.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/assets/gltf.hpp"
#include "engine/core/error.hpp"
#include "fuzz_support.hpp"
#include "gltf_contract.hpp"

namespace {

std::filesystem::path prepareDirectory() {
    namespace fs = std::filesystem;
    ssam::fuzz::silenceWarnings();
    const fs::path scratch = ssam::fuzz::scratchDir("gltf_text");
    const fs::path dir = scratch / "model";
    fs::create_directories(dir / "textures");
    const fs::path fixtures = fs::path(SSAM_SOURCE_DIR) / "tests" / "data" / "gltf";
    for (const char* sibling : {"triangle.bin", "leaf4.png"}) fs::copy_file(fixtures / sibling, dir / sibling);
    fs::copy_file(fixtures / "leaf4.png", dir / "textures" / "leaf4.png");
    fs::copy_file(fixtures / "triangle.bin", scratch / "outside.bin");  // same size as triangle.bin
    fs::create_symlink(scratch / "outside.bin", dir / "escape.bin");
    return dir / "input.gltf";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path input = prepareDirectory();
    ssam::fuzz::writeInput(input, data, size);
    ssam::fuzz::loadAndCheck(input);
    return 0;
}
