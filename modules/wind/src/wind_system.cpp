// SPDX-License-Identifier: MIT
#include "wind/wind_system.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/error.hpp"
#include "engine/core/parallel_for.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/levels_of_detail.hpp"

namespace wind {

using namespace engine;
using engine::render::Vertex;
using engine::scene::Aabb;

namespace {

bool hasFoliage(const scene::MeshLibrary& library, scene::ModelId model) {
    for (std::uint32_t p : library.partsOf(model))
        if (library.part(p).material.surface == scene::SurfaceClass::Mask) return true;
    return false;
}

float distanceToBox(const glm::vec3& p, const Aabb& box) {
    const glm::vec3 d = glm::max(glm::max(box.min - p, p - box.max), glm::vec3(0.0f));
    return glm::length(d);
}

// A well-mixed 32-bit hash (splitmix-style finaliser) for per-plant variety.
std::uint32_t mix(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

}  // namespace

float restWeight(float distance, float fullDetailUntil) {
    const float end = fullDetailUntil, start = kEaseStart * fullDetailUntil;
    if (!(distance > start)) return 1.0f;
    if (!(distance < end)) return 0.0f;
    const float t = (end - distance) / (end - start);
    return t * t * (3.0f - 2.0f * t);  // smoothstep: no jump in the bend nor in its speed
}

WindSystem::WindSystem(const scene::MeshLibrary& library) : library_(library) {}

WindSystem::~WindSystem() {
    // In the order they were always destroyed: plant by plant, then the spares.
    for (auto& [e, plant] : plants_) plant.parts.clear();
    destroySpares();
}

void WindSystem::destroySpares() {
    for (auto& [part, buffers] : spares_) buffers.clear();
    spares_.clear();
}

WindSystem::PartBuffers WindSystem::partBuffers(std::uint32_t part, std::span<const Vertex> vertices) {
    const auto bytes = std::as_bytes(vertices);
    std::vector<PartBuffers>& spare = spares_[part];
    if (!spare.empty()) {
        library_.backend().updateBuffer(spare.back().vertices, 0, bytes);
        PartBuffers b = std::move(spare.back());
        spare.pop_back();
        ++stats_.buffersReused;
        return b;
    }
    PartBuffers b{createBuffer(part, " (deformed)", vertices), {}};
    ++stats_.buffersCreated;
    return b;
}

render::Owned<render::BufferHandle> WindSystem::createBuffer(std::uint32_t part, const char* what,
                                                             std::span<const Vertex> vertices) {
    const auto bytes = std::as_bytes(vertices);
    return render::Owned<render::BufferHandle>(
        library_.backend(), library_.backend().createBuffer(
                                {library_.part(part).name + what, render::BufferKind::Vertex, bytes.size()}, bytes));
}

std::size_t WindSystem::attach(ecs::Registry& registry, std::uint32_t seed) const {
    std::vector<ecs::Entity> foliage;
    registry.view<const scene::Renderable>().each([&](ecs::Entity e, const scene::Renderable& r) {
        if (!registry.has<Sway>(e) && hasFoliage(library_, r.model)) foliage.push_back(e);
    });
    for (ecs::Entity e : foliage) {
        const std::uint32_t h = mix(e.index() * 0x9E3779B9u ^ seed);
        const float phase = float(h & 0xFFFF) / 65536.0f * 2.0f * std::numbers::pi_v<float>;
        const float flexibility = 0.6f + 0.4f * float(h >> 16) / 65536.0f;
        registry.add<Sway>(e, Sway{flexibility, phase});
    }
    return foliage.size();
}

const WindSystem::DeformedPart* WindSystem::partOf(ecs::Entity e, std::size_t i) const {
    const auto it = plants_.find(e);
    if (it == plants_.end()) return nullptr;
    for (const DeformedPart& p : it->second.parts)
        if (p.slot == i) return &p;
    return nullptr;
}

std::span<const Vertex> WindSystem::deformed(ecs::Entity e, std::size_t i) const {
    const DeformedPart* p = partOf(e, i);
    return p ? std::span<const Vertex>(p->vertices) : std::span<const Vertex>();
}

std::span<const Vertex> WindSystem::motion(ecs::Entity e, std::size_t i) const {
    const DeformedPart* p = partOf(e, i);
    return p ? std::span<const Vertex>(p->motion) : std::span<const Vertex>();
}

void WindSystem::releasePlant(ecs::Registry& registry, ecs::Entity e, DeformedPlant& plant) {
    for (DeformedPart& p : plant.parts) {
        spares_[p.part].push_back(std::move(p.buffers));
        ++stats_.buffersReleased;
    }
    plant.parts.clear();
    if (registry.alive(e) && registry.has<scene::VertexOverride>(e)) registry.remove<scene::VertexOverride>(e);
}

void WindSystem::release(ecs::Registry& registry) {
    for (auto& [e, plant] : plants_) releasePlant(registry, e, plant);
    plants_.clear();
    destroySpares();  // no wind: nothing will be deformed again soon
}

void WindSystem::update(ecs::Registry& registry) {
    stats_.plantsDeformed = stats_.verticesDeformed = stats_.motionCopies = 0;
    const Wind* wind = nullptr;
    std::size_t winds = 0;
    registry.view<const Wind>().each([&](const Wind& w) {
        wind = &w;
        ++winds;
    });
    if (winds > 1) throw Error("wind: " + std::to_string(winds) + " entities have a Wind; exactly one may");
    if (!wind) {
        release(registry);
        return;
    }
    validate(*wind);
    if (!std::isfinite(frame_.time) || !std::isfinite(frame_.dt) || frame_.dt < 0.0f)
        throw Error("wind: frame time " + std::to_string(frame_.time) + " / dt " + std::to_string(frame_.dt) +
                    " must be finite with dt >= 0");

    std::vector<SphereCollider> colliders;
    registry.view<const scene::Transform, const scene::Collider>().each(
        [&](const scene::Transform& t, const scene::Collider& c) {
            if (std::isfinite(c.radius) && c.radius > 0.0f) colliders.push_back({t.position, c.radius});
        });

    // Which plants deform this frame: in view, and near the camera or a collider. The box
    // is widened by how far the wind can move a vertex, so nothing pops at the edges.
    struct Active {
        ecs::Entity entity;
        scene::ModelId model;
        PlantPose pose;
    };
    std::vector<Active> active;
    const float reach = wind->strength * (1.0f + wind->gustStrength + 0.25f) + wind->flutterAmplitude;
    registry.view<const scene::Transform, const scene::Renderable, const Sway>().each(
        [&](ecs::Entity e, const scene::Transform& t, const scene::Renderable& r, const Sway& s) {
            if (registry.has<scene::Collider>(e)) return;
            const Aabb local = library_.bounds(r.model);
            if (local.empty()) return;
            const glm::mat4 model = t.matrix();
            Aabb box = local.transformed(model);
            box.min -= glm::vec3(reach);
            box.max += glm::vec3(reach);
            if (frame_.hasView && !scene::intersectsViewVolume(box, frame_.viewProj)) return;
            const float distance = distanceToBox(frame_.eye, box);
            // A plant with a chosen level of detail: the wind eases out before it may leave its
            // full model, and a coarser level does not move at all.
            const scene::LevelsOfDetail* lod = registry.tryGet<scene::LevelsOfDetail>(e);
            const bool levelled = lod && lod->chosen;
            // Measured as the selection measures it: from the eye to the model's bounds centre.
            const float centreDistance =
                levelled ? glm::length(glm::vec3(model * glm::vec4((local.min + local.max) * 0.5f, 1.0f)) - frame_.eye)
                         : 0.0f;
            const float weight =
                levelled
                    ? (lod->level > 0 ? 0.0f
                                      : restWeight(centreDistance, std::min(wind->activeRadius, lod->fullDetailUntil)))
                    : 1.0f;
            bool near = distance <= wind->activeRadius && weight > 0.0f;
            const bool drawnFull = !levelled || lod->level == 0;
            for (const SphereCollider& c : colliders)
                near = near || (drawnFull && distanceToBox(c.center, box) <= c.radius + wind->colliderMargin);
            if (!near) return;
            PlantPose pose;
            pose.model = model;
            pose.inverseModel = glm::inverse(model);
            pose.baseY = local.min.y;
            pose.height = local.max.y - local.min.y;
            pose.sway = {std::clamp(std::isfinite(s.flexibility) ? s.flexibility : 0.0f, 0.0f, 1.0f),
                         std::isfinite(s.phase) ? s.phase : 0.0f};
            pose.weight = weight;
            active.push_back({e, r.model, pose});
        });
    std::sort(active.begin(), active.end(), [](const Active& a, const Active& b) { return a.entity < b.entity; });

    // Plants no longer active (or destroyed) go back to the shared mesh.
    for (auto it = plants_.begin(); it != plants_.end();) {
        const bool keep = std::binary_search(active.begin(), active.end(), Active{it->first, 0, {}},
                                             [](const Active& a, const Active& b) { return a.entity < b.entity; });
        if (keep) {
            ++it;
        } else {
            releasePlant(registry, it->first, it->second);
            it = plants_.erase(it);
        }
    }

    // Newly active plants get their own copy of every deformable part.
    struct Job {
        DeformedPart* part;
        const PlantPose* pose;
    };
    std::vector<Job> jobs;
    for (const Active& a : active) {
        auto [it, fresh] = plants_.try_emplace(a.entity);
        DeformedPlant& plant = it->second;
        const std::vector<std::uint32_t>& parts = library_.partsOf(a.model);
        if (fresh || plant.slots != parts.size()) {
            releasePlant(registry, a.entity, plant);
            plant.slots = parts.size();
            for (std::size_t i = 0; i < parts.size(); ++i) {
                const scene::MeshPart& mesh = library_.part(parts[i]);
                if (mesh.material.surface == scene::SurfaceClass::Blend) continue;
                DeformedPart p;
                p.slot = i;
                p.part = parts[i];
                p.flutter = mesh.material.surface == scene::SurfaceClass::Mask;
                p.vertices = library_.vertices(parts[i]);
                p.push.assign(p.vertices.size(), glm::vec3(0.0f));
                p.buffers = partBuffers(parts[i], p.vertices);
                plant.parts.push_back(std::move(p));
            }
        }
        for (DeformedPart& p : plant.parts) {
            // Motion from the vertices drawn last frame (the rest mesh for a new plant): a copy
            // only on the frame motion is first asked for, freed on the frame it no longer is.
            if (!frame_.motionVectors) std::vector<Vertex>().swap(p.motion);
            else if (p.motion.size() != p.vertices.size()) p.motion = p.vertices;
            if (frame_.motionVectors && !p.buffers.motion.get())
                p.buffers.motion = createBuffer(p.part, " (motion)", p.vertices);
            jobs.push_back({&p, &a.pose});
        }
    }

    // The deformation itself: independent per part, so any thread count gives the same bits.
    const float decay = std::exp(-wind->springRate * frame_.dt);
    const float time = frame_.time;
    const Wind& w = *wind;
    parallelFor(std::size_t(0), jobs.size(), [&](std::size_t j) {
        DeformedPart& p = *jobs[j].part;
        for (std::size_t i = 0; i < p.motion.size(); ++i) p.motion[i].normal = p.vertices[i].position;  // previous
        p.bounds = deformVertices(library_.vertices(p.part), p.vertices, p.push, w, *jobs[j].pose, time, p.flutter,
                                  decay, colliders);
        for (std::size_t i = 0; i < p.motion.size(); ++i) {
            const glm::vec3 previous = p.motion[i].normal;
            p.motion[i] = p.vertices[i];
            p.motion[i].normal = previous - p.vertices[i].position;
        }
    });

    // Upload and point extraction at the deformed copies.
    for (const Active& a : active) {
        DeformedPlant& plant = plants_.at(a.entity);
        scene::VertexOverride override;
        override.buffers.assign(plant.slots, render::BufferHandle{});
        if (frame_.motionVectors) override.motionBuffers.assign(plant.slots, render::BufferHandle{});
        override.bounds.assign(plant.slots, Aabb{});
        for (const DeformedPart& p : plant.parts) {
            library_.backend().updateBuffer(p.buffers.vertices, 0, std::as_bytes(std::span(p.vertices)));
            override.buffers[p.slot] = p.buffers.vertices;
            if (frame_.motionVectors) {
                library_.backend().updateBuffer(p.buffers.motion, 0, std::as_bytes(std::span(p.motion)));
                override.motionBuffers[p.slot] = p.buffers.motion;
                ++stats_.motionCopies;
            }
            override.bounds[p.slot] = p.bounds;
            stats_.verticesDeformed += p.vertices.size();
        }
        ++stats_.plantsDeformed;
        if (scene::VertexOverride* existing = registry.tryGet<scene::VertexOverride>(a.entity))
            *existing = std::move(override);
        else registry.add<scene::VertexOverride>(a.entity, std::move(override));
    }
}

}  // namespace wind
