// SPDX-License-Identifier: MIT
#include "lod_levels.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <cstdlib>

#include "gltf_writer.hpp"
#include "ortho_render.hpp"
#include "textures.hpp"

namespace content {

namespace {

constexpr int kRepeat = 10497;
constexpr int kClampToEdge = 33071;
// Each impostor view: 64 x 96 texels, about the most a plant drawn at the impostor's heights shows.
constexpr int kViewWidth = 64, kViewHeight = 96;

// The box every level is drawn in: around the trunk's axis, out to the farthest vertex, a
// margin so the impostor's texture keeps a transparent border.
struct Frame {
    float halfWidth, bottom, top;
};

Frame frameOf(const PlantMeshes& plant) {
    float radius = 0.0f, bottom = 1e30f, top = -1e30f;
    auto take = [&](const MeshData& m) {
        for (const glm::vec3& p : m.positions) {
            radius = std::max(radius, std::sqrt(p.x * p.x + p.z * p.z));
            bottom = std::min(bottom, p.y);
            top = std::max(top, p.y);
        }
    };
    take(plant.cards);
    if (plant.trunk) take(*plant.trunk);
    const float margin = 0.04f * std::max(2.0f * radius, top - bottom);
    return {radius + margin, bottom - margin, top + margin};
}

std::vector<Surface> surfacesOf(const PlantMeshes& plant, const PlantTextures& textures,
                                const engine::assets::RgbaImage* impostor) {
    std::vector<Surface> out;
    if (plant.trunk) out.push_back({&*plant.trunk, textures.bark, false});
    out.push_back({&plant.cards, impostor ? impostor : textures.foliage, true});
    return out;
}

// Two crossed vertical cards through the axis, each showing its half of the atlas: card 0 in
// the plane z = 0 (seen along +z, yaw 0), card 1 in x = 0 (seen along +x, yaw 90 degrees).
// Their normals face the viewer of their view: the foliage passes light both faces (the back
// face's normal flipped), so either side is lit as facing its viewer.
MeshData impostorCards(const Frame& f) {
    MeshData mesh;
    for (int card = 0; card < 2; ++card) {
        const float yaw = card == 0 ? 0.0f : 0.5f * std::numbers::pi_v<float>;
        const glm::vec3 right(std::cos(yaw), 0.0f, -std::sin(yaw)), facing(-std::sin(yaw), 0.0f, -std::cos(yaw));
        const float u0 = 0.5f * float(card), u1 = u0 + 0.5f;
        const glm::vec3 p[4] = {
            right * -f.halfWidth + glm::vec3(0, f.top, 0), right * f.halfWidth + glm::vec3(0, f.top, 0),
            right * f.halfWidth + glm::vec3(0, f.bottom, 0), right * -f.halfWidth + glm::vec3(0, f.bottom, 0)};
        const glm::vec2 uv[4] = {{u0, 0.0f}, {u1, 0.0f}, {u1, 1.0f}, {u0, 1.0f}};
        mesh.addQuad(p, facing, uv);
    }
    return mesh;
}

// The impostor's atlas: the full model seen from yaw 0 (left half) and yaw 90 degrees (right).
engine::assets::RgbaImage impostorAtlas(const PlantMeshes& full, const PlantTextures& textures, const Frame& f) {
    engine::assets::RgbaImage atlas = engine::assets::RgbaImage::make(2 * kViewWidth, kViewHeight);
    for (int card = 0; card < 2; ++card) {
        OrthoView view;
        view.yaw = card == 0 ? 0.0f : 0.5f * std::numbers::pi_v<float>;
        view.halfWidth = f.halfWidth;
        view.bottom = f.bottom;
        view.top = f.top;
        view.width = kViewWidth;
        view.height = kViewHeight;
        view.samples = 4;
        const engine::assets::RgbaImage half =
            toTexture(renderOrtho(surfacesOf(full, textures, nullptr), view), kViewWidth, kViewHeight);
        for (int y = 0; y < kViewHeight; ++y)
            std::copy_n(half.texel(0, y), 4 * kViewWidth, atlas.texel(card * kViewWidth, y));
    }
    return atlas;
}

// Squared Euclidean distance, in pixels, from each pixel to the nearest pixel of `mask`: the
// exact transform of [Felzenszwalb & Huttenlocher 2012] §2, by columns then by rows.
std::vector<float> squaredDistanceTo(const std::vector<bool>& mask, int width, int height) {
    constexpr float kFar = 1e20f;
    std::vector<float> d(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i) d[i] = mask[i] ? 0.0f : kFar;
    std::vector<float> f, out;
    std::vector<int> v;
    std::vector<float> z;
    auto pass = [&](int n, auto at) {  // the lower envelope of parabolas rooted at f(q)
        f.resize(std::size_t(n));
        out.resize(std::size_t(n));
        v.assign(std::size_t(n), 0);
        z.assign(std::size_t(n) + 1, 0.0f);
        for (int q = 0; q < n; ++q) f[std::size_t(q)] = at(q);
        int k = 0;
        z[0] = -kFar;
        z[1] = kFar;
        for (int q = 1; q < n; ++q) {
            float s;
            while (true) {
                const int r = v[std::size_t(k)];
                s = ((f[std::size_t(q)] + float(q * q)) - (f[std::size_t(r)] + float(r * r))) / float(2 * (q - r));
                if (s > z[std::size_t(k)] || k == 0) break;
                --k;
            }
            if (s <= z[std::size_t(k)]) {  // k == 0 and q wins everywhere
                v[0] = q;
                z[1] = kFar;
                continue;
            }
            ++k;
            v[std::size_t(k)] = q;
            z[std::size_t(k)] = s;
            z[std::size_t(k) + 1] = kFar;
        }
        k = 0;
        for (int q = 0; q < n; ++q) {
            while (z[std::size_t(k) + 1] < float(q)) ++k;
            const int r = v[std::size_t(k)];
            out[std::size_t(q)] = float((q - r) * (q - r)) + f[std::size_t(r)];
        }
    };
    for (int x = 0; x < width; ++x) {
        pass(height, [&](int y) { return d[std::size_t(y) * std::size_t(width) + std::size_t(x)]; });
        for (int y = 0; y < height; ++y) d[std::size_t(y) * std::size_t(width) + std::size_t(x)] = out[std::size_t(y)];
    }
    for (int y = 0; y < height; ++y) {
        pass(width, [&](int x) { return d[std::size_t(y) * std::size_t(width) + std::size_t(x)]; });
        for (int x = 0; x < width; ++x) d[std::size_t(y) * std::size_t(width) + std::size_t(x)] = out[std::size_t(x)];
    }
    return d;
}

// The level's deviation from the full model, in metres (lod_levels.hpp): both drawn
// kDeviationPixels tall from each measured direction; every pixel one covers and the other
// does not is as far off as the other's nearest covered pixel; the kDeviationPercentile-th
// percentile of those distances over the pixels either covers, the worst direction's.
float levelDeviation(const std::vector<Surface>& full, const std::vector<Surface>& level, const Frame& f) {
    float worst = 0.0f;
    for (int i = 0; i < kMeasuredYaws; ++i) {
        OrthoView view;
        view.yaw = float(i) * 0.5f * std::numbers::pi_v<float> / float(kMeasuredYaws);
        view.halfWidth = f.halfWidth;
        view.bottom = f.bottom;
        view.top = f.top;
        view.height = kDeviationPixels;
        view.width = std::max(1, int(std::lround(float(kDeviationPixels) * 2.0f * f.halfWidth / (f.top - f.bottom))));
        view.samples = 1;
        const std::vector<glm::vec4> a = renderOrtho(full, view), b = renderOrtho(level, view);
        std::vector<bool> inA(a.size()), inB(b.size());
        for (std::size_t p = 0; p < a.size(); ++p) {
            inA[p] = a[p].a > 0.0f;
            inB[p] = b[p].a > 0.0f;
        }
        const std::vector<float> toA = squaredDistanceTo(inA, view.width, view.height),
                                 toB = squaredDistanceTo(inB, view.width, view.height);
        std::vector<float> off;
        for (std::size_t p = 0; p < a.size(); ++p)
            if (inA[p] || inB[p]) off.push_back(std::sqrt(inA[p] ? toB[p] : toA[p]));
        if (off.empty()) continue;
        const std::size_t at = std::min(off.size() - 1, std::size_t(double(off.size()) * kDeviationPercentile / 100.0));
        std::nth_element(off.begin(), off.begin() + std::ptrdiff_t(at), off.end());
        worst = std::max(worst, off[at] * (f.top - f.bottom) / float(kDeviationPixels));
    }
    return worst;
}

ordered_json foliageMaterial(const std::string& name, int texture) {
    return {{"name", name},
            {"pbrMetallicRoughness",
             {{"baseColorTexture", {{"index", texture}}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}},
            {"alphaMode", "MASK"},
            {"alphaCutoff", 0.5},
            {"doubleSided", true},
            {"extras", {{"foliage", true}}}};
}

}  // namespace

PlantModel plantModel(const PlantRecipe& recipe, const PlantTextures& textures,
                      const std::vector<std::uint8_t>& foliagePng, const std::vector<std::uint8_t>& barkPng,
                      bool draco) {
    const PlantMeshes full = buildPlant(recipe, 0), middle = buildPlant(recipe, 1);
    const Frame frame = frameOf(full);
    const engine::assets::RgbaImage atlas = impostorAtlas(full, textures, frame);
    PlantMeshes impostor;
    impostor.cards = impostorCards(frame);

    GlbWriter glb;
    const int foliageTexture =
        glb.addTexture(glb.addPngImage(foliagePng, recipe.fronds ? "frond" : "leaf_cluster"), kClampToEdge);
    const int foliage = glb.addMaterial(foliageMaterial(recipe.fronds ? "fronds" : "leaves", foliageTexture));
    int bark = -1;
    if (full.trunk) {
        const int barkTexture = glb.addTexture(glb.addPngImage(barkPng, "bark"), kRepeat);
        bark = glb.addMaterial(
            {{"name", "bark"},
             {"pbrMetallicRoughness",
              {{"baseColorTexture", {{"index", barkTexture}}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.9}}},
             {"alphaMode", "OPAQUE"}});
    }
    auto addLevel = [&](const std::string& name, const PlantMeshes& meshes, int cardsMaterial) {
        std::vector<GlbWriter::Part> parts;
        if (meshes.trunk) parts.push_back({&*meshes.trunk, bark});
        parts.push_back({&meshes.cards, cardsMaterial});
        const int mesh = glb.addMesh(name, parts, draco);
        return glb.addNode({{"name", name}, {"mesh", mesh}});
    };
    glb.setSceneNodes({addLevel(recipe.name, full, foliage)});
    glb.addScene({addLevel(recipe.name + " middle", middle, foliage)});
    const int atlasTexture = glb.addTexture(glb.addPngImage(encodePng(atlas), "impostor"), kClampToEdge);
    glb.addScene(
        {addLevel(recipe.name + " impostor", impostor, glb.addMaterial(foliageMaterial("impostor", atlasTexture)))});

    // Where each level takes over: while its deviation projects to at most kLodPixelError
    // pixels, i.e. while the plant's height on screen is at most kLodPixelError * height / deviation.
    PlantModel out;
    out.glb = glb.glb();
    out.lod = {{"file", recipe.name + ".glb"},
               {"height", std::round(double(frame.top - frame.bottom) * 1000.0) / 1000.0},
               {"levels", ordered_json::array()}};
    const std::vector<Surface> reference = surfacesOf(full, textures, nullptr);
    float previousBelow = 1e30f;
    for (int level = 1; level <= 2; ++level) {
        const std::vector<Surface> drawn =
            level == 1 ? surfacesOf(middle, textures, nullptr) : surfacesOf(impostor, textures, &atlas);
        const float deviation = levelDeviation(reference, drawn, frame);
        // A coarser level never takes over before a finer one.
        const float below =
            std::min(previousBelow, deviation > 0.0f ? kLodPixelError * (frame.top - frame.bottom) / deviation : 1e6f);
        previousBelow = below;
        out.lod["levels"].push_back({{"scene", level},
                                     {"deviationMetres", std::round(double(deviation) * 1000.0) / 1000.0},
                                     {"belowPixels", std::round(double(below) * 10.0) / 10.0}});
    }
    return out;
}

}  // namespace content
