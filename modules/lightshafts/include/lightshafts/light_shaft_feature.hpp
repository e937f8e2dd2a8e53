// SPDX-License-Identifier: MIT
#pragma once
// The light-shafts module as a living-scene feature: one pass, "light shafts", running
// its program (light_shaft_program.hpp) over the whole frame with additive blending (RGB ONE/ONE, alpha
// kept). The occlusion image is the opaque + foliage depth: foliage in front of the sun
// blocks the shafts exactly where its colour pass wrote depth. Off (no pass) when the sun
// is behind the camera or its glow misses the frame; skipped (the pass's draw does not run)
// when an occlusion query finds no sky within the glow, i.e. the sun is fully occluded.
#include <memory>
#include <optional>

#include "engine/render/owned.hpp"
#include "engine/scene/frame_feature.hpp"

namespace lightshafts {

class SunVisibilityProbe;

struct LightShaftOptions {
    glm::vec3 color{1.0f, 0.92f, 0.75f};
    float intensity = 0.8f;  // >= 0
    float decay = 0.96f;     // (0, 1]
    float density = 0.8f;    // (0, 1]: how far towards the sun each pixel looks
    int samples = 32;        // 1..128
    // The sun's glow in the occlusion image, as a fraction of the frame height (> 0): only
    // sky near the sun casts shafts, so open sky elsewhere is not hazed over.
    float glowRadius = 0.3f;
    // Probe the sky near the sun with an occlusion query and skip the pass when there is
    // none. The pass would add exactly 0 then, so this only saves time.
    bool skipWhenSunHidden = true;
};

// Throws engine::Error naming the field for NaN/inf or out-of-range values.
void validate(const LightShaftOptions& options);

class LightShaftFeature final : public engine::scene::Feature {
public:
    LightShaftFeature(engine::render::Backend& backend, const LightShaftOptions& options = {});
    ~LightShaftFeature() override;

    std::string_view name() const override { return "light shafts"; }
    // One pass, "light shafts"; none issued (an empty pass) when the sun's glow misses the frame.
    engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph, const engine::scene::FeatureFrame& frame,
                                         const engine::render::ColorDepth& targets) override;

    // Whether the last frame issued the pass, and where the sun was (pixels). An issued pass
    // may still be skipped by the backend: takeTimings() marks it, or ask sunVisible().
    bool ranLastFrame() const { return ran_; }
    glm::vec2 sunPixel() const { return sunPixel_; }
    // The last frame's sun-visibility query (waits for it on GL); true when none was made.
    bool sunVisible() const;

private:
    bool prepare(const engine::scene::FeatureFrame& frame);  // where the sun is; whether its glow is in view
    void draw(const engine::scene::FeatureFrame& frame);
    engine::render::Backend& backend_;
    LightShaftOptions options_;
    // Owned: a create that throws in the constructor leaves nothing made before it behind.
    engine::render::Owned<engine::render::ProgramHandle> program_;
    engine::render::Owned<engine::render::PipelineHandle> pipeline_;
    std::unique_ptr<SunVisibilityProbe> probe_;
    std::optional<engine::render::QueryHandle> lastQuery_;
    bool ran_ = false;
    glm::vec2 sunPixel_{0.0f};
};

}  // namespace lightshafts
