// SPDX-License-Identifier: MIT
#include "grass/grass_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/error.hpp"
#include "engine/scene/bounds.hpp"

namespace grass {

void validate(const GrassOptions& o) {
    auto positive = [](float v, const char* field) {
        if (!std::isfinite(v) || !(v > 0.0f))
            throw engine::Error(std::string("GrassOptions.") + field + " = " + std::to_string(v) +
                                " must be finite and positive");
    };
    positive(o.drawDistance, "drawDistance");
    positive(o.height, "height");
    positive(o.width, "width");
    if (!std::isfinite(o.sway) || o.sway < 0.0f) throw engine::Error("GrassOptions.sway must be finite and >= 0");
    if (!std::isfinite(o.swayFrequency) || o.swayFrequency < 0.0f)
        throw engine::Error("GrassOptions.swayFrequency must be finite and >= 0");
    if (!(o.alphaReference >= 0.0f && o.alphaReference <= 1.0f))
        throw engine::Error("GrassOptions.alphaReference must be in [0, 1]");
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(o.windDirection[i])) throw engine::Error("GrassOptions.windDirection is not finite");
    if (!(std::abs(o.windDirection.x) + std::abs(o.windDirection.z) > 0.0f))
        throw engine::Error("GrassOptions.windDirection has no horizontal component");
}

std::vector<engine::render::Instance> visibleTufts(std::span<const Tuft> tufts, const GrassOptions& o,
                                                   const glm::vec3& eye, const glm::mat4& viewProj, float time) {
    constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
    const glm::vec3 along = glm::normalize(glm::vec3(o.windDirection.x, 0.0f, o.windDirection.z));
    const float reach = o.width + o.sway;
    const float distance2 = o.drawDistance * o.drawDistance;
    std::vector<engine::render::Instance> out;
    for (const Tuft& t : tufts) {
        const glm::vec3 d = t.root - eye;
        if (!(glm::dot(d, d) <= distance2)) continue;  // NaN roots are never drawn
        engine::scene::Aabb box;
        box.add(t.root - glm::vec3(reach * t.scale, 0.0f, reach * t.scale));
        box.add(t.root + glm::vec3(reach * t.scale, o.height * t.scale, reach * t.scale));
        if (!engine::scene::intersectsViewVolume(box, viewProj)) continue;
        // Sway: a travelling wave so neighbouring tufts move together, not in lockstep.
        const float phase = kTwoPi * (o.swayFrequency * time) - 0.35f * glm::dot(t.root, along) + 0.5f * t.root.y;
        const float bend = o.sway * (0.6f + 0.4f * std::sin(phase)) / o.height;  // tip offset per metre of height
        const float c = std::cos(t.yaw), s = std::sin(t.yaw);
        glm::mat4 m(1.0f);
        m[0] = glm::vec4(c * t.scale, 0.0f, -s * t.scale, 0.0f);
        m[1] = glm::vec4(along.x * bend * t.scale, t.scale, along.z * bend * t.scale, 0.0f);  // shear: tips downwind
        m[2] = glm::vec4(s * t.scale, 0.0f, c * t.scale, 0.0f);
        m[3] = glm::vec4(t.root, 1.0f);
        out.push_back({m, glm::vec4(1.0f)});
    }
    return out;
}

void buildCard(const GrassOptions& o, std::vector<engine::render::Vertex>& vertices,
               std::vector<std::uint32_t>& indices) {
    for (int q = 0; q < 3; ++q) {
        const float a = float(q) * std::numbers::pi_v<float> / 3.0f;
        const glm::vec3 half(std::cos(a) * o.width * 0.5f, 0.0f, std::sin(a) * o.width * 0.5f);
        const std::uint32_t base = std::uint32_t(vertices.size());
        const glm::vec3 p[4] = {-half, half, half + glm::vec3(0, o.height, 0), -half + glm::vec3(0, o.height, 0)};
        const glm::vec2 uv[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        for (int i = 0; i < 4; ++i) {
            engine::render::Vertex v;
            v.position = p[i];
            v.normal = {0.0f, 1.0f, 0.0f};
            v.uv = {uv[i].x + 0.31f * float(q), uv[i].y};                // each card a different stretch of blades
            v.color = glm::vec4(glm::vec3(i < 2 ? 0.75f : 1.0f), 1.0f);  // darker at the root
            vertices.push_back(v);
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
    }
}

std::vector<std::uint8_t> bladeTexels(int width, int height, std::uint32_t seed) {
    std::vector<std::uint8_t> texels(std::size_t(width) * height * 4, 0);
    std::uint32_t state = seed * 747796405u + 2891336453u;
    auto next = [&] {
        state = state * 747796405u + 2891336453u;
        return float((state >> 8) & 0xFFFF) / 65536.0f;
    };
    const int blades = std::max(1, width / 3);
    for (int b = 0; b < blades; ++b) {
        const float x0 = next() * float(width), lean = (next() - 0.5f) * 0.5f * float(width);
        const float tall = 0.55f + 0.45f * next(), thick = 1.0f + 1.5f * next();
        // One draw per statement: C++ leaves the order of a call's arguments unspecified (GCC
        // right to left, Clang left to right); this is the order GCC gave the goldens.
        const float blue = 0.12f + 0.1f * next(), greenness = 0.55f + 0.25f * next(), red = 0.25f + 0.2f * next();
        const glm::vec3 green(red, greenness, blue);
        for (int y = 0; y < height; ++y) {
            const float h = 1.0f - (float(y) + 0.5f) / float(height);  // 0 at the root (bottom row)
            if (h > tall) continue;
            const float t = h / tall;
            const float cx = x0 + lean * t * t, halfWidth = thick * (1.0f - t) + 0.3f;
            for (int x = 0; x < width; ++x) {
                float dx = std::abs(float(x) + 0.5f - cx);
                dx = std::min(dx, float(width) - dx);  // the texture wraps in u
                const float coverage = std::clamp(halfWidth + 0.5f - dx, 0.0f, 1.0f);
                std::uint8_t* p = &texels[(std::size_t(y) * width + x) * 4];
                if (coverage * 255.0f <= float(p[3])) continue;
                const glm::vec3 c = green * (0.7f + 0.3f * t);
                p[0] = std::uint8_t(c.r * 255.0f), p[1] = std::uint8_t(c.g * 255.0f), p[2] = std::uint8_t(c.b * 255.0f);
                p[3] = std::uint8_t(coverage * 255.0f);
            }
        }
    }
    return texels;
}

}  // namespace grass
