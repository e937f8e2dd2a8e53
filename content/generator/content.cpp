// SPDX-License-Identifier: MIT
#include "content.hpp"

#include <cmath>
#include <fstream>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/output_file.hpp"
#include "geometry.hpp"
#include "gltf_writer.hpp"
#include "lod_levels.hpp"
#include "plants.hpp"
#include "textures.hpp"

namespace content {

namespace {

namespace fs = std::filesystem;

constexpr int kRepeat = 10497;
constexpr int kClampToEdge = 33071;

// Writes `bytes` to a temporary file of `staged` that becomes `path` when all are committed.
void stageBytes(engine::PendingFiles& staged, const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(staged.add(path), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw engine::Error("cannot write '" + path.string() + "'");
}

ordered_json opaqueMaterial(const std::string& name, int texture, double metallic, double roughness) {
    return {
        {"name", name},
        {"pbrMetallicRoughness",
         {{"baseColorTexture", {{"index", texture}}}, {"metallicFactor", metallic}, {"roughnessFactor", roughness}}},
        {"alphaMode", "OPAQUE"}};
}

// The skin of a model drawn opaque: one embedded image, sampled by one material.
struct OpaqueSkin {
    const std::vector<std::uint8_t>& png;
    const char* image;
    int wrap;
    const char* material;
    double metallic;
    double roughness;
};

// A file of one opaque textured mesh, scene 0's only node: the car, the terrain, the track.
std::vector<std::uint8_t> opaqueModel(const char* name, const MeshData& mesh, const OpaqueSkin& skin,
                                      ordered_json extras = nullptr) {
    GlbWriter glb;
    const int texture = glb.addTexture(glb.addPngImage(skin.png, skin.image), skin.wrap);
    const int material = glb.addMaterial(opaqueMaterial(skin.material, texture, skin.metallic, skin.roughness));
    const int model = glb.addMesh(name, {{&mesh, material}}, false, std::move(extras));
    glb.setSceneNodes({glb.addNode({{"name", name}, {"mesh", model}})});
    return glb.glb();
}

// The images every model embeds, encoded once, and the plants made from them (each plant's
// levels are measured once, for its file and for the table of levels).
struct Pngs {
    std::vector<std::uint8_t> leaves, fronds, bark, ground, track, car;
    RgbaImage leafImage, frondImage, barkImage;
    std::vector<PlantModel> plants;  // in plantRecipes() order
};

// The plant of that name: its file is scene 0 (the full model) and its levels of detail.
std::vector<std::uint8_t> plantFile(const Pngs& pngs, const char* name) {
    for (const PlantModel& plant : pngs.plants)
        if (plant.lod["file"] == std::string(name) + ".glb") return plant.glb;
    throw engine::Error(std::string("no plant recipe named '") + name + "'");
}

// Every plant's levels: which scene of its file each is and below how many pixels of height
// it takes over, with the measured errors that chose it (lod_levels.hpp).
std::vector<std::uint8_t> lodTable(const Pngs& pngs) {
    ordered_json table = {{"pixelError", kLodPixelError},
                          {"deviationPercentile", kDeviationPercentile},
                          {"measuredPixels", kDeviationPixels},
                          {"measuredYaws", kMeasuredYaws},
                          {"plants", ordered_json::array()}};
    for (const PlantModel& plant : pngs.plants) table["plants"].push_back(plant.lod);
    const std::string text = table.dump(1) + "\n";
    return {text.begin(), text.end()};
}

// Boxes and wheels, +Z forward, one textured atlas material (textures.hpp makeCarAtlas).
std::vector<std::uint8_t> car(const Pngs& pngs) {
    const glm::vec4 paint(0.02f, 0.02f, 0.98f, 0.48f), glass(0.02f, 0.52f, 0.98f, 0.73f),
        tyre(0.02f, 0.77f, 0.98f, 0.98f);
    MeshData body;
    addBox(body, {-0.9f, 0.3f, -2.1f}, {0.9f, 0.95f, 2.1f}, paint, paint);
    addBox(body, {-0.75f, 0.95f, -0.9f}, {0.75f, 1.45f, 0.8f}, paint, glass);
    addBox(body, {-0.85f, 1.0f, -2.1f}, {0.85f, 1.08f, -1.8f}, paint, paint);  // the rear wing
    for (int side = -1; side <= 1; side += 2)
        for (int axle = -1; axle <= 1; axle += 2)
            addWheel(body, {0.9f * static_cast<float>(side), 0.34f, 1.35f * static_cast<float>(axle)}, 0.34f, 0.3f, 12,
                     tyre);
    return opaqueModel("car", body, {pngs.car, "car_atlas", kClampToEdge, "car", 0.2, 0.4});
}

// A round pool of radius 1 (placed scaled): a BLEND material, untextured.
std::vector<std::uint8_t> water() {
    const MeshData surface = disc(1.0f, 32);
    GlbWriter glb;
    const int material = glb.addMaterial(
        {{"name", "water"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.10, 0.30, 0.40, 0.6}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.05}}},
         {"alphaMode", "BLEND"}});
    const int mesh = glb.addMesh("water", {{&surface, material}}, false);
    glb.setSceneNodes({glb.addNode({{"name", "water"}, {"mesh", mesh}})});
    return glb.glb();
}

