// SPDX-License-Identifier: MIT
#pragma once
// A light-shafts test scene on any backend: the camera looks at the sun (straight ahead and
// a little up), a hill at the bottom, and camera-facing cards (opaque or foliage) placed
// around the sun; renders a whole living-scene frame with a sun direction of the test's.
#include <memory>
#include <string>
#include <vector>

#include "engine/render/backend.hpp"
#include "living_frame.hpp"

namespace living::testing {

struct Card {
    float x0, y0, x1, y1, z;
    engine::scene::SurfaceClass surface = engine::scene::SurfaceClass::Mask;
};

// Straight ahead: the sun's pixel is the frame's centre.
inline const glm::vec3 kSunAhead = glm::normalize(glm::vec3(0.0f, 0.15f, 1.0f));

struct ShaftScene {
    static constexpr int kW = 64, kH = 48;
    std::unique_ptr<engine::render::Backend> backend;
    engine::scene::MeshLibrary library{*backend};
    engine::ecs::Registry registry;
    LivingFrame frame{*backend, library, kW, kH};
    Camera camera{{0, 0, 0}, {0.0f, 0.15f, 1.0f}, 1.0f};

    ShaftScene(std::unique_ptr<engine::render::Backend> b, const std::vector<Card>& cards) : backend(std::move(b)) {
        place(registry, addRectangle(library, "hill", -30, -30, 30, -2, 20.0f, engine::scene::SurfaceClass::Opaque,
                                     {0.3f, 0.4f, 0.2f, 1.0f}));
        int n = 0;
        for (const Card& c : cards) {
            const std::string name = "card " + std::to_string(n++);
            place(registry, addRectangle(library, name.c_str(), c.x0, c.y0, c.x1, c.y1, c.z, c.surface,
                                         {0.2f, 0.5f, 0.1f, 1.0f}));
        }
    }

    // One frame with `feature` (or none) seeing the sun towards `towardSun`.
    engine::render::Readback render(engine::scene::Feature* feature, const glm::vec3& towardSun) {
        struct SunOverride final : engine::scene::Feature {
            engine::scene::Feature* inner = nullptr;
            glm::vec3 toward{0.0f};
            std::string_view name() const override { return "sun"; }
            engine::scene::FeatureFrame withSun(const engine::scene::FeatureFrame& f) const {
                engine::scene::FeatureFrame g = f;
                g.sun.towardLight = toward;
                return g;
            }
            engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph,
                                                 const engine::scene::FeatureFrame& f,
                                                 const engine::render::ColorDepth& targets) override {
                return inner->addPasses(graph, withSun(f), targets);
            }
        } wrapper;
        wrapper.inner = feature;
        wrapper.toward = towardSun;
        std::vector<engine::scene::Feature*> features;
        if (feature) features.push_back(&wrapper);
        return frame.render(registry, camera, 0.0f, features);
    }
};

// Foliage over the sun's whole glow (0.3 of the frame height = 14.4 px, and the probe's
// 1 px margin: 31 px across) but not over the frame: sky shows at the sides.
inline std::vector<Card> canopyOverTheSun() { return {{-4.0f, -2.8f, 4.0f, 5.2f, 8.0f}}; }

// The same canopy split by a gap of about one pixel through the sun.
inline std::vector<Card> canopyWithAGap() {
    return {{-4.0f, -2.8f, -0.05f, 5.2f, 8.0f}, {0.14f, -2.8f, 4.0f, 5.2f, 8.0f}};
}

}  // namespace living::testing
