// SPDX-License-Identifier: MIT
#pragma once
// GLSL 3.30 core sources of ssam_gl's three programs ([Hathaway 2010] Listings 3.1 and 3.2).
#include <string>

#include "ssam/gl/ssam_gl.hpp"

namespace ssam::gl::shaders {

// Shared by the mask and colour programs, reading the host's vertex arrays at `locations`.
std::string foliageVertex(const AttributeLocations& locations);
extern const std::string kMaskFragment;      // Listing 3.1: alpha only, replicated
extern const std::string kColorFragment;     // alpha-tested, double-sided lit colour
extern const std::string kFullscreenVertex;  // one triangle over the viewport
// The composite's inputs and ssamComposite() (core/glsl/composite.glsl), what every program reading
// the mask starts with.
extern const std::string kCompositeHead;
extern const std::string kCompositeFragment;  // Listing 3.2 as (foliage, mask) for SRC_ALPHA blending

}  // namespace ssam::gl::shaders
