#pragma once
// One frame of the racing scene on any backend: the opaque pass (terrain, road, trunks,
// car), the foliage by the chosen technique (SSAM, or plain alpha testing in the opaque
// pass), then BLEND surfaces (water) back to front, depth-tested against the foliage depth
// SSAM's colour pass wrote (seeds/000 §3.7).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "camera_rig.hpp"
#include "engine/capture/target_capture.hpp"
#include "engine/render/backend.hpp"
#include "engine/scene/draw_lists.hpp"
#include "ssam/opaque_targets.hpp"
#include "ssam/ssam.hpp"

namespace racer {

enum class Technique { Ssam, AlphaTest };
const char* techniqueName(Technique technique);

struct RendererOptions {
    int width = 1280;
    int height = 720;
    Technique technique = Technique::Ssam;
    int opaqueSamples = 1;
    ssam::Config ssam;
    bool captureLayers = false;  // keep every intermediate of the last frame (EXR layers)
};

class FrameRenderer {
public:
    FrameRenderer(engine::render::Backend& backend, const engine::scene::MeshLibrary& library,
                  const RendererOptions& options);
    ~FrameRenderer();

    void render(const engine::scene::DrawLists& lists, const CameraView& camera);

    engine::render::TextureHandle color() const { return opaque_.color(); }
    const std::vector<engine::capture::CapturedLayer>& layers() const { return layers_; }

private:
    engine::render::BufferHandle uploadInstances(const engine::scene::DrawBatch& batch);
    engine::render::DrawDesc batchDraw(const engine::scene::DrawBatch& batch, engine::render::PipelineHandle pipeline,
                                       engine::render::ProgramParams params);
    engine::render::PipelineHandle opaquePipeline(bool doubleSided);
    engine::render::PipelineHandle alphaTestPipeline(float cutoff);
    void capture(engine::render::TextureHandle target, const char* name);
    void captureMask();

    engine::render::Backend& backend_;
    const engine::scene::MeshLibrary& library_;
    RendererOptions options_;
    ssam::OpaqueTargets opaque_;
    std::unique_ptr<ssam::ScreenSpaceAlphaMask> ssam_;
    engine::render::PipelineHandle opaqueCulled_, opaqueTwoSided_, water_;
    std::map<float, engine::render::PipelineHandle> alphaTested_;
    std::vector<engine::render::BufferHandle> frameBuffers_;  // instance data of the frame in flight
    std::vector<engine::capture::CapturedLayer> layers_;
};

}  // namespace racer
