// SPDX-License-Identifier: MIT
#pragma once
// What a glTF file that loadGltf accepted must look like (engine/assets/gltf.hpp): every
// number finite (the loader refuses NaN and infinity rather than passing them on), every
// index inside what it indexes, triangle lists of whole triangles, images of the size they
// claim. Throws ssam::fuzz::ContractViolation naming the first broken promise.
#include <filesystem>

#include "engine/assets/gltf.hpp"

namespace ssam::fuzz {

void checkLoadedModel(const engine::assets::LoadedModel& model);

// One fuzz input: loads the glTF at `path` and checks the model, or checks that the refusal
// names the file (the only acceptable failure).
void loadAndCheck(const std::filesystem::path& path);

}  // namespace ssam::fuzz
