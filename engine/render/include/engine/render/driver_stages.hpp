// SPDX-License-Identifier: MIT
#pragma once
// The GLSL every GLSL-consuming driver (GL, Vulkan) puts around a program's body, written
// once: the mesh and full-screen vertex stages, the fragment stage's head (outputs, the shared
// tail's inputs, finish(), the interpolants, the layout's declarations) and the drivers' own
// MSAA resolves. The dialect decides only what differs by API: the version line, the
// built-in index names (gl_InstanceID / gl_InstanceIndex) and how inputs are declared, by the
// rule of shader_interface.hpp (GL: loose uniforms; Vulkan: a std140 block or push constants).
#include <string>
#include <string_view>

#include "engine/render/program_desc.hpp"
#include "engine/render/shader_interface.hpp"

namespace engine::render {

// Vulkan descriptor sets of a program: 0 holds the textures (binding = TextureField::unit),
// 1 the uniform block (GL has neither: units and loose uniforms).
inline constexpr int kVulkanTextureSet = 0;
inline constexpr int kVulkanUniformSet = 1;

// The vertex stage of a program with this input and layout. A Mesh program's layout must hold
// u_viewProj (mat4); Error naming the program otherwise.
std::string vertexStage(GlslDialect dialect, VertexInput input, const std::string& programName,
                        const UniformBlockLayout& layout);

// The fragment stage: the head before the program's body. `colorTargets` outputs are
// declared as such; finish() writes the other o_color variables too, so they are declared as
// plain variables (GL declares all four as outputs: unbound ones are dropped by the API).
// `meshEntry`: statements a driver runs first in a Mesh program's main() (its own workarounds,
// none of a program's business): the body's main() is renamed programMain() and called after them.
std::string fragmentStage(GlslDialect dialect, VertexInput input, const UniformBlockLayout& layout,
                          const std::string& body, int colorTargets, std::string_view meshEntry = {});

// The drivers' resolves, complete fragment stages for the full-screen vertex stage. Both read
// the multisampled source at binding 0 and the parameters u_samples (int) and u_greater (int,
// non-zero: larger depth is closer); GL sets them as uniforms, Vulkan as push constants.
// Colour: the average of the samples in the linear domain, summed in sample order as the soft
// backend does; depth: the closest sample ([Hathaway 2010] §3.5.1), never an average.
std::string resolveColorStage(GlslDialect dialect);
std::string resolveDepthStage(GlslDialect dialect);

}  // namespace engine::render
