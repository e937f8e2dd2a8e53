// SSAM+'s front layers (soft: program_kernels.hpp withFrontLayers): the colour `kept` of the leaf
// the colour pass kept at p over the alpha-weighted mean of the layers drawn in front of it,
// u_frontLayers = (sum a * C, sum a), by the kept leaf's alpha; `kept` where none was bound or
// drawn.
vec3 withFrontLayers(ivec2 p, vec3 kept) {
    if (!u_frontLayersBound) return kept;
    vec4 front = texelFetch(u_frontLayers, p, 0);
    if (!(front.a > 0.0)) return kept;
    float k = clamp01(texelFetch(u_foliage, p, 0).a);
    return kept * k + front.rgb / front.a * (1.0 - k);
}
