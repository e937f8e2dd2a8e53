void main() { finish(ssamComposite(ivec2(gl_FragCoord.xy))); }
