// SPDX-License-Identifier: MIT
#pragma once
// A program's parameter block declared once (an X-macro): the one list from which come the C++
// struct its draws pass (and its CPU kernel reads), the uniform and texture table of its
// GlslProgram (what the GL and Vulkan drivers upload and declare, shader_interface.hpp) and the
// samplers its GLSL body reads. Adding a uniform is one edit: a line in the list.
//
//   #define TINT_PARAMS(UNIFORM, DIRECTION, TEXTURE)  (then one member a line, each but the
//       UNIFORM(glm::vec3, color, glm::vec3(1.0f))    last ending in a backslash)
//       TEXTURE(source, Texel, FullSize, Required)
//   ENGINE_PARAM_BLOCK(TintParams, TINT_PARAMS);
//
// gives `struct TintParams { glm::vec3 color = glm::vec3(1.0f); TextureHandle source{}; ... }`,
// TintParams::describe(gl) filling gl.uniforms with {"u_color", Vec3, offsetof(TintParams,
// color)} and gl.textures with {"u_source", offsetof(TintParams, source), unit 0, Texel,
// FullSize}, and samplerDeclarations(gl) (shader_interface.hpp) writing `layout(binding = 0) uniform sampler2D
// u_source;` for the body. The three kinds of line:
//   UNIFORM(type, name, default)   a uniform `u_<name>`; its UniformType follows from the C++ type
//                                  (float, int, bool, std::uint8_t or a one-byte enum, glm::vec2/3/4,
//                                  glm::mat4)
//   DIRECTION(name, default)       a glm::vec3 the drivers normalise (UniformType::Direction)
//   TEXTURE(name, read, use, presence)
//                                  a sampler `u_<name>` at the next unit (0, 1, ...): read Texel
//                                  (a TextureHandle) or Sampled (a TextureBinding, whose filter
//                                  and premultiplication the drivers pass as u_<name>Filter and
//                                  u_<name>Premultiplied), use Sampled or FullSize (TextureUse),
//                                  presence Required or Optional (a null handle allowed, bool
//                                  u_<name>Bound says which)
// A default may not contain an unparenthesised comma: glm::vec2(0.0f, 1.0f), not {0.0f, 1.0f}.
// Comments in the list are /* */ (a // comment would swallow the line's backslash).
//
// Why an X-macro and not constexpr reflection: C++20 cannot list a struct's members, so a
// reflection table (member pointers) would name each member a second time beside the struct,
// two edits per uniform; the list is also plain text a reader greps, and expands to the same
// struct a hand-written one would be (kernels compile to the same code).
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <glm/glm.hpp>

#include "engine/render/program_desc.hpp"

namespace engine::render {

// The UniformType a member of C++ type T is uploaded as.
template <typename T>
constexpr UniformType uniformTypeOf() {
    if constexpr (std::is_same_v<T, float>) return UniformType::Float;
    else if constexpr (std::is_same_v<T, int>) return UniformType::Int;
    else if constexpr (std::is_same_v<T, bool>) return UniformType::Bool;
    else if constexpr (std::is_same_v<T, std::uint8_t> || (std::is_enum_v<T> && sizeof(T) == 1))
        return UniformType::Byte;
    else if constexpr (std::is_same_v<T, glm::vec2>) return UniformType::Vec2;
    else if constexpr (std::is_same_v<T, glm::vec3>) return UniformType::Vec3;
    else if constexpr (std::is_same_v<T, glm::vec4>) return UniformType::Vec4;
    else if constexpr (std::is_same_v<T, glm::mat4>) return UniformType::Mat4;
    else static_assert(sizeof(T) == 0, "a parameter block's uniform has no GLSL type for this C++ type");
}

// The member a TEXTURE line declares: the handle texelFetch reads, or a handle with its sampler.
template <TextureRead Read>
using TextureParam = std::conditional_t<Read == TextureRead::Texel, TextureHandle, TextureBinding>;

enum class TexturePresence : std::uint8_t { Required, Optional };

namespace param_block {

// One TEXTURE line's field; the names point into the string literals the macro writes.
inline TextureField textureField(const char* name, std::size_t offset, int unit, TextureRead read, TextureUse use,
                                 TexturePresence presence, const char* bound, const char* filter,
                                 const char* premultiplied) {
    TextureField f{name, offset, unit, read, use};
    if (presence == TexturePresence::Optional) {
        f.optional = true;
        f.presentUniform = bound;
    }
    if (read == TextureRead::Sampled) {
        f.filterUniform = filter;
        f.premultipliedUniform = premultiplied;
    }
    return f;
}

}  // namespace param_block

}  // namespace engine::render

