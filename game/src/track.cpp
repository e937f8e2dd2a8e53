// SPDX-License-Identifier: MIT
#include "track.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace racer {

float terrainHeight(float x, float z) {
    return 6.0f * std::sin(x * 0.011f) * std::cos(z * 0.013f) +
           2.5f * std::sin(x * 0.027f + 1.3f) * std::sin(z * 0.021f);
}

std::uint32_t Random::next() {
    // PCG-XSH-RR 64/32.
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + 1442695040888963407ull;
    const std::uint32_t xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const std::uint32_t rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

namespace {
glm::vec3 catmullRom(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3, float t) {
    const float t2 = t * t, t3 = t2 * t;
    return 0.5f * ((2.0f * p1) + (-p0 + p2) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                   (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * t3);
}
}  // namespace

Track::Track(std::uint32_t seed) {
    Random random(seed);
    constexpr int kControlPoints = 12;
    std::vector<glm::vec3> control;
    for (int i = 0; i < kControlPoints; ++i) {
        const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / kControlPoints;
        const float radius = 220.0f + random.uniform(-60.0f, 60.0f);
        control.emplace_back(radius * std::cos(angle), 0.0f, radius * std::sin(angle));
    }
    constexpr int kSamplesPerSegment = 64;
    for (int i = 0; i < kControlPoints; ++i) {
        const auto& p0 = control[(i + kControlPoints - 1) % kControlPoints];
        const auto& p1 = control[i];
        const auto& p2 = control[(i + 1) % kControlPoints];
        const auto& p3 = control[(i + 2) % kControlPoints];
        for (int s = 0; s < kSamplesPerSegment; ++s) {
            glm::vec3 p = catmullRom(p0, p1, p2, p3, float(s) / kSamplesPerSegment);
            p.y = terrainHeight(p.x, p.z);
            samples_.push_back(p);
        }
    }
    // The road's height: the land under the centre line, box-filtered three times along the
    // loop (close to a Gaussian of sigma 30 m), so grades are gentle and the road does not follow
    // every bump; the ground is cut down to it (ground.hpp).
    constexpr int kHalfWindow = 16;
    const int n = static_cast<int>(samples_.size());
    for (int pass = 0; pass < 3; ++pass) {
        std::vector<float> smoothed(samples_.size());
        for (int i = 0; i < n; ++i) {
            float sum = 0.0f;
            for (int k = -kHalfWindow; k <= kHalfWindow; ++k) sum += samples_[std::size_t((i + k + n) % n)].y;
            smoothed[std::size_t(i)] = sum / float(2 * kHalfWindow + 1);
        }
        for (int i = 0; i < n; ++i) samples_[std::size_t(i)].y = smoothed[std::size_t(i)];
    }
    samples_.push_back(samples_.front());  // closed
    cumulative_.push_back(0.0f);
    for (std::size_t i = 1; i < samples_.size(); ++i)
        cumulative_.push_back(cumulative_.back() + glm::length(samples_[i] - samples_[i - 1]));
    length_ = cumulative_.back();
}

glm::vec3 Track::position(float distance) const {
    float d = std::fmod(distance, length_);
    if (d < 0.0f) d += length_;
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), d);
    const std::size_t i = std::clamp<std::size_t>(std::size_t(it - cumulative_.begin()), 1, samples_.size() - 1);
    const float span = cumulative_[i] - cumulative_[i - 1];
    const float t = span > 0.0f ? (d - cumulative_[i - 1]) / span : 0.0f;
    return glm::mix(samples_[i - 1], samples_[i], t);
}

