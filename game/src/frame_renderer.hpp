// SPDX-License-Identifier: MIT
#pragma once
// One frame of the racing scene on any backend, built as a frame graph each frame: the
// opaque pass (terrain, road, trunks, car), the foliage by the chosen transparency::Technique
// (SSAM, alpha testing, the rivals and the exact reference), then the living scene's passes
// or BLEND surfaces (water) back to front, depth-tested against the depth the technique
// leaves (SSAM: the foliage depth its colour pass wrote, [Hathaway 2010] §3.7), then present.
// Per-frame instance buffers and the graph's transient targets (the technique's and the
// living scene's intermediates) come from pools, so a steady-state frame creates no buffer
// or texture.
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <vector>

#include "camera_rig.hpp"
#include "engine/capture/target_capture.hpp"
#include "engine/core/non_copyable.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/frame_buffer_pool.hpp"
#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/transient_texture_pool.hpp"
#include "engine/render/frame_targets.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/frame_feature.hpp"
#include "foliage_upload.hpp"
#include "hud/overlay.hpp"
#include "transparency/create_technique.hpp"

namespace racer {

class CompareView;
class LivingScene;

struct RendererOptions {
    int width = 1280;
    int height = 720;
    transparency::TechniqueKind technique = transparency::TechniqueKind::Ssam;
    // The opaque pass's samples are max(msaa, technique->opaqueSamples()): --msaa asks for
    // at least this many (Pure used 2 under SSAM), alpha-to-coverage needs 4 whatever is asked.
    int msaa = 1;
    // Which sample the MSAA depth resolves to (frame_targets.hpp): the closest, as §3.5.1 asks, or
    // any one where the backend cannot read samples (the GLES driver, the web page).
    engine::render::DepthResolve msaaDepth = engine::render::DepthResolve::Closest;
    transparency::TechniqueOptions techniqueOptions;  // its depthFunc is set to the scene's
    glm::vec4 background{0.55f, 0.70f, 0.88f, 1.0f};  // the opaque pass's clear colour (the racing scene's sky)
    // The scene's sun; this default is the one a glTF file without lights gets.
    engine::render::DirectionalLight sun{{0.45f, 0.80f, 0.35f}, {1.05f, 0.98f, 0.88f}, {0.32f, 0.36f, 0.42f}};
    bool captureLayers = false;  // keep every intermediate of the last frame (EXR layers)
};

class FrameRenderer : engine::NonCopyable {
public:
    // Throws engine::Error (from transparency::createTechnique) when the backend cannot run
    // the technique or it is not implemented.
    FrameRenderer(engine::render::Backend& backend, const engine::scene::MeshLibrary& library,
                  const RendererOptions& options);
    ~FrameRenderer();

    // Switches the foliage technique (the window's keys). Throws engine::Error and keeps the
    // current technique when the new one cannot be created.
    void setTechnique(transparency::TechniqueKind kind);
    transparency::TechniqueKind technique() const { return technique_->kind(); }
    // Whether the next frame reads the draws' motion vectors (a temporal technique with them
    // runs, on either side of a compare): the living scene's update is told so
    // (scene::SimulationFrame::motionVectors), and without it the wind makes no motion copies.
    bool needsMotionVectors() const;
    int opaqueSamples() const { return opaque_->desc().samples; }

    // Renders at width x height from the next frame on (the window follows its framebuffer).
    // The opaque targets are made anew; the technique's and the living scene's follow their
    // size when they next draw. Throws engine::Error (keeping the current size and targets)
    // when the backend refuses targets that large.
    void resize(int width, int height);
    int width() const { return options_.width; }
    int height() const { return options_.height; }

    // One frame. A temporal technique (hashed+taa, ...) gets its projection jitter on the
    // opaque pass and the foliage; the living scene's passes, drawn after its temporal pass,
    // keep the unjittered camera.
    void render(const engine::scene::DrawLists& lists, const CameraView& camera);
    // The camera jumped (a camera switch): a temporal technique drops its history next frame.
    void cutHistory() { cut_ = true; }

