// SPDX-License-Identifier: MIT
#pragma once
// One foliage frame of a transparency technique, run as the racer runs it (run_graph.hpp):
// `opaque`'s targets imported after the caller drew the opaque pass into them, the
// technique's passes, then "present". The technique's transients can be read back.
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/render/frame_targets.hpp"
#include "run_graph.hpp"
#include "transparency/technique.hpp"

namespace test_support {

struct TechniqueRun {
    std::vector<std::string> passes;  // the passes that ran, "present" last
    // The transients the technique wrote (Technique::graphIntermediates), by layer name.
    std::vector<std::pair<std::string, engine::render::Readback>> layers;
};

inline TechniqueRun runTechnique(engine::render::Backend& backend, transparency::Technique& technique,
                                 engine::render::FrameTargets& opaque, const transparency::FoliageFrame& frame,
                                 bool readLayers = false) {
    OneFrameGraph one(backend);
    const engine::render::FrameTargets::InGraph in = opaque.importInto(one.graph());
    const engine::render::ColorDepth out = technique.addPasses(one.graph(), opaque, in.drawn, in.resolved, frame);
    std::vector<engine::render::FrameGraphTexture> layers;
    for (const transparency::GraphTarget& t : technique.graphIntermediates()) layers.push_back(t.texture);
    const std::size_t first = readLayers ? one.readBack(layers) : 0;
    TechniqueRun run{one.run(out), {}};
    if (readLayers)
        for (std::size_t i = 0; i < layers.size(); ++i)
            run.layers.emplace_back(technique.graphIntermediates()[i].layer, one.readBacks()[first + i]);
    return run;
}

// The six vertices of a card through `corners` (counter-clockwise), uv from 0 to `uvMax`.
inline std::vector<engine::render::Vertex> cardVertices(const glm::vec3 (&corners)[4], float uvMax, glm::vec4 color) {
    const glm::vec2 uv[4] = {{0, 0}, {uvMax, 0}, {uvMax, uvMax}, {0, uvMax}};
    std::vector<engine::render::Vertex> out;
    for (int i : {0, 1, 2, 0, 2, 3}) {
        engine::render::Vertex v;
        v.position = corners[i];
        v.uv = uv[i];
        v.color = color;
        out.push_back(v);
    }
    return out;
}

// One non-indexed foliage draw for a technique's frames; owns its vertex buffer.
class OneDraw {
public:
    OneDraw(engine::render::Backend& backend, std::span<const engine::render::Vertex> vertices,
            const engine::render::BoundingBox& worldBounds)
        : backend_(backend) {
        const auto bytes = std::as_bytes(vertices);
        draw_.batch.vertices =
            backend.createBuffer({"one draw", engine::render::BufferKind::Vertex, bytes.size()}, bytes);
        draw_.batch.count = std::uint32_t(vertices.size());
        draw_.batch.worldBounds = worldBounds;
        draw_.meshBounds = worldBounds;
    }
    ~OneDraw() { backend_.destroy(draw_.batch.vertices); }
    OneDraw(const OneDraw&) = delete;
    OneDraw& operator=(const OneDraw&) = delete;

    // A frame of this draw alone through `viewProj`, unlit.
    transparency::FoliageFrame frame(const glm::mat4& viewProj) const {
        transparency::FoliageFrame f;
        f.viewProj = viewProj;
        f.light = engine::render::unlitLight();
        f.draws = std::span(&draw_, 1);
        return f;
    }

private:
    engine::render::Backend& backend_;
    transparency::FoliageDraw draw_;
};

// The colour of `technique`'s frame of `draw` through `viewProj`, over an opaque frame of
// size x size cleared to `clear` (RGBA32F, nothing opaque drawn).
inline engine::render::Readback frameOverClear(engine::render::Backend& backend, transparency::Technique& technique,
                                               const OneDraw& draw, const glm::mat4& viewProj, int size,
                                               const glm::vec4& clear) {
    using namespace engine::render;
    FrameTargets opaque(backend, {size, size, technique.opaqueSamples(), Format::RGBA32F, CompareFunc::Less});
    backend.beginPass(opaque.passDesc(clear));
    backend.endPass();
    runTechnique(backend, technique, opaque, draw.frame(viewProj));
    return backend.readback(opaque.color());
}

}  // namespace test_support
