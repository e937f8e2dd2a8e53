// The engine dialect's head of the foliage depth program (foliage_depth_program.cpp):
// SURFACE_OUTPUT (expanded inside the lit surface's main()) is foliage_depth_output.glsl's; the
// soft kernel's NaN alpha fails the alpha test where it discards.
#define PRECISE precise
#define SURFACE_OUTPUT(c) foliageDepthOutput(c)
layout(binding = 1) uniform sampler2D u_mask;
layout(binding = 2) uniform sampler2D u_maskAdd;
