// AlphaOnly: [Hathaway 2010] Listing 3.1: alpha only, replicated; no lighting, no colour fetch.
void main() {
    float a = u_alphaFactor * v_color.a;
    if (u_hasTexture) a *= sampleBase(v_uv).a;
    finish(vec4(a));
}
