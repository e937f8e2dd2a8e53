// SPDX-License-Identifier: MIT
#pragma once
// A pluggable feature of the living scene (modules/wind, water, grass, particles,
// lightshafts): systems registered into the scheduler's phases, and passes drawn after the
// foliage technique. The game keeps an ordered list of the enabled features and calls
// render() on each in that order: opaque -> foliage technique (SSAM's colour pass writes
// foliage depth into the opaque depth target) -> grass -> water -> particles -> light
// shafts -> present. Everything a pass depth-tests against is `depth`, the opaque + foliage
// depth, so foliage correctly hides what is behind it ([Hathaway 2010] §3.7).
#include <string_view>

#include <glm/glm.hpp>

#include "engine/core/ecs/scheduler.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/compare_func.hpp"
#include "engine/render/program.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/mesh_library.hpp"

namespace engine::scene {

struct FeatureFrame {
    render::Backend& backend;
    const MeshLibrary& library;
    const DrawLists& lists;      // this frame's extraction (water draws lists.blend)
    render::TextureHandle color; // the frame so far; passes load and draw onto it
    render::TextureHandle depth; // D32F opaque + foliage depth; load, test, never clear
    int width = 0;
    int height = 0;
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    render::DirectionalLight sun;
    float time = 0.0f;  // simulated seconds (deterministic under --fixed-dt)
    render::CompareFunc depthFunc = render::CompareFunc::Less;  // Greater for reverse-Z
};

// The simulated clock and the camera, given to every feature before the scheduler runs
// the frame's systems (the camera is known first, so culling needs no previous frame).
struct SimulationFrame {
    float time = 0.0f;  // seconds since the start
    float dt = 0.0f;    // this step
    glm::vec3 eye{0.0f};
    glm::mat4 viewProj{1.0f};
};

class Feature {
public:
    virtual ~Feature() = default;
    // Also the prefix of every pass the feature runs (backend->takeTimings() shows them).
    virtual std::string_view name() const = 0;
    // Adds the feature's systems (e.g. wind into phase::deformation); called once.
    virtual void registerSystems(ecs::Scheduler& /*scheduler*/) {}
    // Before the frame's systems run.
    virtual void beginFrame(const SimulationFrame& /*frame*/) {}
    // The feature's passes for one frame; runs nothing when it has nothing to draw.
    virtual void render(const FeatureFrame& /*frame*/) {}
};

}  // namespace engine::scene
