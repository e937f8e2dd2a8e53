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
// A feature runs its frame one way only, as passes added to the frame graph (addPasses): at
// graph-building time it decides whether there is anything to draw (and computes what it
// will draw); its pass records the backend's work when the graph executes. A feature with
// nothing to draw adds a pass marked empty, which the graph skips (racer --dump-graph shows
// it as such). Tests run it the same way, through a one-off graph.
#include <functional>
#include <string_view>

#include <glm/glm.hpp>

#include "engine/core/ecs/scheduler.hpp"
#include "engine/core/non_copyable.hpp"
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
    // Whether this frame's draws are read with motion vectors (a temporal technique that uses
    // them runs): only then does a feature that moves vertices (the wind) make their motion
    // copies (render::MaskedBatch::motionVertices); without, it computes and uploads none.
    bool motionVectors = false;
};

class Feature : NonCopyable {
public:
    virtual ~Feature() = default;
    // Also the prefix of every pass the feature runs (backend->takeTimings() shows them).
    virtual std::string_view name() const = 0;
    // Adds the feature's systems (e.g. wind into phase::deformation); called once.
    virtual void registerSystems(ecs::Scheduler& /*scheduler*/) {}
    // Before the frame's systems run.
    virtual void beginFrame(const SimulationFrame& /*frame*/) {}
    // Adds the feature's passes onto `frame`'s colour and depth, whose latest versions in
    // `graph` are `targets`; returns the versions it leaves. What a pass needs of `frame` is
    // copied into it. Graph-building time: what to draw is decided here, before any pass runs.
    virtual render::ColorDepth addPasses(render::FrameGraph& graph, const FeatureFrame& frame,
                                         const render::ColorDepth& targets) = 0;

protected:
    // Whether a drawing pass also writes the depth (grass does: later passes see it) or only tests it.
    enum class DepthUse { Test, TestAndWrite };
    // The pass most features add: one named name(), reading the depth (writing it too with
    // TestAndWrite) and drawing onto the colour with `draw(frame)`; marked empty when `empty`
    // (nothing to draw this frame), so the graph skips it.
    render::ColorDepth addDrawPass(render::FrameGraph& graph, const FeatureFrame& frame,
                                   const render::ColorDepth& targets, bool empty, DepthUse depth,
                                   std::function<void(const FeatureFrame&)> draw) const;
};

}  // namespace engine::scene
