// SPDX-License-Identifier: MIT
// Checks the images of the raw-OpenGL examples (ssam/examples: ssam::gl embedded in a plain OpenGL
// program, with SSAM's built-in programs or the host's own wind-bent shaders) at known pixels
// against SSAM's formulas ([Hathaway 2010] §3.5.2-3.5.4, §3.6.2) computed from the examples' own
// scene description (scene.hpp): no stored image, no hard-coded results.
//
//   gl_example_check IMAGE.png [--mask MASK.png] [--wind A]
//       the frame (and SSAM's mask: red = MAX, alpha = SUM) at known pixels; with --wind A (A != 0)
//       the pixels where the host's wind moved card C's leaf, and where it left only sky
//   gl_example_check --same A.png B.png
//       the two files hold the same pixels (the host shaders that mimic the built-in programs)
// Exit 0 when every pixel matches, 1 when one does not, 2 for a usage error.
//
// Tolerance: 2 codes of 255 where foliage is blended (the composite blends an 8-bit target; GL
// 4.5 §17.3.6 leaves blending precision to the implementation and llvmpipe blends RGBA8 in
// 8-bit fixed point, README "Differential tolerances"); 0 codes where the mask is 0 (dst * 1 +
// src * 0 is exact in any blender) plus 1 for how the host's float colours become 8-bit codes
// (exactly, 0.9f -> 229.4999 -> 229, or in float arithmetic as llvmpipe does, 0.9f * 255 = 229.5f
// -> 230; both are round-to-nearest of a float product). The mask: 1 code (one 8-bit store of
// tint * texel alpha, then MAX / ADD of stored values, exact; the store's rounding is the
// implementation's, GL 4.5 §2.3.5.2).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "engine/capture/image_read.hpp"
#include "engine/core/error.hpp"
#include "scene.hpp"

using namespace gl_example;

