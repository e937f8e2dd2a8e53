// SPDX-License-Identifier: MIT
#pragma once
// The GL declarations the GL 4.5 and GLES drivers' sources compile against, and the three
// questions they ask of the current context (API, version, extensions).
//   Natively: libepoxy (every entry point resolved on its first call, desktop GL or ES alike).
//   In the web page's WebAssembly build (__EMSCRIPTEN__, only the GLES driver and the shared
//   sources it uses): Emscripten's GLES 3.0 headers, whose calls its WebGL2 library implements;
//   the extension entry points that library lacks (EXT_clip_control, OES_draw_buffers_indexed)
//   are defined in the GLES driver's gles_web_entry_points.js.
#if defined(__EMSCRIPTEN__)
#define GL_GLEXT_PROTOTYPES 1
#include <GLES3/gl3.h>
// GLES3/gl3.h's guard also stands for GLES2/gl2.h, which gl2ext.h needs for its types
#include <GLES2/gl2ext.h>
#else
#include <epoxy/gl.h>
#endif

namespace engine::render::gl {

// Whether the current context is desktop OpenGL (false: OpenGL ES, WebGL2).
bool glIsDesktop();
// The current context's version as 10 * major + minor (45: 4.5, 30: ES 3.0 and WebGL2).
int glVersion();
// Whether the current context offers the extension ("GL_EXT_clip_control"; WebGL's names are
// asked with the same "GL_" prefix).
bool glHasExtension(const char* name);

}  // namespace engine::render::gl
