// Renders one half-transparent leaf quad through SSAM with the soft backend and prints the
// composited centre pixel; exits non-zero if it is not the expected blend. Also links ssam::gl
// (the raw-OpenGL entry point; no context is needed for what it calls here).
#include <cmath>
#include <cstdio>

#include <engine/render/soft/soft_backend.hpp>
#include <engine/render/vertex.hpp>
#include <ssam/gl/ssam_gl.hpp>
#include <ssam/opaque_targets.hpp>
#include <ssam/ssam.hpp>

int main() {
    using namespace engine::render;
    auto backend = soft::createSoftBackend({});
    ssam::OpaqueTargets opaque(*backend, {8, 8, 1, Format::RGBA8_UNORM, CompareFunc::Less});
    backend->beginPass(opaque.passDesc({0.0f, 0.0f, 1.0f, 1.0f}));  // opaque scene: blue
    backend->endPass();

    Vertex v[6];
    const float xy[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 6; ++i) {
        v[i].position = {xy[i][0], xy[i][1], 0.5f};
        v[i].color = {1.0f, 0.0f, 0.0f, 0.5f};  // red leaf, alpha 0.5
    }
    const auto bytes = std::as_bytes(std::span(v));
    ssam::FoliageBatch leaf;
    leaf.vertices = backend->createBuffer({"leaf", BufferKind::Vertex, bytes.size()}, bytes);
    leaf.count = 6;
    leaf.worldBounds = {{-1, -1, 0.5f}, {1, 1, 0.5f}};
    const DirectionalLight unlit{{0, 0, 1}, glm::vec3(0.0f), glm::vec3(1.0f)};

    ssam::ScreenSpaceAlphaMask ssam(*backend);
    ssam.render({opaque.color(), opaque.depth()}, {glm::mat4(1.0f), unlit, std::span(&leaf, 1)});
    const Readback r = backend->readback(opaque.color());
    const float red = r.at(4, 4, 0), blue = r.at(4, 4, 2);
    std::printf("centre pixel: red %.4f blue %.4f; ssam::gl passes: %s, %s\n", red, blue,
                ssam::gl::foliagePassName(ssam::gl::FoliagePass::Mask),
                ssam::gl::foliagePassName(ssam::gl::FoliagePass::Color));
    // mask = lerp(0.5, 0.5, 0.85) = 0.5 (stored 128/255), squared: 0.2520; red = m^2, blue = 1 - m^2.
    const float m = 128.0f / 255.0f;
    return std::fabs(red - m * m) <= 1.0f / 255.0f && std::fabs(blue - (1.0f - m * m)) <= 1.0f / 255.0f ? 0 : 1;
}
