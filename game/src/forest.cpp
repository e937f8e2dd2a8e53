// SPDX-License-Identifier: MIT
#include "forest.hpp"

#include <cmath>
#include <numbers>

#include "content_files.hpp"

namespace racer {

namespace {

using engine::scene::ModelId;

// Clearings, as fractions of the lap: the rest is woodland. The lap's first quarter (where
// the demo's chase camera drives) is woodland all through.
constexpr float kClearings[][2] = {{0.28f, 0.36f}, {0.52f, 0.58f}, {0.76f, 0.82f}};

glm::vec3 sideOf(const Track& track, float distance) {
    return glm::normalize(glm::cross(track.forward(distance), glm::vec3(0.0f, 1.0f, 0.0f)));
}

}  // namespace

bool inWoodland(const Track& track, float distance) {
    float f = std::fmod(distance / track.length(), 1.0f);
    if (f < 0.0f) f += 1.0f;
    for (const auto& c : kClearings)
        if (f >= c[0] && f < c[1]) return false;
    return true;
}

void plantForest(engine::ecs::Registry& registry, const Track& track, const Ground& ground,
                 const std::vector<ModelId>& trees, const std::vector<ModelId>& bushes, Random& random,
                 const ForestOptions& options) {
    // Each draw from `random` is sequenced on its own: C++ leaves the evaluation order of a
    // call's arguments (and of most operators' operands) unspecified, GCC goes right to left
    // and Clang left to right, so two draws in one expression grow a different forest per
    // compiler.
    const ModelId broadleaf = trees.at(0), tall = trees.at(trees.size() - 1), palm = trees.at(trees.size() / 2);
    const float edge = 0.5f * track.width() + Track::kShoulderWidth;  // where the shoulder meets the verge
    auto plant = [&](ModelId model, const glm::vec3& where, float heading, float scale) {
        glm::vec3 p = where;
        p.y = ground.height(p.x, p.z);
        placeModel(registry, model, p, heading, scale);
    };
    // Beside the road at `distance`, `offset` metres from the centre on side -1 or +1, unless a
    // bend brings another stretch of road nearer than `offset` allows.
    auto besideRoad = [&](float distance, int side, float offset, glm::vec3& out) {
        out = track.position(distance) + sideOf(track, distance) * (float(side) * offset);
        return track.nearest(out).offset >= std::min(offset, edge + 0.3f) - 0.01f;
    };

    // The tree line on both sides: every few metres through the woodland, the trunk just past
    // the shoulder; one in four a big broadleaf whose crown reaches out over the asphalt.
    for (int side = -1; side <= 1; side += 2) {
        for (float d = 0.0f; d < track.length();) {
            const float step = options.treeSpacing * random.uniform(0.7f, 1.3f);
            const float roll = random.uniform(0.0f, 1.0f);
            const float out = random.uniform(0.3f, 2.8f);
            const float heading = random.uniform(0.0f, 6.2832f);
            const float size = random.uniform(0.0f, 1.0f);
            glm::vec3 p;
            if (inWoodland(track, d)) {
                if (roll < 0.25f) {
                    if (besideRoad(d, side, edge + 0.3f + 0.2f * out, p))
                        plant(broadleaf, p, heading, 1.7f + 0.4f * size);
                } else if (besideRoad(d, side, edge + out, p)) {
                    plant(roll < 0.65f ? broadleaf : tall, p, heading, 0.9f + 0.5f * size);
                }
            }
            d += step;
        }
    }
    // Bushes on the verges, all round the lap (sparser in the clearings).
    for (int side = -1; side <= 1; side += 2) {
        for (float d = 0.0f; d < track.length();) {
            const float step = options.bushSpacing * random.uniform(0.6f, 1.4f);
            const float keep = random.uniform(0.0f, 1.0f);
            const std::uint32_t which = random.next();
            const float out = random.uniform(0.2f, 3.5f);
            const float heading = random.uniform(0.0f, 6.2832f);
            const float scale = random.uniform(0.7f, 1.3f);
            glm::vec3 p;
            if ((inWoodland(track, d) || keep < 0.35f) && besideRoad(d, side, edge + out, p))
                plant(bushes[which % bushes.size()], p, heading, scale);
            d += step;
        }
    }
    // The woods behind the tree line: trees and undergrowth 11 to 45 m out.
    for (int i = 0; i < options.backRowTrees; ++i) {
        const float d = random.uniform(0.0f, track.length());
        const int side = random.next() & 1 ? 1 : -1;
        const float offset = random.uniform(11.0f, 45.0f);
        const float kind = random.uniform(0.0f, 1.0f);
        const float heading = random.uniform(0.0f, 6.2832f);
        const float scale = random.uniform(0.9f, 1.5f);
        glm::vec3 p;
        if (!inWoodland(track, d) || !besideRoad(d, side, offset, p)) continue;
        const ModelId model = kind < 0.45f   ? broadleaf
                              : kind < 0.8f  ? tall
                              : kind < 0.85f ? palm
                                             : bushes[i % bushes.size()];
        plant(model, p, heading, scale);
    }
    // A grove across the track from the start line, where the pre-race pan camera looks:
    // overlapping trees close up, the case where alpha testing sparkles ([Hathaway 2010] §3.4).
    {
        const glm::vec3 start = track.position(0.0f), f = track.forward(0.0f), side = sideOf(track, 0.0f);
        for (int i = 0; i < options.groveTrees; ++i) {
            const float along = random.uniform(-30.0f, 30.0f);
            const float across = random.uniform(track.width() * 0.5f + 6.0f, 40.0f);
            const bool tree = (random.next() % 3) != 0;
            const auto& models = tree ? trees : bushes;
            const float scale = random.uniform(0.9f, 1.4f), heading = random.uniform(0.0f, 6.2832f);
            plant(models[random.next() % models.size()], start + side * across + f * along, heading, scale);
        }
    }
    // The vista: trees over the hills beyond the track, out to a few kilometres (§3.1).
    for (int i = 0; i < options.vistaTrees; ++i) {
        const float angle = random.uniform(0.0f, 2.0f * std::numbers::pi_v<float>);
        const float radius = random.uniform(480.0f, 1900.0f);
        const float scale = random.uniform(1.6f, 2.6f), heading = random.uniform(0.0f, 6.2832f);
        const std::uint32_t which = random.next();
        plant(which % 3 == 2 ? tall : broadleaf, glm::vec3(radius * std::cos(angle), 0.0f, radius * std::sin(angle)),
              heading, scale);
    }
}

}  // namespace racer
