// Base colour sampling. Nearest and bilinear are the sampler's (GL_NEAREST / GL_LINEAR: the
// base level only). Trilinear computes its LOD here, as the soft backend does: rho is the
// longer analytic UV derivative in texels, lambda = log2 rho, and the two nearest levels are
// lerped. GL's own LOD takes finite differences of uv and leaves precision to the
// implementation (llvmpipe quantizes the fraction); here the derivatives are analytic:
// uv/w and 1/w (gl_FragCoord.w) are linear in screen space, so their differences are exact and
// d(uv)/dx = (d(uv/w)/dx - uv * d(1/w)/dx) * w (soft: tile_rasterizer.cpp interpolate()).
layout(binding = 0) uniform sampler2D u_baseColor;
vec4 sampleBase(vec2 uv) {
    float inverseW = gl_FragCoord.w;
    vec2 uvOverW = uv * inverseW;
    // Linear functions: fine and coarse differences agree, so plain dFdx (GLSL 4.30) will do.
    vec2 dqdx = dFdx(uvOverW), dqdy = dFdy(uvOverW);
    float dwdx = dFdx(inverseW), dwdy = dFdy(inverseW);
    if (u_filter != 2) return texture(u_baseColor, uv);
    float w = 1.0 / inverseW;
    vec2 size = vec2(textureSize(u_baseColor, 0));
    vec2 dx = (dqdx - uv * dwdx) * w * size;
    vec2 dy = (dqdy - uv * dwdy) * w * size;
    float rho = max(length(dx), length(dy));
    float lambda = log2(rho);
    int last = textureQueryLevels(u_baseColor) - 1;
    if (!(lambda > 0.0) || last == 0) return textureLod(u_baseColor, uv, 0.0);
    if (lambda >= float(last)) return textureLod(u_baseColor, uv, float(last));
    int lo = int(lambda);
    return mix(textureLod(u_baseColor, uv, float(lo)), textureLod(u_baseColor, uv, float(lo + 1)), lambda - float(lo));
}
