// SPDX-License-Identifier: MIT
#include "hud/overlay.hpp"

#include <algorithm>
#include <memory>
#include <span>

#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "engine/render/vertex.hpp"
#include "hud/overlay_programs.hpp"

namespace hud {

using namespace engine::render;

namespace {

void addQuad(OverlayMesh& mesh, const PixelRect& r, const glm::vec4& color) {
    if (r.width <= 0 || r.height <= 0) return;
    const auto first = std::uint32_t(mesh.positions.size());
    const float x0 = float(r.x), y0 = float(r.y), x1 = float(r.x + r.width), y1 = float(r.y + r.height);
    for (const glm::vec2 p : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x0, y1), glm::vec2(x1, y1)}) {
        mesh.positions.emplace_back(p, 0.5f);
        mesh.colors.push_back(color);
    }
    mesh.indices.insert(mesh.indices.end(), {first, first + 2, first + 1, first + 1, first + 2, first + 3});
}

}  // namespace

OverlayMesh fillMesh(const std::vector<Fill>& fills) {
    OverlayMesh mesh;
    for (const Fill& f : fills) addQuad(mesh, f.rect, f.color);
    return mesh;
}

OverlayMesh textMesh(const OverlayContent& content) {
    OverlayMesh mesh;
    for (const TextPanel& panel : content.text) {
        addQuad(mesh, panel.box, content.boxColor);
        // The shadow one font pixel down and right, clipped to the box so it never leaves it.
        for (PixelRect g : panel.glyphs) {
            g.x += panel.scale, g.y += panel.scale;
            g.width = std::min(g.x + g.width, panel.box.x + panel.box.width) - g.x;
            g.height = std::min(g.y + g.height, panel.box.y + panel.box.height) - g.y;
            addQuad(mesh, g, content.shadowColor);
        }
        for (const PixelRect& g : panel.glyphs) addQuad(mesh, g, content.textColor);
    }
    return mesh;
}

Overlay::Overlay(Backend& backend)
    : backend_(backend), fillProgram_(backend, backend.createProgram(overlayFillProgram())),
      panelProgram_(backend, backend.createProgram(overlayPanelProgram())), buffers_(backend) {
    PipelineDesc p;
    p.name = "overlay fill";
    p.program = fillProgram_.get();
    p.blend[0] = BlendState::alphaOver();
    fill_ = Owned<PipelineHandle>(backend, backend.createPipeline(p));
    p.name = "overlay panel";
    p.program = panelProgram_.get();
    p.blend[0] = BlendState{};
    panel_ = Owned<PipelineHandle>(backend, backend.createPipeline(p));
}

void Overlay::beginFrame() { buffers_.beginFrame(); }

FrameGraphTexture Overlay::addPass(FrameGraph& graph, const std::string& name, FrameGraphTexture color,
                                   TextureHandle target, int width, int height, OverlayContent content) {
    struct Data {
        FrameGraphTexture out;
    };
    // Read before `content` moves into the pass (both lambdas are made before setup runs).
    const bool empty = content.empty();
    std::vector<FrameGraphTexture> sources;
    for (const ImagePanel& image : content.images)
        if (image.sourceInGraph.isValid()) sources.push_back(image.sourceInGraph);
    return graph
        .addPass<Data>(
            name,
            [&](FrameGraph::Builder& b, Data& d) {
                for (FrameGraphTexture source : sources) b.read(source);
                d.out = b.write(b.read(color));
                if (empty) b.markEmpty();
            },
            [this, target, width, height, name, content = std::move(content)](
                const FrameGraph::Resources&, const Data&) { draw(target, width, height, content, name); })
        .out;
}

void Overlay::drawMesh(const OverlayMesh& mesh, int width, int height, const char* name) {
    if (mesh.indices.empty()) return;
    std::vector<Vertex> vertices(mesh.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        vertices[i].position = mesh.positions[i];
        vertices[i].color = mesh.colors[i];
    }
    DrawDesc d;
    d.pipeline = fill_;
    d.params = OverlayFillParams{pixelToClip(width, height)};
    d.vertices =
        buffers_.upload(std::string(name) + " vertices", BufferKind::Vertex, std::as_bytes(std::span(vertices)));
    d.indices =
        buffers_.upload(std::string(name) + " indices", BufferKind::Index, std::as_bytes(std::span(mesh.indices)));
    d.count = std::uint32_t(mesh.indices.size());
    backend_.draw(d);
}

void Overlay::draw(TextureHandle target, int width, int height, const OverlayContent& content,
                   const std::string& name) {
    PassDesc pass;
    pass.name = name;
    pass.color[0] = {target, LoadOp::Load};
    PassScope scope(backend_, pass);
    for (const ImagePanel& image : content.images) {
        const PixelRect to = image.target();
        // The scissor keeps the full-screen program inside the panel, clipped to the target.
        const int x0 = std::max(0, to.x), y0 = std::max(0, to.y);
        const int x1 = std::min(width, to.x + to.width), y1 = std::min(height, to.y + to.height);
        if (x1 <= x0 || y1 <= y0) continue;
        DrawDesc d;
        d.pipeline = panel_;
        d.params = OverlayPanelParams{image.source, image.region.x, image.region.y, image.at.x, image.at.y, image.zoom};
        d.scissor = Rect{x0, y0, x1 - x0, y1 - y0};
        backend_.draw(d);
    }
    drawMesh(fillMesh(content.fills), width, height, "overlay fills");
    drawMesh(textMesh(content), width, height, "overlay text");
    scope.end();
}

}  // namespace hud
