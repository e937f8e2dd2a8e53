// SPDX-License-Identifier: MIT
// main() of the GL test binaries: skips (exit 77) when no headless EGL context can be created
// here, and says why (gpu_test_main.hpp).
#include "engine/render/gl/gl_context.hpp"
#include "gpu_test_main.hpp"

int main(int argc, char** argv) {
    return test_support::runGpuTests(argc, argv, {"headless OpenGL 4.5 context", false},
                                     [] { return engine::render::gl::HeadlessEglContext::unavailableReason(); });
}
