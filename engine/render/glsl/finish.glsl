// The fragment tail every program ends in (glsl/standard_programs.hpp lists its inputs).
float clamp01(float v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }

bool alphaPasses(float a) {
    switch (u_alphaFunc) {
        case 0: return false;
        case 1: return a < u_alphaRef;
        case 2: return a == u_alphaRef;
        case 3: return a <= u_alphaRef;
        case 4: return a > u_alphaRef;
        case 5: return a != u_alphaRef;
        case 6: return a >= u_alphaRef;
        default: return true;
    }
}

void finish(vec4 color) {
    // Multisampled targets: the scissor again, per pixel. llvmpipe (Mesa 22.x) tests the
    // scissor rectangle at sample positions half a pixel off and lets the column left of it
    // and the row above it through; glScissor still bounds the work.
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (u_scissor.z > 0 && (any(lessThan(pixel, u_scissor.xy)) || any(greaterThanEqual(pixel, u_scissor.zw)))) discard;
    int mask = -1;
    if (u_a2cSamples > 1) {
        // round(alpha * samples) samples, the first ones (tile_rasterizer.cpp); a 2x target that
        // GL made 4x covers the same fraction of its samples.
        precise float scaled = clamp01(color.a) * float(u_a2cSamples) + 0.5;
        int covered = int(scaled) * u_a2cActual / u_a2cSamples;
        mask = (1 << covered) - 1;
    }
    gl_SampleMask[0] = mask;
    if (u_alphaSelect != 0 && alphaPasses(color.a) != (u_alphaSelect == 1)) discard;
    o_color0 = color;
    o_color1 = color;
    o_color2 = color;
    o_color3 = color;
}
