// SPDX-License-Identifier: MIT
// modules/particles: the premultiplied layer ([Turánszki 2017]), soft particles against the
// opaque + foliage depth ([Hathaway 2010] §3.7), the half-resolution upsample without halos,
// caps and bad input, determinism.
#include <gtest/gtest.h>

#include "engine/core/ecs/scheduler.hpp"
#include "engine/core/error.hpp"
#include "living_frame.hpp"
#include "particles/particle_feature.hpp"

namespace {

using namespace engine;

constexpr int kW = 64, kH = 48;

struct ParticleScene : living::testing::LivingScene {
    explicit ParticleScene(bool tree, float treeRight = 1.0f) : LivingScene(kW, kH) {
        // A full-alpha foliage card 5 m ahead: the left part of the view.
        if (tree) addCard("tree", -4, -3, treeRight, 3, 5.0f, scene::SurfaceClass::Mask, {0.2f, 0.5f, 0.1f, 1.0f});
    }
};

particles::Particle puff(glm::vec3 at, glm::vec4 color = {1.0f, 0.2f, 0.1f, 0.9f}, float additive = 0.0f) {
    particles::Particle p;
    p.position = at;
    p.color = color;
    p.additive = additive;
    return p;
}

particles::ParticleOptions options(bool half) {
    particles::ParticleOptions o;
    o.startSize = o.endSize = 1.2f;
    o.softness = 0.25f;
    o.halfResolution = half;
    return o;
}

TEST(Particles, BehindTheTreeHiddenInFrontVisible) {
    for (bool half : {false, true}) {
        ParticleScene bare(false), tree(true);
        const render::Readback treeOnly = tree.render(nullptr);
        particles::ParticleFeature behindOpen(*bare.backend, options(half));
        behindOpen.simulation().emit(puff({-0.5f, 0.0f, 9.0f}));
        EXPECT_NE(bare.render(&behindOpen).values, bare.render(nullptr).values) << "not in view at all, half " << half;

        particles::ParticleFeature behind(*tree.backend, options(half));
        behind.simulation().emit(puff({-0.5f, 0.0f, 9.0f}));
        EXPECT_EQ(tree.render(&behind).values, treeOnly.values) << "dust behind the tree shows through, half " << half;

        ParticleScene tree2(true);
        particles::ParticleFeature front(*tree2.backend, options(half));
        front.simulation().emit(puff({-0.5f, 0.0f, 3.0f}));
        EXPECT_NE(tree2.render(&front).values, treeOnly.values) << "dust in front is missing, half " << half;
    }
}

TEST(Particles, HalfResolutionLayerLeavesNoHaloOnFoliageEdges) {
    // The tree's right edge crosses the view; a large puff behind it straddles the edge. The
    // half-size layer takes each 2x2 block's closest depth, so a layer texel on the edge
    // counts as "tree" and holds no dust: upsampled by plain nearest or bilinear filtering,
    // sky pixels along the edge would lose their dust (a halo of bare sky round the tree)
    // or tree pixels would get it. The nearest-depth upsample does neither.
    for (float edge : {0.37f, 0.41f, 0.55f, 0.6f}) {
        ParticleScene tree(true, edge);
        const render::Readback treeOnly = tree.render(nullptr);
        auto withDust = [&](bool half) {
            particles::ParticleOptions o = options(half);
            o.startSize = o.endSize = 3.0f;
            particles::ParticleFeature dust(*tree.backend, o);
            dust.simulation().emit(puff({1.0f, 0.0f, 9.0f}));
            return tree.render(&dust);
        };
        const render::Readback full = withDust(false), half = withDust(true);
        int treePixelsChanged = 0, holes = 0, dusted = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                auto differs = [&](const render::Readback& r, float by) {
                    for (int c = 0; c < 3; ++c)
                        if (std::abs(r.at(x, y, c) - treeOnly.at(x, y, c)) > by) return true;
                    return false;
                };
                const bool isTree = treeOnly.at(x, y, 2) < 0.3f;  // the card, not the sky
                treePixelsChanged += isTree && differs(half, 0.0f);
                if (!isTree && differs(full, 0.1f)) {
                    ++dusted;
                    holes += !differs(half, 0.02f);
                }
            }
        EXPECT_GT(dusted, 50) << "edge " << edge;
        EXPECT_EQ(treePixelsChanged, 0) << "dust on the tree at edge " << edge;
        EXPECT_EQ(holes, 0) << "bare-sky halo along the tree at edge " << edge;
    }
}

