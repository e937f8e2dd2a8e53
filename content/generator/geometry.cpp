// SPDX-License-Identifier: MIT
#include "geometry.hpp"

#include <array>
#include <cmath>

#include "noise.hpp"

namespace content {

namespace {

constexpr float kPi = 3.14159265358979f;

// Any unit vector perpendicular to n.
glm::vec3 perpendicular(glm::vec3 n) {
    const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    return glm::normalize(glm::cross(n, helper));
}

glm::vec3 randomDirection(Pcg32& rng) {
    const float y = rng.uniform(-1.0f, 1.0f);
    const float phi = rng.uniform(0.0f, 2.0f * kPi);
    const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
    return {r * std::cos(phi), y, r * std::sin(phi)};
}

// A card: centre c, in-plane axes t (u, left to right) and b (up: v = 0 at the top).
void addCard(MeshData& mesh, glm::vec3 c, glm::vec3 t, glm::vec3 b, glm::vec3 normal, glm::vec3 bendFrom) {
    const glm::vec3 corners[4] = {c - t + b, c + t + b, c + t - b, c - t - b};
    const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const std::uint32_t first = static_cast<std::uint32_t>(mesh.vertexCount());
    for (int i = 0; i < 4; ++i) {
        const glm::vec3 radial = glm::normalize(corners[i] - bendFrom);
        mesh.addVertex(corners[i], glm::normalize(0.6f * radial + 0.4f * normal), uvs[i]);
    }
    // Wound counter-clockwise around `normal`.
    const bool ccw = glm::dot(glm::cross(corners[1] - corners[0], corners[2] - corners[0]), normal) > 0.0f;
    const std::uint32_t order[6] = {0, 1, 2, 0, 2, 3};
    const std::uint32_t flipped[6] = {0, 2, 1, 0, 3, 2};
    for (int i = 0; i < 6; ++i) mesh.indices.push_back(first + (ccw ? order[i] : flipped[i]));
}

}  // namespace

std::uint32_t MeshData::addVertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
    positions.push_back(p);
    normals.push_back(n);
    uvs.push_back(uv);
    return static_cast<std::uint32_t>(positions.size() - 1);
}

void MeshData::addQuad(const glm::vec3 (&p)[4], glm::vec3 normal, const glm::vec2 (&uv)[4]) {
    std::uint32_t v[4];
    for (int i = 0; i < 4; ++i) v[i] = addVertex(p[i], normal, uv[i]);
    const bool ccw = glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), normal) > 0.0f;
    if (ccw) indices.insert(indices.end(), {v[0], v[1], v[2], v[0], v[2], v[3]});
    else indices.insert(indices.end(), {v[0], v[2], v[1], v[0], v[3], v[2]});
}

MeshData trunk(float y0, float y1, float radius0, float radius1, int sides, float uRepeat) {
    MeshData mesh;
    const float circumference = 2.0f * kPi * radius0;
    for (int ring = 0; ring < 2; ++ring) {
        const float y = ring == 0 ? y0 : y1;
        const float r = ring == 0 ? radius0 : radius1;
        for (int s = 0; s <= sides; ++s) {  // the seam column is duplicated for continuous u
            const float a = 2.0f * kPi * static_cast<float>(s % sides) / static_cast<float>(sides);
            const glm::vec3 n(std::cos(a), (radius0 - radius1) / (y1 - y0), std::sin(a));
            mesh.addVertex({r * std::cos(a), y, r * std::sin(a)}, glm::normalize(n),
                           {uRepeat * static_cast<float>(s) / static_cast<float>(sides), (y1 - y) / circumference});
        }
    }
    const auto row = static_cast<std::uint32_t>(sides + 1);
    for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(sides); ++s) {
        // Outward-facing: seen from outside, bottom s -> top s -> top s+1 is counter-clockwise.
        mesh.indices.insert(mesh.indices.end(), {s, row + s, row + s + 1, s, row + s + 1, s + 1});
    }
    return mesh;
}

void addCrownLobe(MeshData& mesh, Pcg32& rng, const Lobe& lobe) {
    for (int i = 0; i < lobe.quads; ++i) {
        glm::vec3 offset;
        do {  // uniform in the unit ball, then stretched to the ellipsoid
            // z, y, x: one draw per statement in the order GCC evaluated the constructor's
            // arguments (C++ leaves it unspecified; Clang goes left to right), so the committed
            // assets come out byte for byte with either compiler.
            offset.z = rng.uniform(-1.0f, 1.0f);
            offset.y = rng.uniform(-1.0f, 1.0f);
            offset.x = rng.uniform(-1.0f, 1.0f);
        } while (glm::dot(offset, offset) > 1.0f);
        const glm::vec3 centre = lobe.centre + offset * lobe.radii * 0.8f;
        glm::vec3 normal = randomDirection(rng);
        if (glm::dot(normal, centre - lobe.centre) < 0.0f) normal = -normal;  // face outwards
        const float roll = rng.uniform(0.0f, 2.0f * kPi);
        const glm::vec3 t0 = perpendicular(normal);
        const glm::vec3 b0 = glm::cross(normal, t0);
        const float half = 0.5f * rng.uniform(lobe.sizeMin, lobe.sizeMax);
        const glm::vec3 t = (std::cos(roll) * t0 + std::sin(roll) * b0) * half;
        const glm::vec3 b = (-std::sin(roll) * t0 + std::cos(roll) * b0) * half;
        addCard(mesh, centre, t, b, normal, lobe.centre);
    }
}

