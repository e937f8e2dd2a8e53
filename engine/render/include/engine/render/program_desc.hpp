// SPDX-License-Identifier: MIT
#pragma once
// Programs are data (Filament's DriverAPI createProgram, sokol_gfx's shader descriptors): a
// module describes its program once, for every backend, and hands the description to
// Backend::createProgram. The render layer knows no effect; it runs what it is given:
//   - for GL, a GLSL fragment stage and the layout of the parameter struct's uniforms and
//     textures, which the driver uploads from each draw's DrawParams;
//   - for the soft backend, a CPU kernel written against the program-authoring library
//     (engine/render/kernel/), which instantiates the tile rasterizer for the program
//     in the module's own translation unit (no virtual call per fragment).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/render/draw_params.hpp"
#include "engine/render/texture.hpp"

namespace engine::render {

namespace soft {
class ProgramKernel;  // engine/render/kernel/program_kernel.hpp
}

// What the vertex stage is. Mesh: the engine's Vertex and Instance layout (vertex.hpp),
// transformed by the viewProj the program's parameters carry (GL: uniform u_viewProj).
// Fullscreen: one triangle over the viewport, no vertex input; the fragment stage reads
// its textures at its own pixel.
enum class VertexInput : std::uint8_t { Mesh, Fullscreen };

// One uniform of a GLSL program, read from the parameter struct at `offset`.
enum class UniformType : std::uint8_t {
    Float,      // float
    Int,        // int
    Bool,       // bool (GLSL bool / int)
    Byte,       // std::uint8_t, e.g. an enum class : std::uint8_t (GLSL int)
    Vec2,       // glm::vec2
    Vec3,       // glm::vec3
    Vec4,       // glm::vec4
    Mat4,       // glm::mat4, column-major
    Direction,  // glm::vec3, normalised by the driver as glm::normalize does on the CPU
};
struct UniformField {
    const char* name = "";
    UniformType type = UniformType::Float;
    std::size_t offset = 0;  // offsetof(Params, member)
};

// How a program reads a texture its parameters name.
enum class TextureRead : std::uint8_t {
    Texel,    // a TextureHandle read with texelFetch (no sampler object, no filtering)
    Sampled,  // a TextureBinding, filtered with its sampler state
};
// What the texture must be for the draw to be valid (checked on every backend alike).
enum class TextureUse : std::uint8_t {
    Sampled,   // single-sampled and not a target of the pass
    FullSize,  // as Sampled, and at least the target's size: read at every target pixel
};
struct TextureField {
    const char* name = "";   // the GLSL sampler, for messages
    std::size_t offset = 0;  // offsetof the TextureHandle (Texel) or TextureBinding (Sampled)
    int unit = 0;            // the GLSL layout(binding = unit)
    TextureRead read = TextureRead::Texel;
    TextureUse use = TextureUse::Sampled;
    bool optional = false;                       // a null handle is allowed (the program reads presentUniform)
    const char* presentUniform = nullptr;        // set to whether the handle is non-null
    const char* filterUniform = nullptr;         // Sampled: the binding's Filter, as an int
    const char* premultipliedUniform = nullptr;  // Sampled: whether the texture is premultiplied
};

struct GlslProgram {
    // The fragment stage's body, ending in finish(color). The driver puts before it the version
    // line, the outputs and finish(vec4) (alpha test, alpha-to-coverage, every target written),
    // a Mesh program's interpolants (v_uv, v_normal, v_color: what its vertex stage writes) and
    // the uniforms of `uniforms` and `textures`: the body declares none of them, only its
    // samplers (shader_interface.hpp states the rule, the same for GL and Vulkan).
    std::string fragment;
    std::vector<UniformField> uniforms;
    std::vector<TextureField> textures;
};

// Checks of a draw's parameters beyond their textures, made by every backend before the
// draw is recorded: fail() throws engine::Error naming the draw, pipeline and pass.
class DrawCheck {
public:
    virtual ~DrawCheck() = default;
    [[noreturn]] virtual void fail(const std::string& message) const = 0;
    virtual const TextureDesc& texture(TextureHandle texture) const = 0;
    virtual const TextureDesc& sampled(TextureHandle texture) const = 0;  // TextureUse::Sampled's checks
    virtual int targetWidth() const = 0;
    virtual int targetHeight() const = 0;
};

struct ProgramDesc {
    std::string name;
    VertexInput vertexInput = VertexInput::Mesh;
    ParamsType params = nullptr;  // paramsType<P>() of the struct its draws pass
    const char* paramsName = "";  // that struct's name, for messages
    GlslProgram gl;
    std::shared_ptr<const soft::ProgramKernel> soft;
    // Optional: checks of the parameters (ranges, finiteness, texture formats), made after
    // the textures' own checks; `params` points at the draw's struct.
    std::function<void(const void* params, const DrawCheck& check)> check;
};

// What every description states first: a program `name` whose draws pass a `Params`. A Params
// declared by ENGINE_PARAM_BLOCK (param_block.hpp) also gives gl.uniforms and gl.textures.
template <typename Params>
ProgramDesc describeProgram(std::string name, VertexInput input, const char* paramsName) {
    ProgramDesc d;
    d.name = std::move(name);
    d.vertexInput = input;
    d.params = paramsType<Params>();
    d.paramsName = paramsName;
    if constexpr (requires { Params::describe(d.gl); }) Params::describe(d.gl);
    return d;
}

// The lit surface's uniforms and base-colour texture (glsl/lit_surface.hpp) for any Params
// with its members viewProj, baseColorFactor, baseColor and light: the standard lit programs
// use it, and modules whose programs shade that surface (WBOIT's accumulation).
template <typename Params>
void litSurfaceLayout(GlslProgram& gl) {
    gl.uniforms = {
        {"u_viewProj", UniformType::Mat4, offsetof(Params, viewProj)},
        {"u_color", UniformType::Vec4, offsetof(Params, baseColorFactor)},
        {"u_towardLight", UniformType::Direction, offsetof(Params, light.towardLight)},
        {"u_lightColor", UniformType::Vec3, offsetof(Params, light.color)},
        {"u_ambient", UniformType::Vec3, offsetof(Params, light.ambient)},
    };
    gl.textures = {{"u_baseColor", offsetof(Params, baseColor), 0, TextureRead::Sampled, TextureUse::Sampled, true,
                    "u_hasTexture", "u_filter", "u_premultiplied"}};
}

}  // namespace engine::render
