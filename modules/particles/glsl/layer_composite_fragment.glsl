// LayerComposite (particle_kernels.hpp LayerCompositeKernel): the layer texel, nearest-depth upsampled.
float distanceOf(float z) { return u_depthScale / (z + u_depthOffset); }
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int scale = clamp(u_layerScale, 1, 4);
    ivec2 last = textureSize(u_layer, 0) - 1;
    ivec2 l = min(p / scale, last);
    if (scale > 1 && u_sceneDepthBound) {
        float here = distanceOf(texelFetch(u_sceneDepth, p, 0).r);
        ivec2 c0 = clamp((p - 1) / 2, ivec2(0), last), c1 = min(c0 + 1, last);
        ivec2 n = clamp(p / 2, ivec2(0), last);
        vec4 c00 = texelFetch(u_layer, c0, 0);
        bool same = c00 == texelFetch(u_layer, ivec2(c1.x, c0.y), 0) && c00 == texelFetch(u_layer, ivec2(c0.x, c1.y), 0) &&
                    c00 == texelFetch(u_layer, c1, 0);
        if (same) l = c0; else {
        float best = abs(distanceOf(closestDepth(n, scale)) - here);
        l = n;
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                ivec2 c = ivec2(i == 0 ? c0.x : c1.x, j == 0 ? c0.y : c1.y);
                float diff = abs(distanceOf(closestDepth(c, scale)) - here);
                if (diff < best) { best = diff; l = c; }
            }
        }
    }
    vec4 c = texelFetch(u_layer, l, 0);
    for (int i = 0; i < 4; ++i)
        if (isnan(c[i]) || isinf(c[i])) c[i] = 0.0;
    c.a = saturateOrZero(c.a);
    finish(c);
}
