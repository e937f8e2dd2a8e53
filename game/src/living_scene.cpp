// SPDX-License-Identifier: MIT
#include "living_scene.hpp"

#include "ground.hpp"
#include "track.hpp"

#if SSAM_HAS_WIND
#include "wind/wind_feature.hpp"
#endif
#if SSAM_HAS_GRASS
#include "grass/grass_feature.hpp"
#endif
#if SSAM_HAS_WATER
#include "water/water_feature.hpp"
#endif
#if SSAM_HAS_LIGHTSHAFTS
#include "lightshafts/light_shaft_feature.hpp"
#endif
#if SSAM_HAS_PARTICLES
#include "engine/scene/components.hpp"
#include "particles/particle_feature.hpp"
#endif

namespace racer {

#if SSAM_HAS_GRASS
namespace {
// Tufts in a band on both sides of the track, clear of the road, every ~0.8 m along it, on
// the racing scene's ground (the same function of the track the scene builds).
std::vector<grass::Tuft> tuftsAlong(const Track& track, std::uint32_t seed) {
    const Ground ground(track);
    Random random(seed * 31u + 7u);
    std::vector<grass::Tuft> tufts;
    for (float d = 0.0f; d < track.length(); d += 0.8f) {
        const glm::vec3 p = track.position(d), f = track.forward(d);
        const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        for (int row = 0; row < 6; ++row) {
            const float offset = track.width() * 0.5f + Track::kShoulderWidth + 0.3f + float(row) * 1.6f + random.uniform(0.0f, 1.2f);
            glm::vec3 q = p + side * (row % 2 ? offset : -offset) + f * random.uniform(-0.4f, 0.4f);
            q.y = ground.height(q.x, q.z);
            tufts.push_back({q, random.uniform(0.0f, 6.2832f), random.uniform(0.7f, 1.3f)});
        }
    }
    return tufts;
}
}  // namespace
#endif

LivingScene::LivingScene(engine::ecs::Registry& registry, const engine::scene::MeshLibrary& library,
                         const LivingSceneOptions& options)
    : registry_(registry) {
    // Frame order (issue #8): wind (systems only), grass, water, particles, light shafts.
    if (options.wind) {
#if SSAM_HAS_WIND
        features_.push_back(std::make_unique<wind::WindFeature>(registry, library, options.seed));
#else
        missing_.push_back("wind");
#endif
    }
    if (options.grass) {
#if SSAM_HAS_GRASS
        if (options.track)
            features_.push_back(
                std::make_unique<grass::GrassFeature>(library.backend(), tuftsAlong(*options.track, options.seed)));
#else
        missing_.push_back("grass");
#endif
    }
    if (options.water) {
#if SSAM_HAS_WATER
        features_.push_back(std::make_unique<water::WaterFeature>(library));
#else
        missing_.push_back("water");
#endif
    }
    if (options.particles) {
#if SSAM_HAS_PARTICLES
        // Dust and spray from the wheels of whatever collides (the car).
        std::vector<engine::ecs::Entity> cars;
        registry.view<const engine::scene::Collider>().each(
            [&](engine::ecs::Entity e, const engine::scene::Collider&) { cars.push_back(e); });
        for (engine::ecs::Entity e : cars)
            if (!registry.has<particles::WheelEmitter>(e)) registry.add<particles::WheelEmitter>(e);
        features_.push_back(std::make_unique<particles::ParticleFeature>(library.backend(), particles::ParticleOptions{},
                                                                         options.seed));
#else
        missing_.push_back("particles");
#endif
    }
    if (options.lightshafts) {
#if SSAM_HAS_LIGHTSHAFTS
        features_.push_back(std::make_unique<lightshafts::LightShaftFeature>(library.backend()));
#else
        missing_.push_back("lightshafts");
#endif
    }
    (void)library;
    for (const auto& f : features_) f->registerSystems(scheduler_);
}

LivingScene::~LivingScene() = default;

void LivingScene::update(float time, float dt, const CameraView& camera) {
    time_ = time;
    for (const auto& f : features_) f->beginFrame({time, dt, camera.eye, camera.viewProj});
    scheduler_.run(registry_);
}

engine::render::ColorDepth LivingScene::addPasses(engine::render::FrameGraph& graph,
                                                  const engine::scene::FeatureFrame& frame,
                                                  engine::render::ColorDepth targets) {
    engine::scene::FeatureFrame timed = frame;
    timed.time = time_;
    for (const auto& f : features_) targets = f->addPasses(graph, timed, targets);
    return targets;
}

std::vector<std::string> LivingScene::names() const {
    std::vector<std::string> out;
    for (const auto& f : features_) out.emplace_back(f->name());
    return out;
}

}  // namespace racer