void addFronds(MeshData& mesh, Pcg32& rng, glm::vec3 top, int count, float length, float minElevation,
               float maxElevation) {
    for (int i = 0; i < count; ++i) {
        const float heading =
            2.0f * kPi * (static_cast<float>(i) + rng.uniform(-0.3f, 0.3f)) / static_cast<float>(count);
        const float droop = rng.uniform(minElevation, maxElevation);
        const glm::vec3 out(std::cos(heading) * std::cos(droop), std::sin(droop), std::sin(heading) * std::cos(droop));
        const float roll = rng.uniform(-0.5f, 0.5f);  // around the stem, from lying flat
        const glm::vec3 flat = glm::normalize(glm::cross(glm::vec3(0, 1, 0), out));
        const glm::vec3 up = glm::cross(out, flat);
        const glm::vec3 side = std::cos(roll) * flat + std::sin(roll) * up;
        glm::vec3 normal = glm::normalize(glm::cross(side, out));
        if (normal.y < 0.0f) normal = -normal;
        const float half = 0.5f * length * rng.uniform(0.85f, 1.1f);
        // The texture's stem runs from the bottom centre (v = 1) up: b points along `out`.
        addCard(mesh, top + out * half, side * half, out * half, normal, top - glm::vec3(0, length * 0.5f, 0));
    }
}

void addBox(MeshData& mesh, glm::vec3 lo, glm::vec3 hi, glm::vec4 uvRect, glm::vec4 sideRect) {
    const auto uvOf = [](glm::vec4 r) {
        return std::array<glm::vec2, 4>{glm::vec2(r.x, r.y), glm::vec2(r.z, r.y), glm::vec2(r.z, r.w),
                                        glm::vec2(r.x, r.w)};
    };
    struct Face {
        glm::vec3 n;
        glm::vec3 p[4];
        bool side;
    };
    const Face faces[6] = {
        {{0, 1, 0}, {{lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}, false},
        {{0, -1, 0}, {{lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}}, false},
        {{1, 0, 0}, {{hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}}, true},
        {{-1, 0, 0}, {{lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {lo.x, lo.y, hi.z}, {lo.x, lo.y, lo.z}}, true},
        {{0, 0, 1}, {{lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}}, true},
        {{0, 0, -1}, {{hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}}, true},
    };
    for (const Face& f : faces) {
        const auto uv = uvOf(f.side ? sideRect : uvRect);
        mesh.addQuad(f.p, f.n, {uv[0], uv[1], uv[2], uv[3]});
    }
}

void addWheel(MeshData& mesh, glm::vec3 c, float radius, float width, int sides, glm::vec4 r) {
    const float x0 = c.x - 0.5f * width, x1 = c.x + 0.5f * width;
    for (int s = 0; s < sides; ++s) {
        const float a0 = 2.0f * kPi * static_cast<float>(s) / static_cast<float>(sides);
        const float a1 = 2.0f * kPi * static_cast<float>(s + 1) / static_cast<float>(sides);
        const glm::vec3 d0(0, std::cos(a0), std::sin(a0)), d1(0, std::cos(a1), std::sin(a1));
        const float u0 = r.x + (r.z - r.x) * static_cast<float>(s) / static_cast<float>(sides);
        const float u1 = r.x + (r.z - r.x) * static_cast<float>(s + 1) / static_cast<float>(sides);
        const glm::vec3 tread[4] = {glm::vec3(x0, c.y, c.z) + radius * d0, glm::vec3(x1, c.y, c.z) + radius * d0,
                                    glm::vec3(x1, c.y, c.z) + radius * d1, glm::vec3(x0, c.y, c.z) + radius * d1};
        mesh.addQuad(tread, glm::normalize(d0 + d1), {{u0, r.y}, {u0, r.w}, {u1, r.w}, {u1, r.y}});
        for (int side = 0; side < 2; ++side) {  // the hub caps as thin wedges
            const float x = side ? x1 : x0;
            const glm::vec3 n(side ? 1.0f : -1.0f, 0, 0);
            const glm::vec3 centre(x, c.y, c.z);
            const glm::vec3 wedge[4] = {centre, centre, glm::vec3(x, c.y, c.z) + radius * d0,
                                        glm::vec3(x, c.y, c.z) + radius * d1};
            const glm::vec2 hub(0.5f * (r.x + r.z), 0.5f * (r.y + r.w));
            std::uint32_t v[3];
            v[0] = mesh.addVertex(wedge[0], n, hub);
            v[1] = mesh.addVertex(wedge[2], n, {r.x, r.y});
            v[2] = mesh.addVertex(wedge[3], n, {r.z, r.y});
            const bool ccw = glm::dot(glm::cross(wedge[2] - wedge[0], wedge[3] - wedge[0]), n) > 0.0f;
            if (ccw) mesh.indices.insert(mesh.indices.end(), {v[0], v[1], v[2]});
            else mesh.indices.insert(mesh.indices.end(), {v[0], v[2], v[1]});
        }
    }
}

MeshData disc(float radius, int segments) {
    MeshData mesh;
    const glm::vec3 up(0, 1, 0);
    mesh.addVertex({0, 0, 0}, up, {0.5f, 0.5f});
    for (int s = 0; s < segments; ++s) {
        const float a = 2.0f * kPi * static_cast<float>(s) / static_cast<float>(segments);
        const float x = std::cos(a), z = std::sin(a);
        mesh.addVertex({radius * x, 0, radius * z}, up, {0.5f + 0.5f * x, 0.5f + 0.5f * z});
    }
    for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(segments); ++s) {
        const std::uint32_t a = 1 + s, b = 1 + (s + 1) % static_cast<std::uint32_t>(segments);
        mesh.indices.insert(mesh.indices.end(), {0, b, a});  // counter-clockwise seen from +Y
    }
    return mesh;
}

MeshData terrainPatch(float size, int cells, float relief, float uvMetres, std::uint32_t seed) {
    MeshData mesh;
    const auto height = [&](float x, float z) {
        const float u = x / size + 0.5f, v = z / size + 0.5f;
        return relief * (2.0f * fbm(u, v, 3, 3, 4, seed) - 1.0f);
    };
    const float step = size / static_cast<float>(cells);
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const float x = -0.5f * size + step * static_cast<float>(i);
            const float z = -0.5f * size + step * static_cast<float>(j);
            const float e = 0.5f * step;
            const glm::vec3 n = glm::normalize(
                glm::vec3(height(x - e, z) - height(x + e, z), 2.0f * e, height(x, z - e) - height(x, z + e)));
            mesh.addVertex({x, height(x, z), z}, n, {x / uvMetres, z / uvMetres});
        }
    const auto row = static_cast<std::uint32_t>(cells + 1);
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(cells); ++j)
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(cells); ++i) {
            const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});  // counter-clockwise seen from +Y
        }
    return mesh;
}

