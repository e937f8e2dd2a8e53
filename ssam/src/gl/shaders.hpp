// SPDX-License-Identifier: MIT
#pragma once
// GLSL sources of ssam_gl's three programs ([Hathaway 2010] Listings 3.1 and 3.2), without their
// first lines: glslHead() gives them (GLSL 3.30 core, or ES 3.00 for Api::Gles30) and
// detail::compileProgram() puts it first.
#include <string>

#include "ssam/gl/ssam_gl.hpp"

namespace ssam::gl::detail {
struct GlFunctions;
}

namespace ssam::gl::shaders {
// `#version 330 core`, or `#version 300 es` with highp defaults on OpenGL ES.
const char* glslHead(const detail::GlFunctions& gl);

// Shared by the mask and colour programs, reading the host's vertex arrays at `locations`.
std::string foliageVertex(const AttributeLocations& locations);
extern const std::string kMaskFragment;      // Listing 3.1: alpha only, replicated
extern const std::string kColorFragment;     // alpha-tested, double-sided lit colour
extern const std::string kFullscreenVertex;  // one triangle over the viewport
// The composite's inputs and ssamComposite() (core/glsl/composite.glsl), what every program reading
// the mask starts with.
extern const std::string kCompositeHead;
extern const std::string kCompositeFragment;  // Listing 3.2 as (foliage, mask) for SRC_ALPHA blending

// The uniforms kCompositeHead declares, in every program that starts with it (the composite and
// the depth restore).
struct CompositeInputs {
    int foliage = -1, mask = -1, maskAdd = -1, hasMaskAdd = -1, maskLerp = -1, square = -1, colorFade = -1,
        foliageClear = -1, colorBlur = -1;
    void locate(const detail::GlFunctions& gl, unsigned int program);
    // rt_foliage read from texture unit `foliageUnit`, the mask from unit 1 and the ADD mask (where
    // `hasMaskAdd`) from unit 2; the settings' mask lerp, squaring, colour fade and blur. The program must be in use.
    void set(const detail::GlFunctions& gl, int foliageUnit, bool hasMaskAdd, const Settings& settings) const;
};

}  // namespace ssam::gl::shaders
