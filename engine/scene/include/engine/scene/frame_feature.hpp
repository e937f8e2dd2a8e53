// SPDX-License-Identifier: MIT
#pragma once
// A pluggable feature of the living scene (modules/wind, water, grass, particles,
// lightshafts): systems registered into the scheduler's phases, and passes drawn after the
// foliage technique. The game keeps an ordered list of the enabled features and lets each,
// in that order, add its passes to the frame graph: opaque -> foliage technique (SSAM's
// colour pass writes foliage depth into the opaque depth target) -> grass -> water ->
// particles -> light shafts -> present. Everything a pass depth-tests against is `depth`,
// the opaque + foliage depth, so foliage correctly hides what is behind it
// ([Hathaway 2010] §3.7).
//
// A feature splits its frame in two: prepare() at graph-building time decides whether
// there is anything to draw (and computes what it will draw), draw() records the backend
// passes when the graph executes. A feature with nothing to draw adds a pass marked empty,
// which the graph skips (racer --dump-graph shows it as such).
#include <string_view>

#include <glm/glm.hpp>

#include "engine/core/ecs/scheduler.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/compare_func.hpp"
#include "engine/render/frame_graph/color_depth.hpp"
#include "engine/render/program.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/mesh_library.hpp"

namespace engine::render {
class FrameGraph;
}

namespace engine::scene {

struct FeatureFrame {
    render::Backend& backend;
    const MeshLibrary& library;
    const DrawLists& lists;       // this frame's extraction (water draws lists.blend)
    render::TextureHandle color;  // the frame so far (imported in the graph); passes load and draw onto it
    render::TextureHandle depth;  // D32F opaque + foliage depth; load, test, never clear
    int width = 0;
    int height = 0;
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    render::DirectionalLight sun;
    float time = 0.0f;                                          // simulated seconds (deterministic under --fixed-dt)
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
    // Whether there is anything to draw this frame, with what will be drawn computed now
    // (visible instances, geometry); at graph-building time, before any pass runs.
    virtual bool prepare(const FeatureFrame& /*frame*/) { return false; }
    // The backend passes for what prepare() found, onto frame.color and frame.depth.
    virtual void draw(const FeatureFrame& /*frame*/) {}

    // Whether draw() writes the depth too (grass does: later passes see it), not only tests it.
    virtual bool writesDepth() const { return false; }

    // Adds one pass named name() that reads the depth and draws onto the colour (`frame`'s
    // textures, whose latest versions in `graph` are `targets`), empty when prepare() finds
    // nothing. Returns the versions it leaves. `frame` is copied into the pass.
    virtual render::ColorDepth addPasses(render::FrameGraph& graph, const FeatureFrame& frame,
                                         const render::ColorDepth& targets);
    // Without a graph: prepare(), then draw() when there is something to draw.
    void render(const FeatureFrame& frame) {
        if (prepare(frame)) draw(frame);
    }
};

}  // namespace engine::scene
