// SSAM+'s coverage from the MAX and ADD masks (soft: program_kernels.hpp layerCoverage).
float layerCoverage(ivec2 p) {
    vec4 m = texelFetch(u_mask, p, 0);
    float addMask = u_maskAddBound ? texelFetch(u_maskAdd, p, 0).r : m.a;
    float coverage = 0.0;
    if (u_model == 1) coverage = 1.0 - exp(-addMask);
    else if (m.r >= 1.0) coverage = 1.0;
    else if (m.r > 0.0) coverage = 1.0 - pow(1.0 - m.r, addMask / m.r);
    return clamp01(coverage);
}
