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
    // Its level of detail and whether its instances crossfade (engine::scene::DrawBatch): the
    // alpha-test techniques dither those (transparency/lod_dither.hpp).
    int lodLevel = 0;
    bool crossfading = false;
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
    // Opaque draws that moved (the car; engine/scene rigid_motion.hpp), drawn by the host's
    // opaque pass: each batch's vertices and motionVertices, its instances, cutoff 0. Only the
    // temporal pass reads them, to write their motion (transparency/temporal.hpp).
    std::span<const FoliageDraw> movingOpaque;
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

// A texture a technique keeps, for captures (e.g. the temporal history).
struct NamedTarget {
    std::string name;
    engine::render::TextureHandle texture;
};

// One of those as the graph knows it after addPasses: the version the technique wrote.
struct GraphTarget {
    std::string layer;
    engine::render::FrameGraphTexture texture;
};

// What a technique asks of the frame around it, fixed when it is made.
struct TechniqueTraits {
    TechniqueKind kind = TechniqueKind::Ssam;
    // Samples the caller must draw the opaque pass with (alpha-to-coverage needs 4).
    int opaqueSamples = 1;
    // A temporal technique's frame depends on the frames before it (the temporal pass): such
    // a technique is measured only after frames of history, and the caller moves frame i's
    // projection by haltonJitter(i, jitterPhases) (Technique::projectionJitter).
    bool temporal = false;
    int jitterPhases = 1;
    // The technique reads the draws' motion vectors (MaskedBatch::motionVertices: a temporal
    // technique with TemporalOptions::motionVectors): only then need the features that move
    // vertices (the wind) make their motion copies (scene::SimulationFrame::motionVectors).
    bool motionVectors = false;
};

// A technique runs its frame one way only, as passes added to the caller's frame graph
// (addPasses); tests run it the same way, through a one-off graph.
class Technique {
public:
    explicit Technique(const TechniqueTraits& traits) : traits_(traits) {}
    virtual ~Technique() = default;

    const TechniqueTraits& traits() const { return traits_; }
    TechniqueKind kind() const { return traits_.kind; }
    int opaqueSamples() const { return traits_.opaqueSamples; }
    bool needsHistory() const { return traits_.temporal; }
    bool needsMotionVectors() const { return traits_.motionVectors; }
    // The sub-pixel offset, in pixels, the caller moves frame `frameIndex`'s projection by,
    // for the opaque pass and FoliageFrame::viewProj alike (transparency/temporal.hpp
    // jitteredViewProj); zero but for temporal techniques.
    glm::vec2 projectionJitter(std::uint64_t frameIndex) const;

    // The technique's passes, after the opaque pass drew into `opaque`: `drawn` holds the
    // versions it left in what it drew into (the MSAA targets, or the resolved ones when
    // single-sampled), `resolved` the imported rt_opaque and rt_depth. Returns the versions
    // of the resolved colour and depth the technique leaves: the final colour, and the depth
    // later passes test against (the foliage depth where the technique writes one). Passes
    // with no foliage in view are empty (or cost almost nothing). `frame` and what it points
    // to must outlive the graph's execute(), which must be given an allocator backed by the
    // technique's backend (a TransientTexturePool): the targets a technique draws through
    // and needs no longer are the graph's transients.
    virtual engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph,
                                                 engine::render::FrameTargets& opaque,
                                                 const engine::render::ColorDepth& drawn,
                                                 const engine::render::ColorDepth& resolved,
                                                 const FoliageFrame& frame) = 0;
    // The transients the last addPasses() wrote, by layer name, for a later pass of the same
    // graph to read (a capture: reading one keeps it alive until then); empty when none.
    const std::vector<GraphTarget>& graphIntermediates() const { return graphTargets_; }
    // The textures the technique keeps itself from frame to frame (history, uploads), for
    // captures; empty when there are none.
    virtual std::vector<NamedTarget> intermediates() const { return {}; }
    // The reference's report on its last frame; nullopt for every other technique.
    virtual std::optional<ReferenceReport> referenceReport() const { return std::nullopt; }

protected:
    std::vector<GraphTarget> graphTargets_;  // set by addPasses()

private:
    TechniqueTraits traits_;
};

}  // namespace transparency