    // Side by side (compare_view.hpp): the current technique on the left, `right` on the
    // right; nullopt ends it. Throws engine::Error, keeping the current state, when `right`
    // cannot run here.
    void setCompare(std::optional<transparency::TechniqueKind> right);
    std::optional<transparency::TechniqueKind> comparedTechnique() const;
    // The last frame's compare overlay outside the plain halves (labels, insets, the crop's
    // outline) and the crop the insets show; empty when not comparing.
    std::vector<hud::PixelRect> compareMarks() const;
    hud::PixelRect compareCrop() const;

    // The HUD (modules/hud): these lines in a panel at the frame's top-left corner, drawn by
    // a pass "hud" after everything else; no lines (the default), no HUD. Kept until changed.
    void setHud(std::vector<std::string> lines) { hudLines_ = std::move(lines); }
    bool hudShown() const { return !hudLines_.empty(); }
    // Where the last frame's HUD panel was (empty without one).
    hud::PixelRect hudBox() const { return hudBox_; }

    // The living scene's features (modules/water, ...) draw after the technique, replacing
    // the built-in BLEND step; null (the default) keeps that step.
    void setLivingScene(LivingScene* living);

    // Graphviz dot of the last frame's compiled graph (racer --dump-graph): culled passes
    // and passes skipped as empty are marked so; its label lists each transient's lifetime
    // and bytes and the peak transient bytes. Throws engine::Error before any frame.
    void dumpGraph(std::ostream& out) const;
    // The most bytes the last frame's transient targets (SSAM's mask and foliage, WBOIT's
    // accumulators, the particle layer) held at once; 0 before any frame (the HUD shows it).
    std::uint64_t peakTransientBytes() const;

    engine::render::TextureHandle color() const { return opaque_->color(); }
    const std::vector<engine::capture::CapturedLayer>& layers() const { return layers_; }

private:
    engine::render::ColorDepth addOpaquePass(engine::render::FrameGraph& graph,
                                             const engine::render::ColorDepth& targets,
                                             const engine::scene::DrawLists& lists, const CameraView& camera);
    engine::render::ColorDepth addBlendPass(engine::render::FrameGraph& graph,
                                            const engine::render::ColorDepth& targets,
                                            const engine::scene::FeatureFrame& frame, const CameraView& camera);
    engine::render::SurfaceParams surface(const engine::scene::MeshPart& part, const glm::mat4& viewProj) const;
    engine::render::DrawDesc batchDraw(const engine::scene::DrawBatch& batch, engine::render::PipelineHandle pipeline,
                                       engine::render::DrawParams params);
    engine::render::PipelineHandle opaquePipeline(bool doubleSided);
    void ensureOpaqueTargets(int width, int height, int samples);
    void capture(engine::render::TextureHandle target, const char* name);
    void captureIntermediates(std::vector<transparency::NamedTarget> targets);
    void addCaptureFoliagePass(engine::render::FrameGraph& graph, const engine::render::ColorDepth& frame);

    engine::render::Backend& backend_;
    const engine::scene::MeshLibrary& library_;
    RendererOptions options_;
    std::unique_ptr<engine::render::FrameTargets> opaque_;
    std::unique_ptr<transparency::Technique> technique_;
    FoliageUpload foliage_;
    engine::render::PipelineHandle opaqueCulled_, opaqueTwoSided_, water_, waterCulled_;  // water_: BLEND, two-sided
    engine::render::FrameBufferPool instances_;              // opaque and BLEND instance data
    engine::render::TransientTexturePool transients_;        // the graph's transient targets
    std::unique_ptr<engine::render::FrameGraph> lastGraph_;  // for dumpGraph()
    std::vector<engine::capture::CapturedLayer> layers_;
    LivingScene* living_ = nullptr;
    hud::Overlay overlay_;
    std::unique_ptr<CompareView> compare_;
    std::vector<std::string> hudLines_;
    hud::PixelRect hudBox_;
    std::uint64_t frameIndex_ = 0;  // frames rendered: FoliageFrame::frameIndex
    bool cut_ = false;
};

}  // namespace racer
