// SPDX-License-Identifier: MIT
// Needs u_foliage (sampler2D). Defines vec3 ssamBlurredFoliage(ivec2 pixel), the colour of SSAM's
// Settings::colorBlur and of SSAM+'s blurred composite: the 1-2-1 3x3 average of the colours the
// colour pass wrote (alpha > 0) around the pixel, inside the target, each weighted too by its
// alpha to the power 1.5 (alpha clamped to 1: a leaf's soft edge covers little of its pixel);
// the pixel's own where none was written (soft: covered_tent.hpp, summed in the same order).
vec3 ssamBlurredFoliage(ivec2 p) {
    ivec2 size = textureSize(u_foliage, 0);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            vec4 c = texelFetch(u_foliage, q, 0);
            if (!(c.a > 0.0)) continue;
            float alpha = c.a < 1.0 ? c.a : 1.0;
            float weight = float((2 - dx * dx) * (2 - dy * dy)) * (alpha * sqrt(alpha));
            sum += weight * c.rgb;
            weights += weight;
        }
    return weights > 0.0 ? sum / weights : texelFetch(u_foliage, p, 0).rgb;
}
