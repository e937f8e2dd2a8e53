// SPDX-License-Identifier: MIT
// Another engine's program using the installed ssam package (find_package(ssam 0.4 COMPONENTS
// soft render_gl gl), or pkg-config ssam ssam-soft ssam-render-gl ssam-gl): renders one half-transparent red leaf over a
// blue opaque scene through SSAM's frame-graph passes on the soft backend, then on the GL backend when a headless
// context can be made here, and checks the composited centre pixel. Also links ssam::gl (the
// raw-OpenGL entry point) and checks that a call before initialize() is a Status, not a throw or
// a crash (no context needed). Exit 0 when every check passes.
#include <cmath>
#include <cstdio>
#include <cstring>

#include <engine/core/error.hpp>
#include <engine/render/frame_graph.hpp>
#include <engine/render/frame_graph/side_effect_pass.hpp>
#include <engine/render/frame_graph/transient_texture_pool.hpp>
#include <engine/render/frame_targets.hpp>
#include <engine/render/gl/gl_backend.hpp>
#include <engine/render/soft/soft_backend.hpp>
#include <engine/render/vertex.hpp>
#include <ssam/frame_graph_passes.hpp>
#include <ssam/gl/ssam_gl.hpp>
#include <ssam/ssam.hpp>
#include <ssam/version.hpp>

using namespace engine::render;

namespace {

// The centre pixel's red and blue after SSAM composites the leaf over the opaque scene.
bool leafOverBlue(Backend& backend, const char* name) {
    engine::render::FrameTargets opaque(backend, {8, 8, 1, Format::RGBA8_UNORM, CompareFunc::Less});
    backend.beginPass(opaque.passDesc({0.0f, 0.0f, 1.0f, 1.0f}));  // opaque scene: blue
    backend.endPass();

    Vertex v[6];
    const float xy[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 6; ++i) {
        v[i].position = {xy[i][0], xy[i][1], 0.5f};
        v[i].color = {1.0f, 0.0f, 0.0f, 0.5f};  // red leaf, alpha 0.5
    }
    const auto bytes = std::as_bytes(std::span(v));
    engine::render::MaskedBatch leaf;
    leaf.vertices = backend.createBuffer({"leaf", BufferKind::Vertex, bytes.size()}, bytes);
    leaf.count = 6;
    leaf.worldBounds = {{-1, -1, 0.5f}, {1, 1, 0.5f}};
    const DirectionalLight unlit{{0, 0, 1}, glm::vec3(0.0f), glm::vec3(1.0f)};

    // SSAM's passes in the engine's frame graph, after the opaque pass; its intermediates are
    // the graph's transients, backed by the pool.
    ssam::ScreenSpaceAlphaMask ssam(backend);
    const ssam::FoliageView view{glm::mat4(1.0f), unlit, std::span(&leaf, 1)};
    FrameGraph graph;
    TransientTexturePool pool(backend);
    const ssam::SsamPasses passes = ssam::addSsamPasses(graph, ssam, view, opaque.importInto(graph).resolved);
    addSideEffectPass(graph, "present", passes.frame);
    graph.execute(pool.allocator());
    const Readback r = backend.readback(opaque.color());
    const float red = r.at(4, 4, 0), blue = r.at(4, 4, 2);
    // mask = lerp(0.5, 0.5, 0.85) = 0.5 (stored 128/255), squared: 0.2520; red = m^2, blue = 1 - m^2.
    const float m = 128.0f / 255.0f, tolerance = 1.0f / 255.0f;
    const bool ok = std::fabs(red - m * m) <= tolerance && std::fabs(blue - (1.0f - m * m)) <= tolerance;
    std::printf("%s: centre pixel red %.4f blue %.4f (expected %.4f, %.4f): %s\n", name, red, blue, m * m, 1.0f - m * m,
                ok ? "ok" : "WRONG");
    return ok;
}

}  // namespace

int main() {
    std::printf("ssam %s; ssam::gl passes: %s, %s\n", SSAM_VERSION_STRING,
                ssam::gl::foliagePassName(ssam::gl::FoliagePass::Mask),
                ssam::gl::foliagePassName(ssam::gl::FoliagePass::Color));
#ifdef EXPECTED_SSAM_VERSION  // the version the package said it was (CMake's ssam_VERSION)
    if (std::strcmp(SSAM_VERSION_STRING, EXPECTED_SSAM_VERSION) != 0) {
        std::printf("version.hpp says %s, the package %s\n", SSAM_VERSION_STRING, EXPECTED_SSAM_VERSION);
        return 1;
    }
#endif
    ssam::gl::ScreenSpaceAlphaMaskGl rawGl;  // no GL until initialize(host's loader)
    const ssam::gl::Status early = rawGl.beginMaskPass();
    std::printf("ssam::gl before initialize(): %s (%s)\n", ssam::gl::statusName(early), rawGl.lastMessage());
    if (early != ssam::gl::Status::InvalidCall) return 1;

    auto soft = soft::createSoftBackend({});
    bool ok = leafOverBlue(*soft, "soft");

    const std::string noGl = gl::HeadlessEglContext::unavailableReason();
    if (noGl.empty()) {
        try {
            auto glBackend = gl::createGlBackend({});
            ok = leafOverBlue(*glBackend, "gl") && ok;
        } catch (const engine::Error& e) {
            std::printf("gl: %s\n", e.what());
            ok = false;
        }
    } else {
        std::printf("gl: skipped, no headless OpenGL 4.5 context here (%s)\n", noGl.c_str());
    }
    return ok ? 0 : 1;
}
