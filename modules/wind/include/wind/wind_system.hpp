// SPDX-License-Identifier: MIT
#pragma once
// WindSystem: the ECS system (phase::deformation) that bends foliage in the wind and pushes
// it out of colliders (the car), every frame.
//
// Work scales with the vertices actually deformed: only a plant (an entity with Sway) that
// is in view and within Wind::activeRadius of the camera or near a Collider gets its own
// copy of its mesh (a VertexOverride, which extraction draws instead of the shared mesh);
// every other plant keeps the shared static mesh and costs nothing. A plant that stops
// being active gives its buffers back and is drawn from the shared mesh again; the buffers
// are kept for the next plant of the same part, so driving along the track creates no
// buffer once as many plants as are ever active at once have been (racer's FramePooling test).
//
// While the frame asks for motion vectors (WindFrame::motionVectors: a temporal technique that
// reads them runs), each deformed part also has a motion copy (VertexOverride::motionBuffers):
// the same vertices with each normal the vertex's previous minus current position, for the
// temporal pass (transparency/temporal.hpp). The previous positions are the part's vertices
// before this frame's deformation (the rest mesh for a plant that just became active, which was
// drawn at rest), kept in a buffer of the part's size that is reused every frame. Without the
// request no motion is computed, uploaded or given a buffer.
//
// Deterministic: the result is a function of the registry, the frame's time and dt, and
// does not depend on the number of threads (plants are deformed independently, oneTBB).
#include <cstdint>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/owned.hpp"
#include "engine/scene/mesh_library.hpp"
#include "wind/sway.hpp"

namespace wind {

// Deformation only where it shows: a plant with a chosen level of detail
// (engine/scene/levels_of_detail.hpp) bends with the wind in full up to kEaseStart of the
// distance where it may leave its full model (LevelsOfDetail::fullDetailUntil, or
// Wind::activeRadius if nearer), then eases to rest (smoothstep) by that distance, so the bend
// is continuous and already zero when the coarser level, which never moves, takes over; such a
// plant costs nothing. A plant without levels (racer --lod off) bends as before, in full up to
// Wind::activeRadius.
inline constexpr float kEaseStart = 0.6f;
// 1 up to kEaseStart * fullDetailUntil, 0 from fullDetailUntil on, smoothstep between.
float restWeight(float distance, float fullDetailUntil);

// Where the frame is seen from, and the simulated clock.
struct WindFrame {
    float time = 0.0f;
    float dt = 0.0f;
    glm::vec3 eye{0.0f};
    glm::mat4 viewProj{1.0f};
    bool hasView = false;        // false: no view-volume culling (everything near counts as visible)
    bool motionVectors = false;  // make the motion copies (scene::SimulationFrame::motionVectors)
};

struct WindStats {
    std::size_t plantsDeformed = 0;    // this update
    std::size_t verticesDeformed = 0;  // this update
    std::size_t motionCopies = 0;      // this update: parts given a motion copy
    // Buffers count a part's pair (its deformed copy and its motion copy) as one; a part's
    // motion buffer is made the first time it is asked for, and travels with its pair.
    std::size_t buffersCreated = 0;   // since construction
    std::size_t buffersReused = 0;    // since construction: a spare of the same part, no create
    std::size_t buffersReleased = 0;  // since construction: given back (kept as spares)
};

class WindSystem {
public:
    explicit WindSystem(const engine::scene::MeshLibrary& library);
    ~WindSystem();
    WindSystem(const WindSystem&) = delete;
    WindSystem& operator=(const WindSystem&) = delete;

    // Gives every Renderable whose model has alpha-tested (foliage) parts a Sway, with a
    // phase and flexibility drawn from the entity's index and `seed` (deterministic).
    // Returns how many were added.
    std::size_t attach(engine::ecs::Registry& registry, std::uint32_t seed = 1) const;

    void setFrame(const WindFrame& frame) { frame_ = frame; }
    // One frame of deformation. Needs exactly one Wind entity (none: every plant goes back
    // to its rest mesh); a bad Wind throws engine::Error naming the field.
    void update(engine::ecs::Registry& registry);
    // Drops every deformed copy (plants are drawn from the shared meshes again).
    void release(engine::ecs::Registry& registry);

    const WindStats& stats() const { return stats_; }
    // The deformed vertices of `e`'s part `i` (index into partsOf(model)), empty when the
    // plant is not deformed; for tests.
    std::span<const engine::render::Vertex> deformed(engine::ecs::Entity e, std::size_t i) const;
    // Its motion copy (deformed(), each normal the previous minus current position), empty
    // without WindFrame::motionVectors; for tests.
    std::span<const engine::render::Vertex> motion(engine::ecs::Entity e, std::size_t i) const;

private:
    // A part's vertex buffers: the deformed copy and its motion copy (null until one is asked for).
    struct PartBuffers {
        engine::render::Owned<engine::render::BufferHandle> vertices;
        engine::render::Owned<engine::render::BufferHandle> motion;
    };
    struct DeformedPart {
        std::size_t slot = 0;    // index into partsOf(model)
        std::uint32_t part = 0;  // library part
        bool flutter = false;    // leaf cards (alpha-tested parts) flutter; trunks only bend
        std::vector<engine::render::Vertex> vertices;
        std::vector<engine::render::Vertex> motion;  // vertices, each normal previous - current; or empty
        std::vector<glm::vec3> push;
        PartBuffers buffers;
        engine::scene::Aabb bounds;
    };
    struct DeformedPlant {
        std::vector<DeformedPart> parts;
        std::size_t slots = 0;  // partsOf(model).size()
    };

    // Part slot `i` of plant `e`, or null when it is not deformed.
    const DeformedPart* partOf(engine::ecs::Entity e, std::size_t i) const;
    void releasePlant(engine::ecs::Registry& registry, engine::ecs::Entity e, DeformedPlant& plant);
    // The buffers for a deformed copy of library part `part`: a spare pair, or a new one.
    PartBuffers partBuffers(std::uint32_t part, std::span<const engine::render::Vertex> vertices);
    // A vertex buffer for library part `part` holding `vertices`, named "<part><what>".
    engine::render::Owned<engine::render::BufferHandle> createBuffer(std::uint32_t part, const char* what,
                                                                     std::span<const engine::render::Vertex> vertices);
    void destroySpares();

    const engine::scene::MeshLibrary& library_;
    WindFrame frame_;
    WindStats stats_;
    std::map<engine::ecs::Entity, DeformedPlant> plants_;       // ordered: deterministic walks
    std::map<std::uint32_t, std::vector<PartBuffers>> spares_;  // by library part
};

}  // namespace wind
