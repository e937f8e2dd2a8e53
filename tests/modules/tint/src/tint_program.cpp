// SPDX-License-Identifier: MIT
#include "tint/tint_program.hpp"

#include <cmath>
#include <cstddef>

#include "engine/render/kernel/program_kernel.hpp"
#include "tint_kernel.hpp"

namespace tint {
namespace {

using namespace engine::render;

constexpr const char* kFragment = R"(
void main() {
    finish(vec4(u_tint, 1.0));
}
)";

void check(const void* params, const DrawCheck& check) {
    const glm::vec3 c = static_cast<const TintParams*>(params)->color;
    for (float v : {c.r, c.g, c.b})
        if (!(v >= 0.0f && v <= 1.0f)) check.fail("tint colour channel " + std::to_string(v) + " not in [0, 1]");
}

}  // namespace

ProgramDesc tintProgram() {
    ProgramDesc d = describeProgram<TintParams>("Tint", VertexInput::Fullscreen, "tint::TintParams");
    d.gl.fragment = kFragment;
    d.gl.uniforms = {{"u_tint", UniformType::Vec3, offsetof(TintParams, color)}};
    d.check = check;
    d.soft = soft::makeKernel<TintKernel, TintParams>();
    return d;
}

}  // namespace tint
