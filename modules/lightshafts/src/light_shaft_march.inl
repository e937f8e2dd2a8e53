// SPDX-License-Identifier: MIT
// LightShaftKernel::shade() for the pixels of one block row at once, Floats::kLanes pixels per
// vector: light_shaft_rows.cpp includes this once per instruction set, inside its namespace
// (sse2, avx2) with that set's lane types (engine/render/kernel/simd/), so there is no
// include guard and nothing is included here.
//
// Lane by lane the scalar march's IEEE operations in its order, so the bits are shade()'s:
//   - the weight decay^i is the same running product for every pixel: one scalar multiply
//     per sample, as shade() does per pixel;
//   - sample i of a lane is added where shade() would add it: i at or past the lane's first
//     glowing sample, q_i on the screen, its texel sky. A lane whose sample is not added
//     adds +0, which leaves its sum as it was: a sum that starts at +0 is never -0;
//   - shade() stops a pixel's march when q_i leaves the screen; q_i moves monotonically in
//     each coordinate away from the on-screen p (q_0 = p), so the samples on the screen are
//     the first ones, and the row's march stops when no lane's sample is on it.
void marchRow(const LightShaftKernel& kernel, int bx, int py, std::uint32_t live, glm::vec4* out) {
    const LightShaftParams& params = kernel.params;
    const int w = kernel.depth->desc.width, h = kernel.depth->desc.height;
    const int samples = kernel.sampleCount();
    const float* texels = reinterpret_cast<const float*>(kernel.depth->levels[0].texels.data());
    const float stepScale = params.density / float(samples);
    const bool glows = params.glowRadius > 0.0f;
    constexpr int kLanes = Floats::kLanes;
    constexpr std::uint32_t kAll = (1u << kLanes) - 1u;
    for (int o = 0; o < 8; o += kLanes) {
        const std::uint32_t lanes = (live >> o) & kAll;
        if (!lanes) continue;
        // p = (float(x) + 0.5, float(y) + 0.5); step = (sun - p) * (density / samples).
        const Floats px = (Floats::splat(float(bx + o)) + Floats::laneIndex()) + Floats::splat(0.5f);
        const Floats py5 = Floats::splat(float(py) + 0.5f);
        const Floats stepX = (Floats::splat(params.sunPixel.x) - px) * Floats::splat(stepScale);
        const Floats stepY = (Floats::splat(params.sunPixel.y) - py5) * Floats::splat(stepScale);
        alignas(32) float first[kLanes];
        int start = samples;
        for (int i = 0; i < kLanes; ++i) {
            first[i] = 0.0f;
            if (!((lanes >> i) & 1u)) continue;
            const int f = kernel.firstGlowingSample(glm::vec2(float(bx + o + i) + 0.5f, float(py) + 0.5f), samples);
            first[i] = float(f);
            start = std::min(start, f);
        }
        const Floats firstSample = Floats::load(first);
        const Mask liveLanes = Mask::fromBits(lanes);
        float weight = 1.0f;
        for (int i = 0; i < start; ++i) weight *= params.decay;
        Floats sum = Floats::splat(0.0f);
        for (int i = start; i < samples; ++i) {
            const Floats fi = Floats::splat(float(i));
            const Floats qx = px + stepX * fi, qy = py5 + stepY * fi;
            const Mask onScreen = (qx >= Floats::splat(0.0f)) & (qy >= Floats::splat(0.0f)) &
                                  (qx < Floats::splat(float(w))) & (qy < Floats::splat(float(h))) & liveLanes;
            if (!onScreen.any()) break;
            const Mask active = onScreen & (fi >= firstSample);
            if (active.any()) {
                const Floats z = gather(texels, w, qx, qy, active);
                const Floats far = Floats::splat(params.farDepth);
                const Mask sky = andNot(active, params.greaterIsCloser ? z > far : z < far);
                Floats glow = Floats::splat(1.0f);
                if (glows) {  // sunGlow: t = max(0, 1 - |q - sun| / glowRadius), t * t
                    const Floats dx = qx - Floats::splat(params.sunPixel.x), dy = qy - Floats::splat(params.sunPixel.y);
                    const Floats distance = sqrt(dx * dx + dy * dy);
                    const Floats t = maxOr(Floats::splat(1.0f) - distance / Floats::splat(params.glowRadius),
                                           Floats::splat(0.0f));
                    glow = t * t;
                }
                sum = sum + keepIf(sky, Floats::splat(weight) * glow);
            }
            weight *= params.decay;
        }
        alignas(32) float sums[kLanes];
        sum.store(sums);
        for (std::uint32_t bits = lanes; bits; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            out[o + i] = kernel.colorOf(sums[i]);
        }
    }
}
