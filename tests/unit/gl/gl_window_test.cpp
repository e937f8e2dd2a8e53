// SPDX-License-Identifier: MIT
// A GLFW window through the GL backend, run under `xvfb-run -a` by ctest: renders frames
// and presents them, is resized to 0x0 (minimised: rendering is skipped, nothing breaks)
// and back, reads back what it drew, and closes cleanly. Exits 77 (skipped) when there is
// no display to open a window on. Not a gtest binary: one process, one window.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include <epoxy/gl.h>

#include "draws.hpp"  // tests/support
#include "engine/core/error.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/vertex.hpp"

namespace {

namespace render = engine::render;
namespace gl = engine::render::gl;
using ssam::testing::meshDraw;

int failures = 0;

void check(bool ok, const char* what) {
    std::printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    if (!ok) ++failures;
}

// Renders one frame into `color` (size of the window's framebuffer) and presents it.
bool frame(render::Device& backend, gl::GlfwWindowContext& window, render::TextureHandle& color, int& width,
           int& height, render::PipelineHandle pipeline, render::BufferHandle triangle, int index) {
    window.pollEvents();
    const glm::ivec2 size = window.framebufferSize();
    if (size.x <= 0 || size.y <= 0) return false;  // minimised: skip the frame entirely
    if (size.x != width || size.y != height) {
        if (color) backend.destroy(color);
        color = backend.createTexture({"frame", size.x, size.y, render::Format::RGBA8_SRGB, 1, 1,
                                       render::UsageRenderTarget | render::UsageSampled});
        width = size.x, height = size.y;
    }
    render::PassDesc pass;
    pass.name = "frame";
    pass.color[0] = {color, render::LoadOp::Clear, {0.1f, 0.2f, 0.3f + 0.01f * float(index % 10), 1.0f}};
    backend.beginPass(pass);
    backend.draw(meshDraw(pipeline, render::FlatParams{glm::mat4(1.0f), {1.0f, 0.5f, 0.0f, 1.0f}}, triangle, 3));
    backend.endPass();
    return backend.present(color);
}

bool waitForSize(gl::GlfwWindowContext& window, int width, int height) {
    for (int i = 0; i < 200; ++i) {
        window.pollEvents();
        const glm::ivec2 s = window.framebufferSize();
        if (s.x == width && s.y == height) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
}

}  // namespace

int main() {
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) {
        std::printf("SKIPPED: no DISPLAY (run under xvfb-run -a)\n");
        return 77;
    }
    try {
        std::shared_ptr<gl::GlfwWindowContext> window;
        try {
            gl::GlfwWindowOptions options;
            options.title = "ssam gl window test";
            options.width = 320;
            options.height = 200;
            options.vsync = false;
            window = gl::GlfwWindowContext::create(options);
        } catch (const engine::Error& e) {
            std::printf("SKIPPED: cannot open a window: %s\n", e.what());
            return 77;
        }
        std::printf("window: %s (GL %d.%d)\n", window->describe().c_str(), window->glMajor(), window->glMinor());
        check(window->glMajor() == 4 && window->glMinor() >= 3, "core 4.3+ context");
        gl::GlOptions options;
        options.context = window;
        auto backend = gl::createGlBackend(options);
        check(engine::render::gl::glDriver(*backend).context() == window.get(), "backend uses the window's context");

        render::PipelineDesc flat;
        flat.name = "flat";
        const render::PipelineHandle pipeline = backend->createPipeline(flat);
        std::vector<render::Vertex> tri(3);
        tri[0].position = {-0.5f, -0.5f, 0.5f};
        tri[1].position = {0.5f, -0.5f, 0.5f};
        tri[2].position = {0.0f, 0.5f, 0.5f};
        const render::BufferHandle triangle =
            backend->createBuffer({"triangle", render::BufferKind::Vertex, tri.size() * sizeof(render::Vertex)},
                                  std::as_bytes(std::span(tri)));

        render::TextureHandle color;
        int width = 0, height = 0, presented = 0;
        for (int i = 0; i < 10; ++i) presented += frame(*backend, *window, color, width, height, pipeline, triangle, i);
        check(presented == 10, "10 frames presented");
        check(width == 320 && height == 200, "frame size = framebuffer size");
        const render::Readback r = backend->readback(color);
        check(r.at(160, 100, 0) == 1.0f && r.at(5, 5, 0) < 0.5f, "frame contents (triangle at the centre)");

        // What reached the window. The back buffer after the swap still holds the frame on
        // Mesa's software winsys (GL leaves it undefined; elsewhere this check is skipped).
        // Its row 0 is the bottom: the triangle's wide base (low in the image) must be there,
        // and the stored codes must arrive unchanged.
        auto windowPixel = [&](int x, int rowFromTop) {
            std::uint8_t p[4] = {};
            glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
            glReadBuffer(GL_BACK);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(x, height - 1 - rowFromTop, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
            return glm::ivec3(p[0], p[1], p[2]);
        };
        auto stored = [&](int x, int y) {
            return glm::ivec3(glm::round(glm::vec3(r.at(x, y, 0), r.at(x, y, 1), r.at(x, y, 2)) * 255.0f));
        };
        if (windowPixel(120, 145) == glm::ivec3(0) && windowPixel(120, 55) == glm::ivec3(0)) {
            std::printf("note: the back buffer is not kept after a swap here; presented pixels not checked\n");
        } else {
            check(windowPixel(120, 145) == stored(120, 145) && windowPixel(120, 55) == stored(120, 55) &&
                      stored(120, 145) != stored(120, 55),
                  "presented upright with the stored codes (row 0 at the top of the window)");
        }

        window->setSize(0, 0);
        check(window->minimized(), "0x0 minimises");
        check(window->framebufferSize() == glm::ivec2(0, 0), "minimised framebuffer is 0x0");
        int skipped = 0;
        for (int i = 0; i < 5; ++i) skipped += !frame(*backend, *window, color, width, height, pipeline, triangle, i);
        check(skipped == 5, "frames skipped while minimised");
        check(!backend->present(color), "present skipped while minimised");

        window->setSize(400, 240);
        check(!window->minimized(), "non-zero size restores");
        check(waitForSize(*window, 400, 240), "framebuffer resized to 400x240");
        presented = 0;
        for (int i = 0; i < 5; ++i) presented += frame(*backend, *window, color, width, height, pipeline, triangle, i);
        check(presented == 5 && width == 400 && height == 240, "frames presented at the new size");

        window->setVsync(true);
        check(window->vsync(), "vsync can be switched on");
        window->requestClose();
        window->pollEvents();
        check(window->shouldClose(), "close requested");
        backend.reset();
        window.reset();
        check(true, "closed cleanly");
    } catch (const std::exception& e) {
        std::printf("FAIL exception: %s\n", e.what());
        return 1;
    }
    std::printf("%s\n", failures ? "FAILED" : "PASSED");
    return failures ? 1 : 0;
}