std::vector<std::uint8_t> terrain(const Pngs& pngs) {
    const MeshData ground = terrainPatch(64.0f, 32, 1.2f, 8.0f, 0x7E44u);
    return opaqueModel("terrain", ground, {pngs.ground, "ground", kRepeat, "ground", 0.0, 1.0});
}

// Millimetre-rounded coordinates keep the centre line's JSON short and exact.
ordered_json pointsJson(const std::vector<glm::vec3>& points) {
    ordered_json out = ordered_json::array();
    for (const glm::vec3& p : points)
        out.push_back({std::round(static_cast<double>(p.x) * 1000.0) / 1000.0,
                       std::round(static_cast<double>(p.y) * 1000.0) / 1000.0,
                       std::round(static_cast<double>(p.z) * 1000.0) / 1000.0});
    return out;
}

// The closed track: the ribbon mesh, with its centre line in the mesh's extras.
std::vector<std::uint8_t> track(const Pngs& pngs) {
    const TrackShape shape = trackShape(0x7AC4u, 10, {130.0f, 85.0f}, 24, 12.0f);
    const MeshData ribbon = trackRibbon(shape);
    ordered_json extras = {
        {"centreLine",
         {{"closed", true},
          {"spline", "uniform Catmull-Rom through controlPoints; samples are its points, first not repeated"},
          {"width", shape.width},
          {"controlPoints", pointsJson(shape.control)},
          {"samples", pointsJson(shape.centreLine)}}}};
    return opaqueModel("track", ribbon, {pngs.track, "track", kRepeat, "track", 0.0, 0.9}, std::move(extras));
}

// Every file, in the fixed order generateContent() writes them, and how it is made.
struct ContentFile {
    const char* path;
    std::vector<std::uint8_t> (*make)(const Pngs&);
};

const ContentFile kFiles[] = {
    // Standalone textures the game applies to the terrain and road it builds in code.
    {"textures/ground.png", [](const Pngs& pngs) { return pngs.ground; }},
    {"textures/track.png", [](const Pngs& pngs) { return pngs.track; }},
    {"models/tree_broadleaf.glb", [](const Pngs& pngs) { return plantFile(pngs, "tree_broadleaf"); }},
    {"models/tree_tall.glb", [](const Pngs& pngs) { return plantFile(pngs, "tree_tall"); }},
    {"models/tree_palm.glb", [](const Pngs& pngs) { return plantFile(pngs, "tree_palm"); }},
    {"models/bush_round.glb", [](const Pngs& pngs) { return plantFile(pngs, "bush_round"); }},
    {"models/bush_fern.glb", [](const Pngs& pngs) { return plantFile(pngs, "bush_fern"); }},
    {"lod/levels.json", lodTable},
    {"models/car.glb", car},
    {"models/water.glb", [](const Pngs&) { return water(); }},
    {"models/terrain.glb", terrain},
    {"models/track.glb", track},
};

}  // namespace

std::vector<fs::path> contentFiles() {
    std::vector<fs::path> files;
    for (const ContentFile& file : kFiles) files.emplace_back(file.path);
    return files;
}

std::vector<fs::path> generateContent(const fs::path& dir, bool draco) {
    Pngs pngs;
    pngs.leafImage = makeLeafCluster(0x1EAFu);
    pngs.frondImage = makeFrond(0xF40Du);
    pngs.barkImage = makeBark(0xBA4Cu);
    pngs.leaves = encodePng(pngs.leafImage);
    pngs.fronds = encodePng(pngs.frondImage);
    pngs.bark = encodePng(pngs.barkImage);
    pngs.ground = encodePng(makeGround(0x6400u));
    pngs.track = encodePng(makeTrack(0x7AC0u));
    pngs.car = encodePng(makeCarAtlas(0xCA40u));
    for (const PlantRecipe& recipe : plantRecipes())
        pngs.plants.push_back(plantModel(recipe, {recipe.fronds ? &pngs.frondImage : &pngs.leafImage, &pngs.barkImage},
                                         recipe.fronds ? pngs.fronds : pngs.leaves, pngs.bark, draco));

    engine::PendingFiles staged;  // the content set is replaced whole or not at all
    std::vector<fs::path> written;
    for (const ContentFile& file : kFiles) {
        const fs::path target = dir / file.path;
        fs::create_directories(target.parent_path());
        stageBytes(staged, target, file.make(pngs));
        written.emplace_back(file.path);
    }
    staged.commit();
    return written;
}

}  // namespace content
