// SPDX-License-Identifier: MIT
// main() of the GLES test binaries: skips (exit 77) when no headless EGL OpenGL ES 3.0 context
// with what the GLES driver needs can be made here, and says why (gpu_test_main.hpp).
#include "engine/render/gles/gles_backend.hpp"
#include "gpu_test_main.hpp"

int main(int argc, char** argv) {
    return test_support::runGpuTests(argc, argv, {"headless OpenGL ES 3.0 context", false},
                                     [] { return engine::render::gles::glesUnavailableReason(); });
}