namespace {

// The stored 8-bit value of v, computed in double so v's exact float value decides ties
// (0.7f * 255 is 178.49999..., stored as 178).
float q8(float v) { return static_cast<float>(std::round(std::clamp(double(v), 0.0, 1.0) * 255.0) / 255.0); }
int code(float v) { return static_cast<int>(std::lround(v * 255.0f)); }

struct Mask {
    float max = 0.0f, sum = 0.0f;  // stored values
};

struct Expected {
    std::string what;
    float x, y;  // world position of the pixel
    std::array<float, 3> rgb;
    int toleranceCodes;
    Mask mask;
};

// Unlit foliage colour in rt_foliage: the leaf's uniform core texel times the card's tint.
std::array<float, 3> foliageCore(const Rect3& card) {
    const auto texel = leafTexel(kLeafSize / 2, kLeafSize / 2);
    return {q8(texel[0] / 255.0f * card.color[0]), q8(texel[1] / 255.0f * card.color[1]),
            q8(texel[2] / 255.0f * card.color[2])};
}

// Listing 3.2 with the paper's defaults (maskLerp 0.85, squared): lerp(opaque, foliage, m^2).
std::array<float, 3> composite(const std::array<float, 3>& opaque, const std::array<float, 3>& foliage, Mask mask) {
    float m = std::clamp(mask.max + (mask.sum - mask.max) * 0.85f, 0.0f, 1.0f);
    m *= m;
    return {opaque[0] + (foliage[0] - opaque[0]) * m, opaque[1] + (foliage[1] - opaque[1]) * m,
            opaque[2] + (foliage[2] - opaque[2]) * m};
}

// The leaf texture's alpha at (u, v) in [0, 1], from the texel there (no filtering).
float leafAlphaAt(float u, float v) {
    if (u < 0.0f || u > 1.0f || v < 0.0f || v > 1.0f) return 0.0f;
    const int x = std::min(static_cast<int>(u * kLeafSize), kLeafSize - 1);
    const int y = std::min(static_cast<int>(v * kLeafSize), kLeafSize - 1);
    return leafTexel(x, y)[3] / 255.0f;
}

engine::capture::Image8 read(const char* path) {
    engine::capture::Image8 image = engine::capture::readImage8(path);
    if (image.width != kWidth || image.height != kHeight || image.channels < 3)
        throw engine::Error(std::string(path) + " is " + std::to_string(image.width) + "x" +
                            std::to_string(image.height) + " with " + std::to_string(image.channels) +
                            " channels, expected " + std::to_string(kWidth) + "x" + std::to_string(kHeight) +
                            " RGB(A)");
    return image;
}

int compareSame(const char* a, const char* b) {
    const engine::capture::Image8 first = read(a), second = read(b);
    if (first.channels != second.channels) {
        std::printf("FAIL %s has %d channels, %s %d\n", a, first.channels, b, second.channels);
        return 1;
    }
    long different = 0;
    int worst = 0;
    for (std::size_t i = 0; i < first.pixels.size(); ++i) {
        const int d = std::abs(int(first.pixels[i]) - int(second.pixels[i]));
        different += d != 0;
        worst = std::max(worst, d);
    }
    std::printf("%s %s and %s: %ld of %zu values differ (by up to %d codes)\n", different ? "FAIL" : "ok  ", a, b,
                different, first.pixels.size(), worst);
    return different == 0 ? 0 : 1;
}

int checkFrame(const char* imagePath, const char* maskPath, float wind) {
    const engine::capture::Image8 image = read(imagePath);
    std::optional<engine::capture::Image8> mask;
    if (maskPath) {
        mask = read(maskPath);
        if (mask->channels != 4) throw engine::Error(std::string(maskPath) + " has no alpha channel (the SUM mask)");
    }
    const std::array<float, 3> ground{q8(kGround.color[0]), q8(kGround.color[1]), q8(kGround.color[2])};
    const std::array<float, 3> box{q8(kBox.color[0]), q8(kBox.color[1]), q8(kBox.color[2])};
    const std::array<float, 3> sky{q8(kSky[0]), q8(kSky[1]), q8(kSky[2])};
    const float alphaA = q8(kCardA.color[3]), alphaB = q8(kCardB.color[3]), alphaC = q8(kCardC.color[3]);
    const Mask none, cardC{alphaC, alphaC}, aOverB{alphaA, std::min(alphaA + alphaB, 1.0f)};

    std::vector<Expected> checks = {
        {"opaque ground only (inside the composite's scissor, mask 0)", -0.8f, -0.8f, ground, 1, none},
        {"sky, no foliage", -0.9f, 0.9f, sky, 1, none},
        {"box in front of card D (the mask pass depth-tests against the opaque depth)", 0.6f, -0.3f, box, 1, none},
    };
    // A point of card C (alone over the sky) at texture (u, v), where the wind put it.
    auto onCardC = [&](float u, float v) {
        return std::array<float, 2>{kCardC.x0 + (kCardC.x1 - kCardC.x0) * u + bentOffset(wind, v),
                                    kCardC.y0 + (kCardC.y1 - kCardC.y0) * v};
    };
    if (wind == 0.0f) {
        // Both crossing cards pass the colour-pass reference (64/255), so the nearer one shows.
        const auto [cx, cy] = onCardC(0.5f, 0.5f);
        checks.push_back({"card C alone over the sky: max = add = alpha C", cx, cy,
                          composite(sky, foliageCore(kCardC), cardC), 2, cardC});
        checks.push_back({"A over B, left of their crossing: max = A, add = A + B, colour A", -0.25f, 0.1f,
                          composite(sky, foliageCore(kCardA), aOverB), 2, aOverB});
        checks.push_back({"B over A, right of their crossing: max = A, add = A + B, colour B", -0.05f, 0.1f,
                          composite(sky, foliageCore(kCardB), aOverB), 2, aOverB});
    } else {
        // The host's vertex shader moved the leaf: its core at texture (0.5, 0.75) is where
        // bentOffset says; and near its top (v = 0.9, above card B's top, which the wind moves
        // right too) a point of the unbent card's rim, left of the bent card's edge, is sky
        // (checked to hold: this check fails on an unbent frame).
        const auto [cx, cy] = onCardC(0.5f, 0.75f);
        checks.push_back(
            {"card C's core where the wind moved it", cx, cy, composite(sky, foliageCore(kCardC), cardC), 2, cardC});
        const float rimU = 0.3f, rimV = 0.9f;
        const float rimX = kCardC.x0 + rimU * (kCardC.x1 - kCardC.x0), rimY = onCardC(rimU, rimV)[1];
        if (!(leafAlphaAt(rimU, rimV) > 0.25f) || !(rimX + 2.0f / kWidth < onCardC(0.0f, rimV)[0]) ||
            !(rimY - 2.0f / kHeight > kCardB.y1))
            throw engine::Error("--wind " + std::to_string(wind) + " does not move card C's rim off that pixel");
        checks.push_back({"sky where the unbent card C's rim was", rimX, rimY, sky, 1, none});
    }

    int failures = 0;
    for (const Expected& e : checks) {
        const auto [px, py] = pixelAt(e.x, e.y);
        bool ok = true;
        std::string got, want;
        for (int c = 0; c < 3; ++c) {
            const int value = image.pixels[image.index(px, py, c)];
            ok = ok && std::abs(value - code(e.rgb[c])) <= e.toleranceCodes;
            got += std::to_string(value) + (c < 2 ? "," : "");
            want += std::to_string(code(e.rgb[c])) + (c < 2 ? "," : "");
        }
        if (mask) {
            const int max = mask->pixels[mask->index(px, py, 0)], sum = mask->pixels[mask->index(px, py, 3)];
            ok = ok && std::abs(max - code(e.mask.max)) <= 1 && std::abs(sum - code(e.mask.sum)) <= 1;
            got += "; mask " + std::to_string(max) + "," + std::to_string(sum);
            want += "; mask " + std::to_string(code(e.mask.max)) + "," + std::to_string(code(e.mask.sum));
        }
        std::printf("%s pixel (%d, %d) %s: got (%s), expected (%s) +-%d\n", ok ? "ok  " : "FAIL", px, py,
                    e.what.c_str(), got.c_str(), want.c_str(), e.toleranceCodes);
        failures += ok ? 0 : 1;
    }
    return failures == 0 ? 0 : 1;
}

int usage(const char* self) {
    std::fprintf(stderr, "usage: %s IMAGE.png [--mask MASK.png] [--wind A]\n       %s --same A.png B.png\n", self,
                 self);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc == 4 && std::string(argv[1]) == "--same") return compareSame(argv[2], argv[3]);
        if (argc < 2 || argv[1][0] == '-') return usage(argv[0]);
        const char* maskPath = nullptr;
        float wind = 0.0f;
        for (int i = 2; i < argc; ++i) {
            const std::string arg = argv[i];
            if (i + 1 >= argc) return usage(argv[0]);
            if (arg == "--mask") maskPath = argv[++i];
            else if (arg == "--wind") wind = std::strtof(argv[++i], nullptr);
            else return usage(argv[0]);
        }
        return checkFrame(argv[1], maskPath, wind);
    } catch (const engine::Error& e) {
        std::fprintf(stderr, "gl_example_check: error: %s\n", e.what());
        return 1;
    }
}
