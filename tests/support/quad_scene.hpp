// SPDX-License-Identifier: MIT
#pragma once
// Small hand-made scenes for SSAM tests: axis-aligned quads at a given depth with a given
// colour and alpha (vertex colour; no texture), in NDC with an identity view-projection.
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/render/vertex.hpp"
#include "ssam/foliage.hpp"

namespace ssam::testing {

struct Quad {
    float x0, y0, x1, y1;  // NDC
    float depth;           // [0, 1]
    glm::vec4 color;       // straight alpha
};

inline std::vector<engine::render::Vertex> quadVertices(const Quad& q) {
    using engine::render::Vertex;
    auto v = [&](float x, float y) {
        Vertex vertex;
        vertex.position = {x, y, q.depth};
        vertex.color = q.color;
        return vertex;
    };
    return {v(q.x0, q.y0), v(q.x1, q.y0), v(q.x1, q.y1), v(q.x0, q.y0), v(q.x1, q.y1), v(q.x0, q.y1)};
}

// One foliage batch per quad, drawn in the order given.
struct QuadBatches {
    engine::render::Backend& backend;
    std::vector<engine::render::BufferHandle> buffers;
    std::vector<engine::render::MaskedBatch> batches;

    QuadBatches(engine::render::Backend& b, const std::vector<Quad>& quads) : backend(b) {
        for (const Quad& q : quads) {
            const auto vertices = quadVertices(q);
            const auto bytes = std::as_bytes(std::span(vertices));
            buffers.push_back(backend.createBuffer({"quad", engine::render::BufferKind::Vertex, bytes.size()}, bytes));
            engine::render::MaskedBatch batch;
            batch.vertices = buffers.back();
            batch.count = 6;
            batch.worldBounds = {{q.x0, q.y0, q.depth}, {q.x1, q.y1, q.depth}};
            batches.push_back(batch);
        }
    }
    ~QuadBatches() {
        for (auto b : buffers) backend.destroy(b);
    }

    // Draws every quad with `pipeline` (a Flat one) into the open pass: opaque geometry, or a
    // later pass that depth-tests against the foliage.
    void drawFlat(engine::render::PipelineHandle pipeline) const {
        for (const engine::render::MaskedBatch& batch : batches) {
            engine::render::DrawDesc d;
            d.pipeline = pipeline;
            d.params = engine::render::FlatParams{};
            d.vertices = batch.vertices;
            d.count = batch.count;
            backend.draw(d);
        }
    }
};

}  // namespace ssam::testing
