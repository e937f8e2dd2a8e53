// The engine dialect's head of SSAM's composite (composite_program.cpp): before the core's
// composite_mask.glsl and composite.glsl.
#define PRECISE precise
layout(binding = 0) uniform sampler2D u_foliage;
layout(binding = 1) uniform sampler2D u_mask;
layout(binding = 2) uniform sampler2D u_maskAdd;