TEST(Particles, PremultipliedLayerAccumulatesAlphaAndSharesAdditive) {
    ParticleScene s(false);
    particles::ParticleOptions o = options(false);
    o.softness = 1000.0f;  // far sky: fade 1
    particles::ParticleFeature f(*s.backend, o);
    // Two overlapping dust puffs of alpha 0.5 and one additive spray in the same layer.
    f.simulation().emit(puff({0.0f, 0.0f, 6.0f}, {1.0f, 0.0f, 0.0f, 0.5f}));
    f.simulation().emit(puff({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 1.0f, 0.5f}));
    f.simulation().emit(puff({0.0f, 0.0f, 4.0f}, {0.0f, 1.0f, 0.0f, 0.5f}, 1.0f));
    s.frame.readBackAfterFeatures = [&f] { return std::vector{f.graphLayer()}; };
    s.render(&f);
    ASSERT_EQ(s.frame.readBacks.size(), 1u);
    const render::Readback layer = s.frame.readBacks[0];
    // Centre of the quads (shape 1): a = 0.5 + 0.5 * (1 - 0.5) = 0.75 ([Turánszki 2017]), the
    // additive spray adds green without touching alpha.
    const int x = kW / 2, y = kH / 2;
    EXPECT_NEAR(layer.at(x, y, 3), 0.75f, 0.01f);
    EXPECT_NEAR(layer.at(x, y, 0), 0.25f, 0.02f);  // red 0.5, then * (1 - 0.5)
    EXPECT_NEAR(layer.at(x, y, 2), 0.5f, 0.02f);   // blue 0.5
    EXPECT_NEAR(layer.at(x, y, 1), 0.5f, 0.02f);   // green 0.5, additive
}

TEST(Particles, OffOrNothingAliveMeansNoPass) {
    ParticleScene s(true);
    s.backend->takeTimings();
    particles::ParticleFeature f(*s.backend, options(true));
    s.render(&f);  // no particle alive
    s.render(nullptr);
    for (const auto& t : s.backend->takeTimings()) EXPECT_EQ(t.pass.find("particles"), std::string::npos);
    f.simulation().emit(puff({0.0f, 0.0f, 3.0f}));
    s.render(&f);
    int passes = 0;
    for (const auto& t : s.backend->takeTimings()) passes += t.pass.find("particles") != std::string::npos;
    EXPECT_EQ(passes, 2);  // the layer and its composite
}

TEST(Particles, CapsAndBadInput) {
    particles::ParticleOptions o;
    o.maxParticles = 1'000'001;
    try {
        particles::ParticleSimulation s(o);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("exceeds the limit of 1000000"), std::string::npos);
    }
    o = {};
    o.startSize = 0.0f;
    EXPECT_THROW(particles::ParticleSimulation{o}, Error);
    o = {};
    o.endSize = -1.0f;
    EXPECT_THROW(particles::ParticleSimulation{o}, Error);
    o = {};
    o.lifetime = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(particles::ParticleSimulation{o}, Error);
    o = {};
    o.maxParticles = 0;  // allowed: nothing ever spawns
    particles::ParticleSimulation none(o);
    EXPECT_FALSE(none.emit(puff({0, 0, 0})));

    o = {};
    o.maxParticles = 100;
    particles::ParticleSimulation sim(o);
    ecs::Registry registry;
    const ecs::Entity car = registry.create();
    registry.add<scene::Transform>(car);
    registry.add<particles::WheelEmitter>(car);  // 400 per second
    sim.update(registry, 1.0f);
    EXPECT_EQ(sim.particles().size(), 100u);
    EXPECT_GT(sim.refused(), 0u);
    EXPECT_THROW(sim.update(registry, -1.0f), Error);
    EXPECT_THROW(sim.update(registry, std::numeric_limits<float>::infinity()), Error);
    registry.get<particles::WheelEmitter>(car).rate = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(sim.update(registry, 0.1f), Error);
    o = {};
    o.thinning = 0.0f;
    EXPECT_THROW(particles::ParticleSimulation{o}, Error);
}

