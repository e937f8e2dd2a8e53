// SPDX-License-Identifier: MIT
// The web page's build only (Emscripten, WebGL2; linked with --js-library): the extension entry
// points the GLES driver calls that Emscripten 3.1.6's GL library does not define, each calling
// the WebGL extension object's method of the same meaning on the current context (GLctx).
// Emscripten's context creation has already enabled every extension the browser offers, and the
// driver calls these only after it found the extension (gles_driver.cpp): EXT_clip_control
// (without it the vertex stages remap instead), OES_draw_buffers_indexed (blend state per target).
mergeInto(LibraryManager.library, {
  glClipControlEXT: function(origin, depth) {
    GLctx.getExtension('EXT_clip_control').clipControlEXT(origin, depth);
  },
  glEnableiOES: function(target, index) {
    GLctx.getExtension('OES_draw_buffers_indexed').enableiOES(target, index);
  },
  glDisableiOES: function(target, index) {
    GLctx.getExtension('OES_draw_buffers_indexed').disableiOES(target, index);
  },
  glBlendFuncSeparateiOES: function(buf, srcRgb, dstRgb, srcAlpha, dstAlpha) {
    GLctx.getExtension('OES_draw_buffers_indexed').blendFuncSeparateiOES(buf, srcRgb, dstRgb, srcAlpha, dstAlpha);
  },
  glBlendEquationSeparateiOES: function(buf, modeRgb, modeAlpha) {
    GLctx.getExtension('OES_draw_buffers_indexed').blendEquationSeparateiOES(buf, modeRgb, modeAlpha);
  },
  glColorMaskiOES: function(buf, r, g, b, a) {
    GLctx.getExtension('OES_draw_buffers_indexed').colorMaskiOES(buf, !!r, !!g, !!b, !!a);
  },
});
