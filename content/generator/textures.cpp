// SPDX-License-Identifier: MIT
#include "textures.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "engine/core/error.hpp"
#include "noise.hpp"
#include "prng.hpp"

namespace content {

namespace {

constexpr float kPi = 3.14159265358979f;

// Straight colour (sRGB-encoded values in [0, 1]) and alpha, composited with "over".
struct Canvas {
    int width;
    int height;
    std::vector<glm::vec4> texels;

    Canvas(int w, int h, glm::vec4 fill) : width(w), height(h), texels(static_cast<std::size_t>(w * h), fill) {}

    glm::vec4& at(int x, int y) { return texels[static_cast<std::size_t>(y * width + x)]; }

    // Straight-alpha "over". Where nothing covers a texel its colour stays as filled.
    void over(int x, int y, glm::vec3 colour, float alpha) {
        if (x < 0 || y < 0 || x >= width || y >= height || alpha <= 0.0f) return;
        glm::vec4& d = at(x, y);
        const float a = alpha + d.a * (1.0f - alpha);
        const glm::vec3 c = (colour * alpha + glm::vec3(d) * d.a * (1.0f - alpha)) / a;
        d = glm::vec4(c, a);
    }

    // Alpha fades to 0 within `margin` texels of the border: nothing reaches the edge, so
    // clamped or wrapped sampling never shows a cut leaf.
    void fadeBorder(float margin) {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const float d = static_cast<float>(std::min(std::min(x, y), std::min(width - 1 - x, height - 1 - y)));
                at(x, y).a *= std::clamp(d / margin, 0.0f, 1.0f);
            }
    }

    RgbaImage image() const {
        RgbaImage out = RgbaImage::make(width, height);
        for (std::size_t t = 0; t < texels.size(); ++t)
            for (int c = 0; c < 4; ++c)
                out.pixels[t * 4 + static_cast<std::size_t>(c)] =
                    static_cast<std::uint8_t>(std::lround(std::clamp(texels[t][c], 0.0f, 1.0f) * 255.0f));
        return out;
    }
};

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// A leaf from `base` towards `angle` (radians, y down as in the image): a lens of the given
// length and width, pointed at both ends, with a lighter midrib, one side a little brighter,
// and an alpha ramp of `edge` texels inside its outline.
void drawLeaf(Canvas& canvas, glm::vec2 base, float angle, float length, float width, glm::vec3 colour, float edge,
              std::uint32_t seed) {
    const glm::vec2 dir(std::cos(angle), std::sin(angle));
    const glm::vec2 side(-dir.y, dir.x);
    const float reach = length + width;
    const int x0 = static_cast<int>(std::floor(base.x - reach)), x1 = static_cast<int>(std::ceil(base.x + reach));
    const int y0 = static_cast<int>(std::floor(base.y - reach)), y1 = static_cast<int>(std::ceil(base.y + reach));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 p = glm::vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f) - base;
            const float u = glm::dot(p, dir) / length;
            if (u <= 0.0f || u >= 1.0f) continue;
            const float s = glm::dot(p, side);
            const float halfWidth = 0.5f * width * 4.0f * u * (1.0f - u);
            const float inside = halfWidth - std::abs(s);
            const float alpha = std::clamp((inside + 0.5f) / edge, 0.0f, 1.0f);
            if (alpha <= 0.0f) continue;
            const float grain = 0.92f + 0.16f * valueNoise(static_cast<float>(x) / 256.0f,
                                                           static_cast<float>(y) / 256.0f, 64, 64, seed);
            glm::vec3 c = colour * grain * (s > 0.0f ? 1.08f : 0.94f) * (0.85f + 0.15f * u);
            const float rib = 1.0f - smoothstep(0.4f, 1.2f, std::abs(s));
            c = glm::mix(c, colour * 1.35f + glm::vec3(0.05f, 0.05f, 0.0f), rib * 0.6f * (1.0f - u));
            canvas.over(x, y, glm::clamp(c, 0.0f, 1.0f), alpha);
        }
}

// A stroke of varying width along a quadratic Bezier (twigs and stems).
void drawStroke(Canvas& canvas, glm::vec2 a, glm::vec2 control, glm::vec2 b, float width0, float width1,
                glm::vec3 colour) {
    const int steps = 96;
    for (int i = 0; i <= steps; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(steps);
        const glm::vec2 p = (1 - t) * (1 - t) * a + 2 * (1 - t) * t * control + t * t * b;
        const float r = 0.5f * (width0 + (width1 - width0) * t);
        for (int y = static_cast<int>(p.y - r - 2); y <= static_cast<int>(p.y + r + 2); ++y)
            for (int x = static_cast<int>(p.x - r - 2); x <= static_cast<int>(p.x + r + 2); ++x) {
                const float d = glm::length(glm::vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f) - p);
                const float alpha = std::clamp(r - d + 0.5f, 0.0f, 1.0f);
                if (x >= 0 && y >= 0 && x < canvas.width && y < canvas.height && alpha > canvas.at(x, y).a)
                    canvas.over(x, y, colour, alpha);
            }
    }
}

