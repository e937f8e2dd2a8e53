// SPDX-License-Identifier: MIT
#pragma once
// The OpenGL entry points ssam::gl calls, resolved once through the host's own loader into a
// table (the adopted-context pattern: SSAM links no GL library and never looks for one; the
// host's context and loader decide which driver answers). Only types and PFN... typedefs come
// from the Khronos header: nothing here is a GL implementation.
#include <GL/glcorearb.h>

#include <string>

#include "engine/render/gl/plumbing/build_program.hpp"
#include "ssam/gl/ssam_gl.hpp"

namespace ssam::gl::detail {

// OpenGL 3.3 core and OpenGL ES 3.0 alike: ssam::gl needs every one of these, and those of
// ENGINE_GL_PROGRAM_FUNCTIONS (GlFunctions' base, which the engine's shared program builder takes).
#define SSAM_GL_REQUIRED_FUNCTIONS(X)                                                    \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                             \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                                   \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                         \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                                       \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                                 \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                         \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation)                                             \
    X(PFNGLBLENDEQUATIONSEPARATEPROC, BlendEquationSeparate)                             \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                                     \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                                         \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                           \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                                             \
    X(PFNGLCOLORMASKPROC, ColorMask)                                                     \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                                   \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                           \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                                   \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                     \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                                     \
    X(PFNGLDISABLEPROC, Disable)                                                         \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                   \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                                 \
    X(PFNGLENABLEPROC, Enable)                                                           \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                         \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                               \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                         \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                                 \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                         \
    X(PFNGLGETBOOLEANVPROC, GetBooleanv)                                                 \
    X(PFNGLGETERRORPROC, GetError)                                                       \
    X(PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC, GetFramebufferAttachmentParameteriv) \
    X(PFNGLGETINTEGERI_VPROC, GetIntegeri_v)                                             \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                                 \
    X(PFNGLGETRENDERBUFFERPARAMETERIVPROC, GetRenderbufferParameteriv)                   \
    X(PFNGLGETSTRINGPROC, GetString)                                                     \
    X(PFNGLGETSTRINGIPROC, GetStringi)                                                   \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                   \
    X(PFNGLGETVERTEXATTRIBFVPROC, GetVertexAttribfv)                                     \
    X(PFNGLISENABLEDPROC, IsEnabled)                                                     \
    X(PFNGLISRENDERBUFFERPROC, IsRenderbuffer)                                           \
    X(PFNGLISTEXTUREPROC, IsTexture)                                                     \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                                                   \
    X(PFNGLSCISSORPROC, Scissor)                                                         \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                   \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                             \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                                     \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                                     \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                                                     \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                                   \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                                                     \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                                       \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                                   \
    X(PFNGLVERTEXATTRIB2FPROC, VertexAttrib2f)                                           \
    X(PFNGLVERTEXATTRIB3FPROC, VertexAttrib3f)                                           \
    X(PFNGLVERTEXATTRIB4FPROC, VertexAttrib4f)                                           \
    X(PFNGLVERTEXATTRIB4FVPROC, VertexAttrib4fv)                                         \
    X(PFNGLVIEWPORTPROC, Viewport)

// OpenGL 3.3 but not ES 3.0: required on desktop GL (Api::Gl33). On ES they are ES 3.1 / 3.2 or
// OES_draw_buffers_indexed's (looked up as optional ones) and used only where `indexedBuffers`.
#define SSAM_GL_DESKTOP_FUNCTIONS(X)         \
    X(PFNGLCOLORMASKIPROC, ColorMaski)       \
    X(PFNGLDISABLEIPROC, Disablei)           \
    X(PFNGLENABLEIPROC, Enablei)             \
    X(PFNGLGETBOOLEANI_VPROC, GetBooleani_v) \
    X(PFNGLISENABLEDIPROC, IsEnabledi)       \
    X(PFNGLGETTEXLEVELPARAMETERIVPROC, GetTexLevelParameteriv)

// Newer than 3.3, used when the context has them: per-buffer blending (GL 4.0 or
// GL_ARB_draw_buffers_blend, whose names end in ARB) for the Rg16f mask, immutable storage
// (GL 4.2 or GL_ARB_texture_storage, same names); glClampColor for compatibility contexts.
#define SSAM_GL_OPTIONAL_FUNCTIONS(X)                          \
    X(PFNGLCLAMPCOLORPROC, ClampColor)                         \
    X(PFNGLBLENDEQUATIONIPROC, BlendEquationi)                 \
    X(PFNGLBLENDEQUATIONSEPARATEIPROC, BlendEquationSeparatei) \
    X(PFNGLBLENDFUNCSEPARATEIPROC, BlendFuncSeparatei)         \
    X(PFNGLTEXSTORAGE2DPROC, TexStorage2D)

struct GlFunctions : engine::render::gl::plumbing::ProgramFunctions {
#define SSAM_GL_DECLARE(type, name) type name = nullptr;
    SSAM_GL_REQUIRED_FUNCTIONS(SSAM_GL_DECLARE)
    SSAM_GL_DESKTOP_FUNCTIONS(SSAM_GL_DECLARE)
    SSAM_GL_OPTIONAL_FUNCTIONS(SSAM_GL_DECLARE)
#undef SSAM_GL_DECLARE

