// SPDX-License-Identifier: MIT
// Checks the image of ssam/examples/gl_embedding (ssam::gl embedded in a plain OpenGL program)
// at known pixels against SSAM's formulas ([Hathaway 2010] §3.5.2-3.5.4, §3.6.2) computed from the
// example's own scene description (scene.hpp): no stored image, no hard-coded results.
//
// Tolerance: 2 codes of 255 where foliage is blended (the composite blends an 8-bit target; GL
// 4.5 §17.3.6 leaves blending precision to the implementation and llvmpipe blends RGBA8 in
// 8-bit fixed point, README "Differential tolerances"); the masks themselves are exact (one
// 8-bit store of factor * texel alpha, and MAX / ADD of stored 8-bit values); 0 codes where
// the mask is 0 (dst * 1 + src * 0 is exact in any blender) plus 1 for how the host's float
// colours become 8-bit codes (exactly, 0.9f -> 229.4999 -> 229, or in float arithmetic as
// llvmpipe does, 0.9f * 255 = 229.5f -> 230; both are round-to-nearest of a float product).
// Usage: gl_embedding_check IMAGE.png; exit 0 when every pixel matches.
#include <cmath>
#include <cstdio>
#include <string>

#include "engine/capture/image_read.hpp"
#include "engine/core/error.hpp"
#include "scene.hpp"

using namespace gl_embedding;

namespace {

// The stored 8-bit value of v, computed in double so v's exact float value decides ties
// (0.7f * 255 is 178.49999..., stored as 178).
float q8(float v) { return static_cast<float>(std::round(std::clamp(double(v), 0.0, 1.0) * 255.0) / 255.0); }

struct Expected {
    const char* what;
    float x, y;  // world position of the pixel
    std::array<float, 3> rgb;
    int toleranceCodes;
};

// Unlit foliage colour in rt_foliage: the leaf's uniform core texel times the card's tint.
std::array<float, 3> foliageCore(const Rect3& card) {
    const auto texel = leafTexel(kLeafSize / 2, kLeafSize / 2);
    return {q8(texel[0] / 255.0f * card.color[0]), q8(texel[1] / 255.0f * card.color[1]),
            q8(texel[2] / 255.0f * card.color[2])};
}

// Listing 3.2 with the paper's defaults (maskLerp 0.85, squared): lerp(opaque, foliage, m^2).
std::array<float, 3> composite(const std::array<float, 3>& opaque, const std::array<float, 3>& foliage, float maxMask,
                               float addMask) {
    float m = std::clamp(maxMask + (addMask - maxMask) * 0.85f, 0.0f, 1.0f);
    m *= m;
    return {opaque[0] + (foliage[0] - opaque[0]) * m, opaque[1] + (foliage[1] - opaque[1]) * m,
            opaque[2] + (foliage[2] - opaque[2]) * m};
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s IMAGE.png\n", argv[0]);
        return 2;
    }
    engine::capture::Image8 image;
    try {
        image = engine::capture::readImage8(argv[1]);
    } catch (const engine::Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    if (image.width != kWidth || image.height != kHeight || image.channels < 3) {
        std::fprintf(stderr, "%s is %dx%d with %d channels, expected %dx%d RGB(A)\n", argv[1], image.width, image.height,
                     image.channels, kWidth, kHeight);
        return 1;
    }
    const std::array<float, 3> ground{q8(kGround.color[0]), q8(kGround.color[1]), q8(kGround.color[2])};
    const std::array<float, 3> box{q8(kBox.color[0]), q8(kBox.color[1]), q8(kBox.color[2])};
    const std::array<float, 3> sky{q8(kSky[0]), q8(kSky[1]), q8(kSky[2])};
    const float alphaA = q8(kCardA.color[3]), alphaB = q8(kCardB.color[3]), alphaC = q8(kCardC.color[3]);
    // Both crossing cards pass the colour-pass reference (64/255), so the nearer one shows.
    const Expected checks[] = {
        {"opaque ground only (inside the composite's scissor, mask 0)", -0.8f, -0.8f, ground, 1},
        {"sky, no foliage", -0.9f, 0.9f, sky, 1},
        {"box in front of card D (the mask pass depth-tests against the opaque depth)", 0.6f, -0.3f, box, 1},
        {"card C alone over the sky: max = add = alpha C", 0.6f, 0.65f, composite(sky, foliageCore(kCardC), alphaC, alphaC), 2},
        {"A over B, left of their crossing: max = A, add = A + B, colour A", -0.25f, 0.1f,
         composite(sky, foliageCore(kCardA), alphaA, alphaA + alphaB), 2},
        {"B over A, right of their crossing: max = A, add = A + B, colour B", -0.05f, 0.1f,
         composite(sky, foliageCore(kCardB), alphaA, alphaA + alphaB), 2},
    };
    int failures = 0;
    for (const Expected& e : checks) {
        const auto [px, py] = pixelAt(e.x, e.y);
        bool ok = true;
        std::string got, want;
        for (int c = 0; c < 3; ++c) {
            const int code = image.pixels[image.index(px, py, c)];
            const int expected = static_cast<int>(std::lround(e.rgb[c] * 255.0f));
            ok = ok && std::abs(code - expected) <= e.toleranceCodes;
            got += std::to_string(code) + (c < 2 ? "," : "");
            want += std::to_string(expected) + (c < 2 ? "," : "");
        }
        std::printf("%s pixel (%d, %d) %s: got (%s), expected (%s) +-%d\n", ok ? "ok  " : "FAIL", px, py, e.what,
                    got.c_str(), want.c_str(), e.toleranceCodes);
        failures += ok ? 0 : 1;
    }
    return failures == 0 ? 0 : 1;
}
