// SPDX-License-Identifier: MIT
#pragma once
// Loading the committed content (content/): models, textures and placed instances, shared
// by the racing scene and ssam-bench's scenes.
#include <filesystem>

#include <glm/glm.hpp>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/backend.hpp"
#include "engine/scene/mesh_library.hpp"

namespace racer {

// The path, or engine::Error saying the content file is missing and how to regenerate it.
std::filesystem::path requireContent(const std::filesystem::path& path);

// An sRGB colour texture with premultiplied-alpha mips ([Hargreaves 2009]), trilinear and wrapping.
engine::render::TextureBinding loadContentTexture(engine::render::Backend& backend, const std::filesystem::path& path);

engine::scene::ModelId loadContentModel(engine::scene::MeshLibrary& library, const std::filesystem::path& path);

// An entity showing `model` at `position`, turned `rotation` radians about +Y and scaled.
void placeModel(engine::ecs::Registry& registry, engine::scene::ModelId model, const glm::vec3& position,
                float rotation, float scale);

}  // namespace racer