// The struct's members.
#define ENGINE_PARAM_MEMBER(type, name, init) type name = init;
#define ENGINE_PARAM_DIRECTION_MEMBER(name, init) glm::vec3 name = init;
#define ENGINE_PARAM_TEXTURE_MEMBER(name, read, use, presence) \
    ::engine::render::TextureParam<::engine::render::TextureRead::read> name{};
// The table's entries (statements of describe(), which is where the struct is complete).
#define ENGINE_PARAM_UNIFORM_ENTRY(type, name, init) \
    gl.uniforms.push_back({"u_" #name, ::engine::render::uniformTypeOf<type>(), offsetof(Self, name)});
#define ENGINE_PARAM_DIRECTION_ENTRY(name, init) \
    gl.uniforms.push_back({"u_" #name, ::engine::render::UniformType::Direction, offsetof(Self, name)});
#define ENGINE_PARAM_TEXTURE_ENTRY(name, read, use, presence)                                               \
    gl.textures.push_back(::engine::render::param_block::textureField(                                      \
        "u_" #name, offsetof(Self, name), unit++, ::engine::render::TextureRead::read,                      \
        ::engine::render::TextureUse::use, ::engine::render::TexturePresence::presence, "u_" #name "Bound", \
        "u_" #name "Filter", "u_" #name "Premultiplied"));

// struct Name from LIST(UNIFORM, DIRECTION, TEXTURE), with
//   static void describe(GlslProgram& gl): gl.uniforms and gl.textures, in the list's order.
// describeProgram<Name>() calls describe() itself.
#define ENGINE_PARAM_BLOCK(Name, LIST)                                                                 \
    struct Name {                                                                                      \
        LIST(ENGINE_PARAM_MEMBER, ENGINE_PARAM_DIRECTION_MEMBER, ENGINE_PARAM_TEXTURE_MEMBER)          \
        static void describe(::engine::render::GlslProgram& gl) {                                      \
            using Self = Name;                                                                         \
            [[maybe_unused]] int unit = 0;                                                             \
            gl.uniforms.clear();                                                                       \
            gl.textures.clear();                                                                       \
            LIST(ENGINE_PARAM_UNIFORM_ENTRY, ENGINE_PARAM_DIRECTION_ENTRY, ENGINE_PARAM_TEXTURE_ENTRY) \
        }                                                                                              \
    }

// struct Name on the lit surface (glsl/lit_surface.glsl, program_desc.hpp's litSurfaceLayout):
// the surface's members viewProj, baseColorFactor, baseColor (unit 0) and light first, then the
// list's, whose textures take units 1, 2, ...; describe() gives the surface's table, then the
// list's. The programs that shade the engine's surface (OpaqueLit, MaskedLit) and build on it.
#define ENGINE_PARAM_BLOCK_ON_LIT_SURFACE(Name, LIST)                                                  \
    struct Name {                                                                                      \
        glm::mat4 viewProj{1.0f};                                                                      \
        glm::vec4 baseColorFactor{1.0f};                                                               \
        ::engine::render::TextureBinding baseColor; /* null texture: white */                          \
        ::engine::render::DirectionalLight light;                                                      \
        LIST(ENGINE_PARAM_MEMBER, ENGINE_PARAM_DIRECTION_MEMBER, ENGINE_PARAM_TEXTURE_MEMBER)          \
        static void describe(::engine::render::GlslProgram& gl) {                                      \
            using Self = Name;                                                                         \
            [[maybe_unused]] int unit = 1;                                                             \
            ::engine::render::litSurfaceLayout<Self>(gl);                                              \
            LIST(ENGINE_PARAM_UNIFORM_ENTRY, ENGINE_PARAM_DIRECTION_ENTRY, ENGINE_PARAM_TEXTURE_ENTRY) \
        }                                                                                              \
    }

// A list with no members of its own (a block that is the lit surface alone).
#define ENGINE_NO_PARAMS(UNIFORM, DIRECTION, TEXTURE)
