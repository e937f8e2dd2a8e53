// SPDX-License-Identifier: MIT
#include "sun_visibility.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/render/pass_scope.hpp"
#include "engine/render/vertex.hpp"

namespace lightshafts {

using namespace engine::render;

namespace {

// A regular polygon circumscribing the unit circle, as a triangle list around the centre:
// it covers every point of the disc, so no pixel centre inside the disc is missed.
constexpr int kDiscSides = 64;

std::array<Vertex, 3 * kDiscSides> circumscribedDisc() {
    const double step = 2.0 * std::numbers::pi / kDiscSides;
    const double corner = 1.0 / std::cos(step / 2.0);
    std::array<Vertex, 3 * kDiscSides> v{};
    for (int i = 0; i < kDiscSides; ++i) {
        const double a0 = step * i, a1 = step * (i + 1);
        v[3 * i + 1].position = {float(corner * std::cos(a0)), float(corner * std::sin(a0)), 0.0f};
        v[3 * i + 2].position = {float(corner * std::cos(a1)), float(corner * std::sin(a1)), 0.0f};
    }
    return v;
}

Owned<PipelineHandle> probePipeline(Backend& backend, CompareFunc func) {
    PipelineDesc p;
    p.name = "light shafts: sun visibility";
    p.program = ProgramKind::Flat;
    p.depth = DepthState::testOnly(func);
    return Owned<PipelineHandle>(backend, backend.createPipeline(p));
}

Owned<BufferHandle> discBuffer(Backend& backend) {
    const auto disc = circumscribedDisc();
    const auto bytes = std::as_bytes(std::span(disc));
    return Owned<BufferHandle>(
        backend, backend.createBuffer({"light shafts: sun disc", BufferKind::Vertex, bytes.size()}, bytes));
}

}  // namespace

SunVisibilityProbe::SunVisibilityProbe(Backend& backend)
    : backend_(backend),
      // The probe sits on the far plane and passes where the stored depth is at least as far:
      // only where the clear value (sky) is left.
      standardZ_(probePipeline(backend, CompareFunc::LessEqual)),
      reverseZ_(probePipeline(backend, CompareFunc::GreaterEqual)),
      query_(backend, backend.createQuery("light shafts: sun visible")), disc_(discBuffer(backend)) {}

std::optional<QueryHandle> SunVisibilityProbe::probe(TextureHandle depth, int width, int height, CompareFunc depthFunc,
                                                     glm::vec2 sunPixel, float radius) {
    // The nearest point of the frame to the sun: farther than the radius, no pixel is near.
    const glm::vec2 nearest = glm::clamp(sunPixel, glm::vec2(0.0f), glm::vec2(float(width), float(height)));
    if (!(glm::length(nearest - sunPixel) < radius)) return std::nullopt;

    const bool reverse = depthFunc == CompareFunc::Greater || depthFunc == CompareFunc::GreaterEqual;
    // Pixels to clip space: the inverse of the mapping the light-shafts pass places the sun
    // with (row 0 at the top), and z on the far plane (depth 1, or 0 under reverse-Z).
    const glm::vec3 centre(2.0f * sunPixel.x / float(width) - 1.0f, 1.0f - 2.0f * sunPixel.y / float(height),
                           reverse ? 0.0f : 1.0f);
    const glm::vec3 scale(2.0f * radius / float(width), 2.0f * radius / float(height), 1.0f);
    FlatParams params;
    params.viewProj = glm::scale(glm::translate(glm::mat4(1.0f), centre), scale);

    PassDesc pass;
    pass.name = "light shafts: sun visibility";
    pass.depth = {depth, LoadOp::Load};
    pass.countSamplesInto = query_.get();
    PassScope passScope(backend_, pass);
    DrawDesc d;
    d.pipeline = reverse ? reverseZ_.get() : standardZ_.get();
    d.params = params;
    d.vertices = disc_;
    d.count = 3 * kDiscSides;
    backend_.draw(d);
    passScope.end();
    return query_.get();
}

}  // namespace lightshafts
