// SPDX-License-Identifier: MIT
// TemporalResolve's GLSL (transparency/temporal.hpp; soft: temporal_kernel.hpp), the jitter
// sequence and the reprojection matrix.
#include <cmath>
#include <string>

#include "engine/render/kernel/program_kernel.hpp"
#include "engine/render/shader_interface.hpp"
#include "temporal_kernel.hpp"
#include "transparency_glsl.hpp"  // generated from glsl/
#include "transparency/temporal.hpp"

namespace transparency {
namespace {

using namespace engine::render;

float halton(std::uint64_t index, std::uint64_t base) {
    float f = 1.0f, r = 0.0f;
    while (index > 0) {
        f /= float(base);
        r += f * float(index % base);
        index /= base;
    }
    return r;
}

}  // namespace

glm::vec2 haltonJitter(std::uint64_t frameIndex, int phases) {
    const std::uint64_t i = 1 + frameIndex % std::uint64_t(phases < 1 ? 1 : phases);
    // Rounded to 1/256 pixel (finer than the rasterizers' sub-pixel grids): a binary fraction,
    // so that a jittered and unjittered matrix differ by exactly the jitter.
    auto snap = [](float v) { return std::round(v * 256.0f) / 256.0f; };
    return {snap(halton(i, 2) - 0.5f), snap(halton(i, 3) - 0.5f)};
}

glm::mat4 jitteredViewProj(const glm::mat4& viewProj, glm::vec2 jitterPixels, int width, int height) {
    if (jitterPixels == glm::vec2(0.0f)) return viewProj;  // the same bits, not a product with the identity
    glm::mat4 j(1.0f);
    j[3][0] = 2.0f * jitterPixels.x / float(width);
    j[3][1] = -2.0f * jitterPixels.y / float(height);  // rows grow downwards
    return j * viewProj;
}

namespace {

// Pixel (centre coordinates) and depth to NDC: x = 2 px / w - 1, y = 1 - 2 py / h.
glm::dmat4 pixelsToNdc(double w, double h) {
    glm::dmat4 toNdc(1.0);
    toNdc[0][0] = 2.0 / w;
    toNdc[1][1] = -2.0 / h;
    toNdc[3][0] = -1.0;
    toNdc[3][1] = 1.0;
    return toNdc;
}

// Clip to pixel coordinates times w: px w = (x + w) * width / 2, py w = (w - y) * height / 2.
glm::dmat4 clipToPixels(double w, double h) {
    glm::dmat4 toPixels(1.0);
    toPixels[0][0] = w / 2.0;
    toPixels[1][1] = -h / 2.0;
    toPixels[3][0] = w / 2.0;
    toPixels[3][1] = h / 2.0;
    return toPixels;
}

bool allFinite(const glm::mat4& m) {
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(m[i][k])) return false;
    return true;
}

}  // namespace

bool reprojectionMatrix(const glm::mat4& current, const glm::mat4& previous, int width, int height, glm::mat4& out) {
    const glm::dmat4 c(current), p(previous);
    if (!(std::abs(glm::determinant(c)) > 0.0)) return false;
    const glm::dmat4 m = clipToPixels(width, height) * p * glm::inverse(c) * pixelsToNdc(width, height);
    out = glm::mat4(m);
    return allFinite(out);
}

bool motionReprojection(const glm::mat4& current, const glm::mat4& previous, int width, int height,
                        MotionReprojection& out) {
    const glm::dmat4 c(current), p(previous);
    if (!(std::abs(glm::determinant(c)) > 0.0)) return false;
    const glm::dmat4 toWorld = glm::inverse(c) * pixelsToNdc(width, height);
    out.previousToPixels = glm::mat4(clipToPixels(width, height) * p);
    out.worldW = glm::vec4(toWorld[0][3], toWorld[1][3], toWorld[2][3], toWorld[3][3]);
    glm::mat4 w(0.0f);
    w[0] = out.worldW;
    return allFinite(out.previousToPixels) && allFinite(w);
}

ProgramDesc temporalResolveProgram() {
    ProgramDesc d = describeProgram<TemporalResolveParams>("TemporalResolve", VertexInput::Fullscreen,
                                                           "transparency::TemporalResolveParams");
    d.gl.fragment = samplerDeclarations(d.gl) + glsl::kTemporalResolveFragment;
    d.check = [](const void* params, const DrawCheck& check) {
        const float blend = static_cast<const TemporalResolveParams*>(params)->blend;
        if (!(blend > 0.0f && blend <= 1.0f)) check.fail("blend " + std::to_string(blend) + " must be in (0, 1]");
    };
    d.soft = soft::makeKernel<TemporalResolveKernel, TemporalResolveParams>();
    return d;
}

}  // namespace transparency
