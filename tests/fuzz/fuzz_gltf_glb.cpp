// SPDX-License-Identifier: MIT
// Fuzz target: engine::assets::loadGltf on a binary glTF (.glb) — the container, the JSON,
// accessors, Draco (KHR_draco_mesh_compression) and images embedded in bufferViews.
// Seeds: tests/fuzz/corpus/gltf_glb (make_corpus.py).
#include <cstddef>
#include <cstdint>

#include "engine/assets/gltf.hpp"
#include "engine/core/error.hpp"
#include "fuzz_support.hpp"
#include "gltf_contract.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path input = [] {
        ssam::fuzz::silenceWarnings();
        return ssam::fuzz::scratchDir("gltf_glb") / "input.glb";
    }();
    ssam::fuzz::writeInput(input, data, size);
    ssam::fuzz::loadAndCheck(input);
    return 0;
}
