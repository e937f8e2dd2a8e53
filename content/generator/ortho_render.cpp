// SPDX-License-Identifier: MIT
#include "ortho_render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/render/pixel_codec.hpp"

namespace content {

namespace {

struct Sample {
    float depth = std::numeric_limits<float>::infinity();
    glm::vec3 color{0.0f};
    bool covered = false;
};

// Nearest texel, clamped: the texture's own resolution is what the level shows.
const std::uint8_t* texelAt(const engine::assets::RgbaImage& image, glm::vec2 uv) {
    const int x = std::clamp(int(std::floor(uv.x * float(image.width))), 0, image.width - 1);
    const int y = std::clamp(int(std::floor(uv.y * float(image.height))), 0, image.height - 1);
    return image.texel(x, y);
}

float edge(glm::vec2 a, glm::vec2 b, glm::vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

}  // namespace

std::vector<glm::vec4> renderOrtho(const std::vector<Surface>& surfaces, const OrthoView& view) {
    const int sw = view.width * view.samples, sh = view.height * view.samples;
    std::vector<Sample> samples(std::size_t(sw) * std::size_t(sh));
    const glm::vec3 forward(std::sin(view.yaw), 0.0f, std::cos(view.yaw));
    const glm::vec3 right(std::cos(view.yaw), 0.0f, -std::sin(view.yaw));
    const float toX = float(sw) / (2.0f * view.halfWidth), toY = float(sh) / (view.top - view.bottom);
    const auto& srgb = engine::render::byteTables().srgb;
    for (const Surface& s : surfaces) {
        const MeshData& m = *s.mesh;
        std::vector<glm::vec2> screen(m.positions.size());
        std::vector<float> depth(m.positions.size());
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            screen[i] = {(glm::dot(m.positions[i], right) + view.halfWidth) * toX, (view.top - m.positions[i].y) * toY};
            depth[i] = glm::dot(m.positions[i], forward);
        }
        for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            const std::uint32_t i0 = m.indices[t], i1 = m.indices[t + 1], i2 = m.indices[t + 2];
            const glm::vec2 a = screen[i0], b = screen[i1], c = screen[i2];
            const float area = edge(a, b, c);
            if (std::abs(area) < 1e-12f) continue;  // seen edge-on: covers no sample
            const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
            const int x1 = std::min(sw - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
            const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
            const int y1 = std::min(sh - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) {
                    const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
                    // Both windings: the cards are double-sided.
                    const float w0 = edge(b, c, p) / area, w1 = edge(c, a, p) / area, w2 = edge(a, b, p) / area;
                    if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
                    const float z = w0 * depth[i0] + w1 * depth[i1] + w2 * depth[i2];
                    Sample& out = samples[std::size_t(y) * std::size_t(sw) + std::size_t(x)];
                    if (z >= out.depth) continue;
                    const glm::vec2 uv = w0 * m.uvs[i0] + w1 * m.uvs[i1] + w2 * m.uvs[i2];
                    const std::uint8_t* texel = texelAt(*s.texture, uv);
                    if (s.alphaTested && texel[3] < 128) continue;  // MASK at 0.5: kept where alpha >= 0.5
                    out = {z, {srgb[texel[0]], srgb[texel[1]], srgb[texel[2]]}, true};
                }
        }
    }
    std::vector<glm::vec4> pixels(std::size_t(view.width) * std::size_t(view.height), glm::vec4(0.0f));
    const float weight = 1.0f / float(view.samples * view.samples);
    for (int y = 0; y < sh; ++y)
        for (int x = 0; x < sw; ++x) {
            const Sample& s = samples[std::size_t(y) * std::size_t(sw) + std::size_t(x)];
            if (!s.covered) continue;
            pixels[std::size_t(y / view.samples) * std::size_t(view.width) + std::size_t(x / view.samples)] +=
                glm::vec4(s.color, 1.0f) * weight;
        }
    return pixels;
}

engine::assets::RgbaImage toTexture(const std::vector<glm::vec4>& pixels, int width, int height) {
    glm::vec4 sum(0.0f);
    for (const glm::vec4& p : pixels) sum += p;
    const glm::vec3 mean = sum.a > 0.0f ? glm::vec3(sum) / sum.a : glm::vec3(0.0f);
    engine::assets::RgbaImage image = engine::assets::RgbaImage::make(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::vec4 p = pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            const glm::vec3 color = p.a > 0.0f ? glm::vec3(p) / p.a : mean;
            std::uint8_t* texel = image.texel(x, y);
            for (int c = 0; c < 3; ++c) texel[c] = engine::render::encodeSrgb8Exact(color[c]);
            texel[3] = engine::render::encodeUnorm8(p.a);
        }
    return image;
}

}  // namespace content