Track::Nearest Track::nearest(const glm::vec3& p) const {
    Nearest best{0.0f, std::numeric_limits<float>::infinity()};
    const glm::vec2 q(p.x, p.z);
    for (std::size_t i = 0; i + 1 < samples_.size(); ++i) {
        const glm::vec2 a(samples_[i].x, samples_[i].z), b(samples_[i + 1].x, samples_[i + 1].z), ab = b - a;
        const float t = std::clamp(glm::dot(q - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
        const float offset = glm::length(q - (a + ab * t));
        if (offset < best.offset) best = {cumulative_[i] + t * (cumulative_[i + 1] - cumulative_[i]), offset};
    }
    return best;
}

glm::vec3 Track::forward(float distance) const {
    const glm::vec3 d = position(distance + 1.0f) - position(distance - 1.0f);
    return glm::normalize(d);
}

void Track::buildRoad(std::vector<engine::render::Vertex>& vertices, std::vector<std::uint32_t>& indices) const {
    const int steps = static_cast<int>(length_ / 4.0f);
    for (int i = 0; i <= steps; ++i) {
        const float d = length_ * float(i) / float(steps);
        const glm::vec3 p = position(d), f = forward(d);
        const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        for (int s = 0; s < 2; ++s) {
            engine::render::Vertex v;
            v.position = p + side * (s == 0 ? -0.5f : 0.5f) * width();  // level across: p.y
            v.normal = {0.0f, 1.0f, 0.0f};
            v.uv = {float(s), d / 10.0f};
            vertices.push_back(v);
        }
        if (i < steps) {
            const std::uint32_t b = std::uint32_t(2 * i);
            indices.insert(indices.end(), {b, b + 2, b + 1, b + 1, b + 2, b + 3});
        }
    }
}

void Track::buildShoulders(float drop, std::vector<engine::render::Vertex>& vertices,
                           std::vector<std::uint32_t>& indices) const {
    const int steps = static_cast<int>(length_ / 4.0f);
    const float halfWidth = 0.5f * width();
    // Across one side: under the asphalt's edge (10 cm in, 2 cm down: hidden, no gap), then
    // out and down into the ground beside the road.
    const float across[2] = {halfWidth - 0.1f, halfWidth + kShoulderWidth};
    const float down[2] = {0.02f, drop + 0.05f};
    const glm::vec3 slopeNormal = glm::normalize(glm::vec3(down[1] - down[0], across[1] - across[0], 0.0f));
    for (int side = -1; side <= 1; side += 2) {
        const std::uint32_t first = std::uint32_t(vertices.size());
        for (int i = 0; i <= steps; ++i) {
            const float d = length_ * float(i) / float(steps);
            const glm::vec3 p = position(d), f = forward(d);
            const glm::vec3 out = float(side) * glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
            for (int k = 0; k < 2; ++k) {
                engine::render::Vertex v;
                v.position = p + out * across[k] - glm::vec3(0.0f, down[k], 0.0f);
                // The slope's normal: tilted outwards, in the plane of `out` and up.
                v.normal = glm::normalize(out * slopeNormal.x + glm::vec3(0.0f, slopeNormal.y, 0.0f));
                v.uv = {0.2f + 0.2f * float(k), d / 10.0f};
                vertices.push_back(v);
            }
            if (i < steps) {
                const std::uint32_t b = first + std::uint32_t(2 * i);
                indices.insert(indices.end(), {b, b + 2, b + 1, b + 1, b + 2, b + 3});
            }
        }
    }
}

void buildTerrain(float halfSize, int cells, std::vector<engine::render::Vertex>& vertices,
                  std::vector<std::uint32_t>& indices) {
    const float step = 2.0f * halfSize / float(cells);
    for (int z = 0; z <= cells; ++z) {
        for (int x = 0; x <= cells; ++x) {
            const float px = -halfSize + step * float(x), pz = -halfSize + step * float(z);
            engine::render::Vertex v;
            v.position = {px, terrainHeight(px, pz), pz};
            const float e = 0.5f;
            const glm::vec3 dx(2.0f * e, terrainHeight(px + e, pz) - terrainHeight(px - e, pz), 0.0f);
            const glm::vec3 dz(0.0f, terrainHeight(px, pz + e) - terrainHeight(px, pz - e), 2.0f * e);
            v.normal = glm::normalize(glm::cross(dz, dx));
            v.uv = {px / 8.0f, pz / 8.0f};  // ground texture repeats every 8 m
            vertices.push_back(v);
        }
    }
    const std::uint32_t row = std::uint32_t(cells + 1);
    for (int z = 0; z < cells; ++z)
        for (int x = 0; x < cells; ++x) {
            const std::uint32_t i = std::uint32_t(z) * row + std::uint32_t(x);
            indices.insert(indices.end(), {i, i + row, i + 1, i + 1, i + row, i + row + 1});
        }
}

}  // namespace racer
