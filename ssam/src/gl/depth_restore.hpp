// SPDX-License-Identifier: MIT
#pragma once
// Settings::depthMaskThreshold: the foliage depth kept only where the composited mask is high.
// The colour pass must write the host's depth to find the nearest surviving fragment (§3.5.3),
// and writes it wherever the leaf passes the alpha test (§3.7), also where the composite then
// shows mostly what is behind the leaf; a later transparent pass behind such an edge is cut
// there, and a rim of the unblended background shows round the leaves. With a threshold the
// opaque depth is copied before the colour pass and written back after the composite wherever
// the mask is below it: one depth copy and one full-screen depth-only pass, both scissored to
// the foliage's region.
#include "shaders.hpp"
#include "ssam/gl/ssam_gl.hpp"

namespace ssam::gl::detail {

struct GlFunctions;
class FrameTargets;

class DepthRestore {
public:
    void destroy(const GlFunctions& gl);  // every GL object (none until first used)

    // Before the colour pass: the host's opaque depth, attached to `source`, copied over `region`
    // into a texture of the same format (made or remade here). Binds the read and draw framebuffers.
    void saveOpaqueDepth(const GlFunctions& gl, unsigned int source, int depthFormat, int width, int height,
                         const Rect& region);
    // After the composite, with its state (scissor, textures of units 0-2, SSAM's empty VAO bound):
    // the saved depth written back into the host's depth (attached to `target`, whose colour
    // attachment is not written) wherever the composited mask is below the settings' threshold.
    // Changes the program, unit 3's texture, the draw framebuffer, depth and colour-mask state.
    void restoreWhereMaskIsLow(const GlFunctions& gl, unsigned int target, bool hasMaskAdd, const Settings& settings);

private:
    unsigned int program_ = 0, texture_ = 0, framebuffer_ = 0;
    int width_ = 0, height_ = 0, format_ = 0;
    shaders::CompositeInputs composite_;
    int opaqueDepth_ = -1, threshold_ = -1;
};

}  // namespace ssam::gl::detail
