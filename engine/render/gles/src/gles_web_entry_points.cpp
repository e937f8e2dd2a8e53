// SPDX-License-Identifier: MIT
// The web page's build only (Emscripten, WebGL2): the extension entry points the driver calls
// that Emscripten 3.1.6's GL library does not define, each calling the WebGL extension object's
// method of the same meaning on the current context (GLctx). Emscripten's context creation has
// already enabled every extension the browser offers, and the driver calls these only after it
// found the extension (gles_driver.cpp): EXT_clip_control (required), OES_draw_buffers_indexed.
#include <emscripten/emscripten.h>

#include "gl_api.hpp"

// clang-format off
EM_JS(void, glClipControlEXT, (GLenum origin, GLenum depth), {
    GLctx.getExtension('EXT_clip_control').clipControlEXT(origin, depth);
});
EM_JS(void, glEnableiOES, (GLenum target, GLuint index), {
    GLctx.getExtension('OES_draw_buffers_indexed').enableiOES(target, index);
});
EM_JS(void, glDisableiOES, (GLenum target, GLuint index), {
    GLctx.getExtension('OES_draw_buffers_indexed').disableiOES(target, index);
});
EM_JS(void, glBlendFuncSeparateiOES, (GLuint buf, GLenum srcRgb, GLenum dstRgb, GLenum srcAlpha, GLenum dstAlpha), {
    GLctx.getExtension('OES_draw_buffers_indexed').blendFuncSeparateiOES(buf, srcRgb, dstRgb, srcAlpha, dstAlpha);
});
EM_JS(void, glBlendEquationSeparateiOES, (GLuint buf, GLenum modeRgb, GLenum modeAlpha), {
    GLctx.getExtension('OES_draw_buffers_indexed').blendEquationSeparateiOES(buf, modeRgb, modeAlpha);
});
EM_JS(void, glColorMaskiOES, (GLuint buf, GLboolean r, GLboolean g, GLboolean b, GLboolean a), {
    GLctx.getExtension('OES_draw_buffers_indexed').colorMaskiOES(buf, !!r, !!g, !!b, !!a);
});
// clang-format on