glm::vec2 bezier(glm::vec2 a, glm::vec2 c, glm::vec2 b, float t) {
    return (1 - t) * (1 - t) * a + 2 * (1 - t) * t * c + t * t * b;
}
glm::vec2 bezierTangent(glm::vec2 a, glm::vec2 c, glm::vec2 b, float t) {
    return glm::normalize(2 * (1 - t) * (c - a) + 2 * t * (b - c));
}

}  // namespace

RgbaImage makeLeafCluster(std::uint32_t seed) {
    Pcg32 rng(seed);
    const glm::vec3 leafBase(0.26f, 0.45f, 0.12f);
    Canvas canvas(256, 256, glm::vec4(leafBase, 0.0f));
    const glm::vec3 twigColour(0.33f, 0.24f, 0.14f);
    const glm::vec2 root(128.0f, 244.0f);
    const int twigs = 8;
    struct Twig {
        glm::vec2 a, c, b;
    };
    std::vector<Twig> layout;
    for (int i = 0; i < twigs; ++i) {
        const float spread = (static_cast<float>(i) / static_cast<float>(twigs - 1) - 0.5f) * 2.0f;  // -1..1
        const float angle = -kPi / 2 + spread * 1.1f + rng.uniform(-0.1f, 0.1f);
        const float length = rng.uniform(160.0f, 205.0f) * (1.0f - 0.3f * std::abs(spread));
        const glm::vec2 tip = root + length * glm::vec2(std::cos(angle), std::sin(angle));
        // One draw per statement, in the order GCC evaluated them when the assets were committed
        // (C++ leaves the order of a call's arguments unspecified; Clang goes left to right).
        const float bendY = rng.uniform(-10.0f, 10.0f), bendX = rng.uniform(-18.0f, 18.0f);
        const glm::vec2 bend = 0.5f * (root + tip) + glm::vec2(bendX, bendY);
        layout.push_back({root, bend, tip});
        drawStroke(canvas, root, bend, tip, 4.0f, 1.5f, twigColour);
    }
    // Leaves along every twig, alternating sides, then one at each tip.
    for (const Twig& twig : layout) {
        int side = rng.below(2) ? 1 : -1;
        for (float t = rng.uniform(0.15f, 0.25f); t < 0.97f; t += rng.uniform(0.06f, 0.09f)) {
            const glm::vec2 at = bezier(twig.a, twig.c, twig.b, t);
            const glm::vec2 tangent = bezierTangent(twig.a, twig.c, twig.b, t);
            const float angle = std::atan2(tangent.y, tangent.x) + static_cast<float>(side) * rng.uniform(0.55f, 0.95f);
            // One draw per statement, in GCC's order (as for `bend` above).
            const float greenShift = rng.uniform(-0.03f, 0.06f), redShift = rng.uniform(-0.04f, 0.05f);
            const float brightness = rng.uniform(0.8f, 1.2f);
            const glm::vec3 tint = leafBase * brightness + glm::vec3(redShift, greenShift, 0.0f);
            const float width = rng.uniform(14.0f, 20.0f), length = rng.uniform(30.0f, 44.0f);
            drawLeaf(canvas, at, angle, length, width, tint, 3.0f, seed + 7u);
            side = -side;
        }
        const glm::vec2 tangent = bezierTangent(twig.a, twig.c, twig.b, 1.0f);
        drawLeaf(canvas, twig.b - tangent * 4.0f, std::atan2(tangent.y, tangent.x), rng.uniform(30.0f, 38.0f), 15.0f,
                 leafBase * 1.1f, 3.0f, seed + 7u);
    }
    canvas.fadeBorder(4.0f);
    return canvas.image();
}

RgbaImage makeFrond(std::uint32_t seed) {
    Pcg32 rng(seed);
    const glm::vec3 green(0.18f, 0.38f, 0.10f);
    Canvas canvas(256, 256, glm::vec4(green, 0.0f));
    const glm::vec2 a(128.0f, 248.0f), c(150.0f, 120.0f), b(118.0f, 10.0f);
    drawStroke(canvas, a, c, b, 4.0f, 1.2f, glm::vec3(0.30f, 0.32f, 0.12f));
    const int pairs = 20;
    for (int i = 0; i < pairs; ++i) {
        const float t = 0.06f + 0.9f * static_cast<float>(i) / static_cast<float>(pairs - 1);
        const glm::vec2 tangent = bezierTangent(a, c, b, t);
        const float stemAngle = std::atan2(tangent.y, tangent.x);
        const float length = 78.0f * std::pow(1.0f - t, 0.7f) + 10.0f;
        for (int side = -1; side <= 1; side += 2) {
            const float offset = side > 0 ? 0.0f : 0.012f;  // alternate a little along the stem
            const glm::vec2 at = bezier(a, c, b, std::min(t + offset, 1.0f));
            const float angle = stemAngle + static_cast<float>(side) * rng.uniform(1.0f, 1.2f);
            const glm::vec3 tint = green * rng.uniform(0.85f, 1.2f);
            drawLeaf(canvas, at, angle, length, std::max(5.0f, length * 0.2f), tint, 2.5f, seed + 3u);
        }
    }
    canvas.fadeBorder(4.0f);
    return canvas.image();
}

