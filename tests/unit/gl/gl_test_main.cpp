// SPDX-License-Identifier: MIT
// main() of the GL test binaries: skips (exit 77, ctest SKIP_RETURN_CODE) when no headless
// EGL context can be created here, and says why. Listing tests (ctest discovery) never needs GL.
// llvmpipe compiles a shader variant per fixed-function state (every blend state is one): Mesa's
// shader cache is pointed into the build tree so later runs reuse them, and LLVM's optimisation
// passes are skipped for these small shaders (GALLIVM_PERF=nopt: a third faster to compile,
// same results). Both only when the environment does not say otherwise.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "engine/render/gl/gl_context.hpp"

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (GTEST_FLAG_GET(list_tests)) return RUN_ALL_TESTS();
#ifdef SSAM_BINARY_DIR
    setenv("MESA_SHADER_CACHE_DIR", (std::string(SSAM_BINARY_DIR) + "/mesa_shader_cache").c_str(), 0);
#endif
    setenv("GALLIVM_PERF", "nopt", 0);
    const std::string why = engine::render::gl::HeadlessEglContext::unavailableReason();
    if (!why.empty()) {
        std::printf("SKIPPED: no headless OpenGL 4.5 context: %s\n", why.c_str());
        return 77;
    }
    return RUN_ALL_TESTS();
}
