// SPDX-License-Identifier: MIT
#include "tint/tint_program.hpp"

#include <cmath>

#include "engine/render/kernel/program_kernel.hpp"
#include "tint_glsl.hpp"  // generated from glsl/
#include "tint_kernel.hpp"

namespace tint {
namespace {

using namespace engine::render;

void check(const void* params, const DrawCheck& check) {
    const glm::vec3 c = static_cast<const TintParams*>(params)->color;
    for (float v : {c.r, c.g, c.b})
        if (!(v >= 0.0f && v <= 1.0f)) check.fail("tint colour channel " + std::to_string(v) + " not in [0, 1]");
}

}  // namespace

ProgramDesc tintProgram() {
    ProgramDesc d = describeProgram<TintParams>("Tint", VertexInput::Fullscreen, "tint::TintParams");
    d.gl.fragment = glsl::kTintFragment;
    d.check = check;
    d.soft = soft::makeKernel<TintKernel, TintParams>();
    return d;
}

}  // namespace tint