RgbaImage makeBark(std::uint32_t seed) {
    Canvas canvas(128, 128, glm::vec4(0.0f));
    const glm::vec3 dark(0.20f, 0.14f, 0.09f), light(0.46f, 0.36f, 0.26f);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) {
            const float u = static_cast<float>(x) / 128.0f, v = static_cast<float>(y) / 128.0f;
            const float ridges = fbm(u, v, 12, 2, 4, seed);  // vertical fibres
            const float detail = fbm(u, v, 32, 16, 2, seed + 9u);
            const float crack = smoothstep(0.30f, 0.42f, ridges);
            const glm::vec3 colour = glm::mix(dark, light, ridges * 0.8f + detail * 0.2f) * (0.45f + 0.55f * crack);
            canvas.at(x, y) = glm::vec4(colour, 1.0f);
        }
    return canvas.image();
}

RgbaImage makeGround(std::uint32_t seed) {
    Canvas canvas(256, 256, glm::vec4(0.0f));
    const glm::vec3 grass(0.28f, 0.40f, 0.15f), dryGrass(0.46f, 0.46f, 0.22f), dirt(0.44f, 0.35f, 0.23f);
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            const float u = static_cast<float>(x) / 256.0f, v = static_cast<float>(y) / 256.0f;
            const float patches = fbm(u, v, 4, 4, 4, seed);
            const float dry = fbm(u, v, 8, 8, 3, seed + 1u);
            const float blades = fbm(u, v, 64, 64, 2, seed + 2u);
            glm::vec3 colour = glm::mix(grass, dryGrass, smoothstep(0.45f, 0.7f, dry));
            colour = glm::mix(colour, dirt, smoothstep(0.55f, 0.68f, patches));
            canvas.at(x, y) = glm::vec4(colour * (0.8f + 0.4f * blades), 1.0f);
        }
    return canvas.image();
}

RgbaImage makeTrack(std::uint32_t seed) {
    Canvas canvas(256, 256, glm::vec4(0.0f));
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            const float u = static_cast<float>(x) / 256.0f, v = static_cast<float>(y) / 256.0f;
            const float grit = fbm(u, v, 64, 64, 2, seed);
            const float stains = fbm(u, v, 4, 8, 3, seed + 5u);
            float grey = 0.27f + 0.10f * grit - 0.06f * smoothstep(0.55f, 0.75f, stains);
            const bool edgeLine = (u > 0.035f && u < 0.065f) || (u > 0.935f && u < 0.965f);
            const bool centreDash = std::abs(u - 0.5f) < 0.012f && v < 0.5f;
            if (edgeLine || centreDash) grey = 0.82f + 0.08f * grit;
            canvas.at(x, y) = glm::vec4(grey, grey, grey * 1.02f, 1.0f);
        }
    return canvas.image();
}

RgbaImage makeCarAtlas(std::uint32_t seed) {
    Canvas canvas(128, 128, glm::vec4(0.0f));
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) {
            const float u = (static_cast<float>(x) + 0.5f) / 128.0f, v = (static_cast<float>(y) + 0.5f) / 128.0f;
            const float grain = fbm(u, v, 16, 16, 2, seed);
            glm::vec3 colour;
            if (v < 0.5f) {  // paint
                colour = glm::vec3(0.78f, 0.09f, 0.06f) * (0.95f + 0.1f * grain);
                if (std::abs(u - 0.5f) < 0.08f) colour = glm::vec3(0.92f);
                const float disc = glm::length(glm::vec2(u - 0.22f, v - 0.25f));
                if (disc < 0.13f) colour = disc > 0.11f ? glm::vec3(0.05f) : glm::vec3(0.95f);
            } else if (v < 0.75f) {  // glass, with a diagonal reflection
                colour = glm::vec3(0.10f, 0.14f, 0.18f);
                if (std::abs((u - (v - 0.5f) * 2.0f) - 0.35f) < 0.06f) colour = glm::vec3(0.35f, 0.42f, 0.48f);
            } else {  // tyre rubber with tread
                colour = glm::vec3(0.07f) * ((y / 4) % 2 ? 1.0f : 1.6f) * (0.9f + 0.2f * grain);
            }
            canvas.at(x, y) = glm::vec4(colour, 1.0f);
        }
    return canvas.image();
}

std::vector<std::uint8_t> encodePng(const RgbaImage& image) {
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput proxy(bytes);
    auto out = OIIO::ImageOutput::create("texture.png", &proxy);
    if (!out) throw engine::Error("encodePng: no PNG writer: " + OIIO::geterror());
    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the codes are straight already: store as is
    spec.attribute("png:compressionLevel", 9);
    if (!out->open("texture.png", spec) || !out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data()) ||
        !out->close())
        throw engine::Error("encodePng: " + out->geterror());
    return {bytes.begin(), bytes.end()};
}

}  // namespace content
