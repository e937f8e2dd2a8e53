// SPDX-License-Identifier: MIT
#include "content_files.hpp"

#include <fstream>
#include <iterator>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "engine/assets/gltf.hpp"
#include "engine/assets/image.hpp"
#include "engine/assets/mips.hpp"
#include "engine/core/error.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/transform.hpp"

namespace racer {

using namespace engine;
using namespace engine::render;

std::filesystem::path requireContent(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path))
        throw Error("content file '" + path.string() + "' is missing (regenerate with `make content`)");
    return path;
}

TextureBinding loadContentTexture(Backend& backend, const std::filesystem::path& path) {
    std::ifstream file(requireContent(path), std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const assets::RgbaImage image = assets::decodeImage(bytes, path.string());
    const std::vector<assets::RgbaImage> levels = assets::generateMips(image, {AlphaMode::Premultiplied, -1.0f, 0});
    TextureDesc desc;
    desc.name = path.filename().string();
    desc.width = image.width;
    desc.height = image.height;
    desc.format = Format::RGBA8_SRGB;
    desc.mipLevels = static_cast<int>(levels.size());
    desc.alpha = levels.front().alpha;
    const TextureData data = assets::textureData(levels);
    return {backend.createTexture(desc, &data), {Filter::Trilinear, AddressMode::Wrap, AddressMode::Wrap}};
}

scene::ModelId loadContentModel(scene::MeshLibrary& library, const std::filesystem::path& path) {
    return library.add(assets::loadGltf(requireContent(path)));
}

void placeModel(ecs::Registry& registry, scene::ModelId model, const glm::vec3& position, float rotation, float scale) {
    const ecs::Entity e = registry.create();
    registry.add<scene::Transform>(
        e, scene::Transform{position, glm::angleAxis(rotation, glm::vec3(0.0f, 1.0f, 0.0f)), glm::vec3(scale)});
    registry.add<scene::Renderable>(e, scene::Renderable{model});
}

}  // namespace racer
