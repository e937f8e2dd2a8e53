// SPDX-License-Identifier: MIT
#include "plant_levels.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

#include "content_files.hpp"
#include "engine/assets/gltf.hpp"
#include "engine/core/error.hpp"
#include "engine/scene/components.hpp"

namespace racer {

using engine::scene::LevelsOfDetail;
using engine::scene::ModelId;

namespace {

// The entry of levels.json for `name` (e.g. "tree_tall.glb").
nlohmann::json levelEntry(const std::filesystem::path& table, const std::string& name) {
    std::ifstream in(requireContent(table));
    const nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !doc.contains("plants") || !doc["plants"].is_array())
        throw engine::Error(table.string() + ": not a table of levels (no \"plants\" array); run `make content`");
    for (const nlohmann::json& plant : doc["plants"])
        if (plant.value("file", std::string()) == name) return plant;
    throw engine::Error(table.string() + ": no levels for '" + name + "'");
}

float positiveNumber(const nlohmann::json& value, const std::filesystem::path& table, const std::string& what) {
    if (!value.is_number() || !(value.get<float>() > 0.0f))
        throw engine::Error(table.string() + ": " + what + " must be a positive number");
    return value.get<float>();
}

}  // namespace

LevelsOfDetail loadPlantLevels(engine::scene::MeshLibrary& library, const std::filesystem::path& contentDir,
                               const std::filesystem::path& file, ModelId full) {
    const std::filesystem::path table = contentDir / "lod" / "levels.json";
    const std::string name = file.filename().string();
    const nlohmann::json entry = levelEntry(table, name);
    LevelsOfDetail lod;
    lod.models[0] = full;
    lod.height = positiveNumber(entry.value("height", nlohmann::json()), table, name + ": height");
    const nlohmann::json levels = entry.value("levels", nlohmann::json::array());
    if (!levels.is_array() || levels.size() + 1 > lod.models.size())
        throw engine::Error(table.string() + ": " + name + ": levels must be an array of at most " +
                            std::to_string(lod.models.size() - 1));
    for (std::size_t k = 0; k < levels.size(); ++k) {
        const std::string where = name + ": levels[" + std::to_string(k) + "]";
        const nlohmann::json& level = levels[k];
        if (!level.is_object() || !level.value("scene", nlohmann::json()).is_number_integer())
            throw engine::Error(table.string() + ": " + where + ": scene must be an integer");
        lod.belowPixels[k] =
            positiveNumber(level.value("belowPixels", nlohmann::json()), table, where + ".belowPixels");
        if (k > 0 && lod.belowPixels[k] > lod.belowPixels[k - 1])
            throw engine::Error(table.string() + ": " + where + ".belowPixels exceeds the finer level's");
        engine::assets::LoadOptions options;
        options.scene = level["scene"].get<int>();
        lod.models[k + 1] = library.add(engine::assets::loadGltf(requireContent(file), options));
    }
    lod.levels = int(levels.size()) + 1;
    return lod;
}

std::size_t attachPlantLevels(engine::ecs::Registry& registry, const std::map<ModelId, LevelsOfDetail>& levels) {
    std::vector<std::pair<engine::ecs::Entity, const LevelsOfDetail*>> plants;
    registry.view<const engine::scene::Renderable>().each(
        [&](engine::ecs::Entity e, const engine::scene::Renderable& r) {
            const auto it = levels.find(r.model);
            if (it != levels.end()) plants.emplace_back(e, &it->second);
        });
    for (const auto& [e, lod] : plants) registry.add<LevelsOfDetail>(e, *lod);
    return plants.size();
}

}  // namespace racer