// Dust is thick at the wheels and thins along its trail (so the chase camera sees the
// car, not a wall of dust): opacity falls by 1/e per `thinning` metres travelled, on top of the
// fade with age. A car driving at 28 m/s for a second: the particles within 2 m of a wheel are
// several times as opaque as those over 6 m behind.
TEST(Particles, DustThinsWithDistanceFromTheWheels) {
    particles::ParticleOptions o;
    particles::ParticleSimulation sim(o);
    particles::Particle p = puff({0.0f, 0.0f, 0.0f});
    EXPECT_FLOAT_EQ(sim.opacityOf(p), 1.0f);  // emitted directly: nothing travelled yet
    p.travelled = o.thinning;
    EXPECT_NEAR(sim.opacityOf(p), std::exp(-1.0f), 1e-6f);
    p.age = 0.5f * o.lifetime;
    EXPECT_NEAR(sim.opacityOf(p), 0.5f * std::exp(-1.0f), 1e-6f);

    ecs::Registry registry;
    const ecs::Entity car = registry.create();
    registry.add<scene::Transform>(car);
    const particles::WheelEmitter& emitter = registry.add<particles::WheelEmitter>(car);
    const float dt = 1.0f / 30.0f;
    for (int i = 0; i < 30; ++i) {
        registry.get<scene::Transform>(car).position.z += 28.0f * dt;
        sim.update(registry, dt);
    }
    const glm::mat4 m = registry.get<scene::Transform>(car).matrix();
    double nearSum = 0.0, farSum = 0.0;
    int nearCount = 0, farCount = 0;
    for (const particles::Particle& q : sim.particles()) {
        float fromWheels = 1e30f;
        for (const glm::vec3& w : emitter.wheels)
            fromWheels = std::min(fromWheels, glm::length(q.position - glm::vec3(m * glm::vec4(w, 1.0f))));
        if (fromWheels < 2.0f) nearSum += sim.opacityOf(q), ++nearCount;
        if (fromWheels > 6.0f) farSum += sim.opacityOf(q), ++farCount;
    }
    ASSERT_GT(nearCount, 20);
    ASSERT_GT(farCount, 20);
    EXPECT_GT(nearSum / nearCount, 4.0 * (farSum / farCount))
        << "near the wheels " << nearSum / nearCount << ", over 6 m behind " << farSum / farCount;
}

TEST(Particles, DeterministicAndNeverNaN) {
    auto run = [] {
        ecs::Registry registry;
        const ecs::Entity car = registry.create();
        registry.add<scene::Transform>(car, scene::Transform{{0.0f, 0.0f, 8.0f}});
        registry.add<particles::WheelEmitter>(car);
        ParticleScene s(true);
        particles::ParticleFeature f(*s.backend, particles::ParticleOptions{}, 5);
        ecs::Scheduler scheduler;
        f.registerSystems(scheduler);
        for (int i = 0; i < 20; ++i) {
            f.beginFrame({i / 30.0f, 1.0f / 30.0f, glm::vec3(0.0f), glm::mat4(1.0f)});
            scheduler.run(registry);
            registry.get<scene::Transform>(car).position.x += 0.3f;
        }
        EXPECT_GT(f.simulation().particles().size(), 0u);
        return s.render(&f);
    };
    const render::Readback a = run(), b = run();
    EXPECT_EQ(a.values, b.values);
    for (float v : a.values) EXPECT_TRUE(std::isfinite(v));
}

}  // namespace