    // What the current context offers (set by checkContext()).
    bool es = false;  // Api::Gles30: `#version 300 es`, only ES 3.0's state and queries
    int version = 0;  // major * 10 + minor
    // Enable/Disable/IsEnabled/ColorMask/GetBoolean per draw buffer (GL 3.0; ES 3.2 or
    // OES_draw_buffers_indexed); without them the global ones set every draw buffer alike.
    bool indexedBuffers = true;
    bool colorBufferFloat = true;  // 16F / 32F colour targets (GL 3.0; ES: GL_EXT_color_buffer_float)
    bool floatBlend = true;        // blending into 32F targets (GL 3.0; ES: GL_EXT_float_blend)
    bool perBufferBlend = false;   // BlendEquationi & co. are usable
    bool textureStorage = false;   // TexStorage2D is usable
    bool clipControl = false;      // GL_CLIP_ORIGIN / GL_CLIP_DEPTH_MODE can be queried
    bool compatibility = false;    // a compatibility profile: fixed-function state exists (below)

    bool hasExtension(const char* name) const;

    // Draw buffer `buffer`'s colour mask: per buffer where the context has it, else (buffer 0) the
    // global one, which is every buffer's.
    void colorMaskAt(GLuint buffer, GLboolean r, GLboolean g, GLboolean b, GLboolean a) const;
};

// The host's loader, in either of its shapes.
struct Loader {
    GetProcAddress returningPointer = nullptr;
    GetProcAddressFunction returningFunction = nullptr;
    using AnyFunction = void (*)();
    AnyFunction operator()(const char* name) const;
};

// Resolves every entry point through the host's loader. Throws Failure(MissingEntryPoint) naming
// the first required function without an address; optional ones are looked up under their core
// name, then their ARB (desktop) or OES and EXT (ES) names.
void loadFunctions(GlFunctions& gl, const Loader& load, Api api);

// Compatibility-profile state that acts on shader output (GL 4.5 compatibility §17.3.5 alpha test,
// §14.6.2 polygon stipple, §18.2.6 fragment colour clamping); not in <GL/glcorearb.h>.
constexpr GLenum kAlphaTest = 0x0BC0;
constexpr GLenum kPolygonStipple = 0x0B42;
constexpr GLenum kClampFragmentColor = 0x891B;
constexpr GLenum kFixedOnly = 0x891D;

// Throws Failure(NoContext) unless a GL 3.3+ context (core or compatibility; Api::Gles30: ES 3.0+) is
// current (glGetString answers), Failure(InvalidArgument) when it is of the other API; fills
// version and the optional capabilities. Returns the context's description for the log.
std::string checkContext(GlFunctions& gl, Api api);

}  // namespace ssam::gl::detail
