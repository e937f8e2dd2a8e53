// SPDX-License-Identifier: MIT
#include "engine/scene/rigid_motion.hpp"

#include "engine/scene/components.hpp"

namespace engine::scene {

void RigidMotion::forget(ecs::Registry& registry, ecs::Entity e) {
    if (registry.alive(e) && registry.has<VertexOverride>(e)) registry.remove<VertexOverride>(e);
}

std::span<const render::Vertex> RigidMotion::motion(ecs::Entity e, std::size_t i) const {
    const auto it = moving_.find(e);
    if (it == moving_.end() || i >= it->second.copies.size()) return {};
    return it->second.copies[i];
}

void RigidMotion::update(ecs::Registry& registry, bool motionVectors) {
    motionCopies_ = 0;
    for (auto it = moving_.begin(); it != moving_.end();) {
        const bool keep = motionVectors && registry.alive(it->first) && registry.has<MovesRigidly>(it->first) &&
                          registry.has<Transform>(it->first) && registry.has<Renderable>(it->first);
        if (keep) {
            ++it;
            continue;
        }
        forget(registry, it->first);
        it = moving_.erase(it);
    }
    if (!motionVectors) return;
    marked_.clear();  // collected first: the walk below adds components
    registry.view<const Transform, const Renderable, const MovesRigidly>().each(
        [&](ecs::Entity e, const Transform&, const Renderable&, const MovesRigidly&) { marked_.push_back(e); });
    for (ecs::Entity e : marked_) {
        const glm::mat4 model = registry.get<Transform>(e).matrix();
        const Renderable& r = registry.get<Renderable>(e);
        auto [it, fresh] = moving_.try_emplace(e);
        Moving& m = it->second;
        if (fresh) {
            if (registry.has<VertexOverride>(e)) {  // someone else's (a bent plant): not ours to replace
                moving_.erase(it);
                continue;
            }
            m.previous = model;
        }
        const std::vector<std::uint32_t>& parts = library_.partsOf(r.model);
        m.buffers.resize(parts.size());
        m.copies.resize(parts.size());
        // Model space of this frame: where each vertex was last frame, minus where it is.
        const glm::mat4 previousHere = glm::inverse(model) * m.previous;
        // Refilled in place after the first frame: its vectors keep their capacity, so a moving car
        // allocates nothing per frame.
        VertexOverride* existing = registry.tryGet<VertexOverride>(e);
        VertexOverride& override = existing ? *existing : registry.add<VertexOverride>(e);
        override.buffers.assign(parts.size(), render::BufferHandle{});
        override.motionBuffers.assign(parts.size(), render::BufferHandle{});
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const MeshPart& part = library_.part(parts[i]);
            if (part.material.surface == SurfaceClass::Blend) continue;
            const std::vector<render::Vertex>& rest = library_.vertices(parts[i]);
            std::vector<render::Vertex>& copy = m.copies[i];
            copy.assign(rest.begin(), rest.end());
            for (render::Vertex& v : copy)
                v.normal = glm::vec3(previousHere * glm::vec4(v.position, 1.0f)) - v.position;
            const auto bytes = std::as_bytes(std::span(copy));
            if (!m.buffers[i].get())
                m.buffers[i] = render::Owned<render::BufferHandle>(
                    library_.backend(),
                    library_.backend().createBuffer({part.name + " (motion)", render::BufferKind::Vertex, bytes.size()},
                                                    bytes));
            else library_.backend().updateBuffer(m.buffers[i], 0, bytes);
            override.buffers[i] = part.vertices;
            override.motionBuffers[i] = m.buffers[i];
            ++motionCopies_;
        }
        m.previous = model;
    }
}

}  // namespace engine::scene
