// SPDX-License-Identifier: MIT
#pragma once
// Overlays on a finished frame, drawn by the backend as a frame-graph pass: image panels (a
// region of another texture, copied or zoomed: the compare's split and insets), then filled
// rectangles (frames, outlines), then text panels (a translucent box, the glyphs with a one-pixel shadow: the HUD and labels).
// Nothing outside the panels' rectangles is touched, so a frame with an overlay equals the
// frame without it everywhere else, bit for bit.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/render/backend.hpp"
#include "engine/render/frame_buffer_pool.hpp"
#include "engine/render/frame_graph.hpp"
#include "engine/render/owned.hpp"
#include "hud/text_layout.hpp"

namespace hud {

struct ImagePanel {
    engine::render::TextureHandle source;             // single-sampled colour, read by texel
    engine::render::FrameGraphTexture sourceInGraph;  // its latest version, when the graph knows it
    PixelRect region;                                 // of `source`
    glm::ivec2 at{0};                                 // where its top-left texel lands in the target
    int zoom = 1;                                     // each texel zoom x zoom pixels
    PixelRect target() const { return {at.x, at.y, region.width * zoom, region.height * zoom}; }
};

// A rectangle of one colour (straight alpha over the frame).
struct Fill {
    PixelRect rect;
    glm::vec4 color{1.0f};
};

struct OverlayContent {
    std::vector<Fill> fills;
    std::vector<ImagePanel> images;
    std::vector<TextPanel> text;
    glm::vec4 boxColor{0.01f, 0.012f, 0.02f, 0.8f};  // straight alpha over the frame
    glm::vec4 textColor{1.0f, 0.97f, 0.85f, 1.0f};
    glm::vec4 shadowColor{0.0f, 0.0f, 0.0f, 1.0f};
    bool empty() const { return fills.empty() && images.empty() && text.empty(); }
};

// The quads of `content`'s fills or text (boxes, shadows, glyphs, in drawing order) as
// triangles in pixel coordinates: what Overlay draws with OverlayFill.
struct OverlayMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec4> colors;
    std::vector<std::uint32_t> indices;
};
OverlayMesh fillMesh(const std::vector<Fill>& fills);
OverlayMesh textMesh(const OverlayContent& content);

class Overlay {
public:
    // Creates the two programs and their pipelines on `backend` (Throws engine::Error).
    explicit Overlay(engine::render::Backend& backend);
    ~Overlay() = default;
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    // Call once a frame before adding passes: the vertex buffers of earlier frames are reused.
    void beginFrame();

    // Adds pass `name` drawing `content` over `color` (the graph's latest version of
    // `target`, a width x height colour target); returns the colour's new version. An empty
    // content marks the pass empty (skipped).
    engine::render::FrameGraphTexture addPass(engine::render::FrameGraph& graph, const std::string& name,
                                              engine::render::FrameGraphTexture color,
                                              engine::render::TextureHandle target, int width, int height,
                                              OverlayContent content);

    // Records the draws at once, in a pass of its own over `target` (what addPass executes).
    void draw(engine::render::TextureHandle target, int width, int height, const OverlayContent& content,
              const std::string& name = "overlay");

private:
    void drawMesh(const OverlayMesh& mesh, int width, int height, const char* name);

    engine::render::Backend& backend_;
    // Pipelines after their programs, so they are destroyed first.
    engine::render::Owned<engine::render::ProgramHandle> fillProgram_, panelProgram_;
    engine::render::Owned<engine::render::PipelineHandle> fill_, panel_;
    engine::render::FrameBufferPool buffers_;
};

}  // namespace hud
