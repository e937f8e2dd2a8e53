// SPDX-License-Identifier: MIT
#pragma once
// How the foliage of a frame is drawn: SSAM and the rivals it is judged against
// and the exact reference that judges them. Every technique draws the same foliage over
// the same opaque frame, so `ssam-bench` and `racer --technique` can swap them freely.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "engine/render/backend.hpp"
#include "engine/render/frame_graph/color_depth.hpp"
#include "engine/render/frame_graph/texture_handle.hpp"
#include "engine/render/frame_targets.hpp"
#include "engine/render/masked_batch.hpp"
#include "engine/render/vertex.hpp"
#include "transparency/programs.hpp"
#include "transparency/technique_kind.hpp"  // generated from the ssam_technique() lines

namespace engine::render {
class FrameGraph;
}

namespace transparency {

// Every kind, in the order tables list them.
std::span<const TechniqueKind> allTechniques();
// As `racer --technique` spells it: ssam, ssam-plus, alpha-test, a2c, blend-unsorted,
// blend-sorted, wboit, reference.
const char* techniqueName(TechniqueKind kind);
std::optional<TechniqueKind> parseTechnique(std::string_view name);

// One batch of foliage, both as GPU handles (to draw it) and as the CPU copy of its
// instances (for techniques that reorder instances, such as sorted blending).
struct FoliageDraw {
    engine::render::MaskedBatch batch;
    std::span<const engine::render::Instance> instances;  // the contents of batch.instances
    engine::render::BoundingBox meshBounds;               // of one instance, in model space
    float alphaCutoff = 0.5f;  // the material's (glTF alphaCutoff): alpha-test techniques use it
};

struct FoliageFrame {
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    engine::render::DirectionalLight light;
    std::span<const FoliageDraw> draws;
    // The frame's number in its sequence: hashed+taa varies its threshold with it, and the
    // temporal pass keeps its history only from one index to the next.
    std::uint64_t frameIndex = 0;
    bool cut = false;  // the camera jumped: temporal techniques drop their history
};

// What the exact reference found in its last frame (Technique::referenceReport).
struct ReferenceReport {
    std::uint64_t fragments = 0;           // fragments kept and composited
    std::size_t maxFragmentsPerPixel = 0;  // the deepest pixel's fragment count (before the cap)
    std::uint64_t pixelsOverCap = 0;       // pixels with more than referenceFragmentsPerPixel fragments:
                                           // only their nearest cap were composited (logged as a warning)
    std::uint64_t fragmentsOverCap = 0;    // fragments those pixels lost
    bool exact() const { return pixelsOverCap == 0; }
};

// A target a technique keeps, for captures (e.g. SSAM's mask and foliage).
struct NamedTarget {
    std::string name;
    engine::render::TextureHandle texture;
};

// A target a technique draws a frame through and needs no longer: in a frame graph, a
// transient the technique's pass creates (Technique::transientTargets).
struct TransientTarget {
    std::string layer;                 // its name among the captured layers (racer --capture-layers)
    engine::render::TextureDesc desc;  // a render target of the frame's size (renderTargetDesc)
};

// One of those as the graph knows it after addPasses: the version the technique wrote.
struct GraphTarget {
    std::string layer;
    engine::render::FrameGraphTexture texture;
};

class Technique {
public:
    virtual ~Technique() = default;
    virtual TechniqueKind kind() const = 0;
    // Samples the caller must draw the opaque pass with (alpha-to-coverage needs 4).
    virtual int opaqueSamples() const { return 1; }
    // The sub-pixel offset, in pixels, the caller moves frame `frameIndex`'s projection by,
    // for the opaque pass and FoliageFrame::viewProj alike (transparency/temporal.hpp
    // jitteredViewProj); zero but for temporal techniques.
    virtual glm::vec2 projectionJitter(std::uint64_t /*frameIndex*/) const { return glm::vec2(0.0f); }
    // Whether the technique's frame depends on the frames before it (the temporal pass): such
    // a technique is measured only after frames of history.
    virtual bool needsHistory() const { return false; }
    // Called after the opaque pass was drawn into `opaque` and BEFORE opaque.resolve():
    // draws the foliage, resolves, and leaves the final colour in opaque.color() and, in
    // opaque.depth(), the depth later passes test against (the foliage depth where the
    // technique writes one). No foliage in view: costs (almost) nothing.
    virtual void render(engine::render::FrameTargets& opaque, const FoliageFrame& frame) = 0;
    // The same work as frame-graph passes, after the opaque pass drew into `opaque`:
    // `drawn` holds the versions it left in what it drew into (the MSAA targets, or the
    // resolved ones when single-sampled), `resolved` the imported rt_opaque and rt_depth.
    // Returns the versions of the resolved colour and depth the technique leaves. By default
    // one pass named after the technique reads and writes all of them and calls render()
    // (which may draw into the MSAA targets before resolving, as alpha testing does); SSAM
    // declares its mask, colour and composite passes, which are empty with no foliage in view.
    // `frame` and what it points to must outlive the graph's execute(), which must be given
    // an allocator backed by the technique's backend (a TransientTexturePool): the default
    // pass creates the technique's transientTargets() as the graph's transients and draws
    // through them (renderInto), so the graph, not the technique, owns them.
    virtual engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph,
                                                 engine::render::FrameTargets& opaque,
                                                 const engine::render::ColorDepth& drawn,
                                                 const engine::render::ColorDepth& resolved, const FoliageFrame& frame);
    // The targets a frame of width x height with colour in `colorFormat` needs, in the order
    // renderInto() takes them; none when there is nothing to draw (no foliage in view) or
    // the technique needs none.
    virtual std::vector<TransientTarget> transientTargets(int /*width*/, int /*height*/,
                                                          engine::render::Format /*colorFormat*/,
                                                          const FoliageFrame& /*frame*/) const {
        return {};
    }
    // render() drawing through `targets` (backend textures as transientTargets() described
    // them) instead of targets of its own. The default is render(): no targets.
    virtual void renderInto(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                            std::span<const engine::render::TextureHandle> /*targets*/) {
        render(opaque, frame);
    }
    // The transients the last addPasses() wrote, by layer name, for a later pass of the same
    // graph to read (a capture: reading one keeps it alive until then); empty when none.
    const std::vector<GraphTarget>& graphIntermediates() const { return graphTargets_; }
    // The targets the technique keeps itself (render() without a graph; textures it
    // uploads), for captures; empty when there are none.
    virtual std::vector<NamedTarget> intermediates() const { return {}; }
    // The reference's report on its last frame; nullopt for every other technique.
    virtual std::optional<ReferenceReport> referenceReport() const { return std::nullopt; }

protected:
    std::vector<GraphTarget> graphTargets_;  // set by addPasses()
};

}  // namespace transparency
