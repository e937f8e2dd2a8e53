// SPDX-License-Identifier: MIT
#include "lightshafts/light_shaft_feature.hpp"

#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/pass_scope.hpp"
#include "lightshafts/light_shaft_program.hpp"
#include "sun_visibility.hpp"

namespace lightshafts {

using namespace engine::render;

void validate(const LightShaftOptions& o) {
    for (float v : {o.color.r, o.color.g, o.color.b, o.intensity, o.decay, o.density, o.glowRadius})
        if (!std::isfinite(v)) throw engine::Error("LightShaftOptions: a value is not finite");
    if (o.color.r < 0.0f || o.color.g < 0.0f || o.color.b < 0.0f)
        throw engine::Error("LightShaftOptions.color is negative");
    if (o.intensity < 0.0f) throw engine::Error("LightShaftOptions.intensity must be >= 0");
    if (!(o.glowRadius > 0.0f)) throw engine::Error("LightShaftOptions.glowRadius must be > 0");
    if (!(o.decay > 0.0f && o.decay <= 1.0f)) throw engine::Error("LightShaftOptions.decay must be in (0, 1]");
    if (!(o.density > 0.0f && o.density <= 1.0f)) throw engine::Error("LightShaftOptions.density must be in (0, 1]");
    if (o.samples < 1 || o.samples > 128)
        throw engine::Error("LightShaftOptions.samples = " + std::to_string(o.samples) + " not in 1..128");
}

LightShaftFeature::LightShaftFeature(Backend& backend, const LightShaftOptions& options)
    : backend_(backend), options_(options) {
    validate(options_);
    program_ = Owned<ProgramHandle>(backend, backend.createProgram(lightShaftProgram()));
    PipelineDesc p;
    p.name = "light shafts (additive)";
    p.program = program_.get();
    p.blend[0] = {true,         BlendFactor::One, BlendFactor::One, BlendOp::Add, BlendFactor::Zero, BlendFactor::One,
                  BlendOp::Add, WriteRGB};
    pipeline_ = Owned<PipelineHandle>(backend, backend.createPipeline(p));
    if (options_.skipWhenSunHidden) probe_ = std::make_unique<SunVisibilityProbe>(backend);
}

LightShaftFeature::~LightShaftFeature() = default;

bool LightShaftFeature::sunVisible() const { return !lastQuery_ || backend_.anySamplesPassed(*lastQuery_); }

engine::render::ColorDepth LightShaftFeature::addPasses(engine::render::FrameGraph& graph,
                                                        const engine::scene::FeatureFrame& frame,
                                                        const engine::render::ColorDepth& targets) {
    return addDrawPass(graph, frame, targets, !prepare(frame), DepthUse::Test,
                       [this](const engine::scene::FeatureFrame& f) { draw(f); });
}

bool LightShaftFeature::prepare(const engine::scene::FeatureFrame& frame) {
    ran_ = false;
    lastQuery_.reset();
    // The sun is a direction: a point at infinity (w = 0). Behind the camera: no shafts.
    const glm::vec3 toward = glm::normalize(frame.sun.towardLight);
    const glm::vec4 clip = frame.viewProj * glm::vec4(toward, 0.0f);
    if (!(clip.w > 1e-6f) || !std::isfinite(clip.x) || !std::isfinite(clip.y)) return false;
    sunPixel_ = {(clip.x / clip.w * 0.5f + 0.5f) * float(frame.width),
                 (0.5f - clip.y / clip.w * 0.5f) * float(frame.height)};
    return std::isfinite(sunPixel_.x) && std::isfinite(sunPixel_.y);
}

void LightShaftFeature::draw(const engine::scene::FeatureFrame& frame) {
    const bool greater = frame.depthFunc == CompareFunc::Greater || frame.depthFunc == CompareFunc::GreaterEqual;
    LightShaftParams params;
    params.depth = frame.depth;
    params.sunPixel = sunPixel_;
    params.farDepth = greater ? 0.0f : 1.0f;  // the depth clear value
    params.greaterIsCloser = greater;
    params.color = options_.color * frame.sun.color;
    params.intensity = options_.intensity;
    params.decay = options_.decay;
    params.density = options_.density;
    params.samples = options_.samples;
    params.glowRadius = options_.glowRadius * float(frame.height);
    PassDesc pass;
    pass.name = "light shafts";
    pass.color[0] = {frame.color, LoadOp::Load};
    if (probe_) {
        // A sample q adds light only when |q - sun| < glowRadius and its texel floor(q) is sky;
        // that texel's centre is within glowRadius + sqrt(2)/2 of the sun, so probing the
        // centres within glowRadius + 1 finds every texel that could add light.
        lastQuery_ =
            probe_->probe(frame.depth, frame.width, frame.height, frame.depthFunc, sunPixel_, params.glowRadius + 1.0f);
        if (!lastQuery_) return;  // the glow misses the frame: nothing to add
        pass.drawOnlyIfSamplesIn = *lastQuery_;
    }
    PassScope passScope(backend_, pass);
    DrawDesc d;
    d.pipeline = pipeline_;
    d.params = params;
    backend_.draw(d);
    passScope.end();
    ran_ = true;
}

}  // namespace lightshafts