TrackShape trackShape(std::uint32_t seed, int controlPoints, glm::vec2 radii, int samplesPerSpan, float width) {
    Pcg32 rng(seed);
    TrackShape shape;
    shape.width = width;
    for (int i = 0; i < controlPoints; ++i) {
        const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(controlPoints);
        const float jitter = rng.uniform(0.85f, 1.15f);
        shape.control.push_back(
            {radii.x * jitter * std::cos(a), rng.uniform(-1.5f, 1.5f), radii.y * jitter * std::sin(a)});
    }
    const int n = controlPoints;
    for (int i = 0; i < n; ++i) {  // uniform Catmull-Rom through control[i] .. control[i+1]
        const glm::vec3& p0 = shape.control[static_cast<std::size_t>((i + n - 1) % n)];
        const glm::vec3& p1 = shape.control[static_cast<std::size_t>(i)];
        const glm::vec3& p2 = shape.control[static_cast<std::size_t>((i + 1) % n)];
        const glm::vec3& p3 = shape.control[static_cast<std::size_t>((i + 2) % n)];
        for (int s = 0; s < samplesPerSpan; ++s) {
            const float t = static_cast<float>(s) / static_cast<float>(samplesPerSpan);
            const float t2 = t * t, t3 = t2 * t;
            shape.centreLine.push_back(0.5f *
                                       ((2.0f * p1) + (-p0 + p2) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                                        (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * t3));
        }
    }
    return shape;
}

MeshData trackRibbon(const TrackShape& shape) {
    MeshData mesh;
    const std::size_t n = shape.centreLine.size();
    float distance = 0.0f;
    for (std::size_t i = 0; i <= n; ++i) {  // the first cross-section repeated at the end: v keeps growing
        const glm::vec3 p = shape.centreLine[i % n];
        const glm::vec3 forward = glm::normalize(shape.centreLine[(i + 1) % n] - shape.centreLine[(i + n - 1) % n]);
        const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
        const glm::vec3 normal = glm::normalize(glm::cross(right, forward));
        if (i > 0) distance += glm::length(p - shape.centreLine[i - 1]);
        const float v = distance / shape.width;
        mesh.addVertex(p - right * (0.5f * shape.width), normal, {0.0f, v});
        mesh.addVertex(p + right * (0.5f * shape.width), normal, {1.0f, v});
    }
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
        const std::uint32_t l0 = 2 * i, r0 = l0 + 1, l1 = l0 + 2, r1 = l0 + 3;
        const glm::vec3 up = mesh.normals[l0];
        const bool ccw =
            glm::dot(glm::cross(mesh.positions[r0] - mesh.positions[l0], mesh.positions[l1] - mesh.positions[l0]), up) >
            0.0f;
        if (ccw) mesh.indices.insert(mesh.indices.end(), {l0, r0, l1, r0, r1, l1});
        else mesh.indices.insert(mesh.indices.end(), {l0, l1, r0, r0, l1, r1});
    }
    return mesh;
}

}  // namespace content
