// SPDX-License-Identifier: MIT
#pragma once
// The main() every test binary that needs a GPU API shares (the GL and Vulkan backends' tests,
// ssam::vk's host tests): listing tests (ctest discovery) never needs the API; otherwise it
// skips (exit 77, ctest SKIP_RETURN_CODE) when the API is not there and says why, or fails
// (exit 1) instead when `failUnderCi` and CI=true, so CI cannot pass without running them.
// llvmpipe and lavapipe compile a shader variant per fixed-function state: Mesa's shader cache
// is pointed into the build tree so later runs reuse them, and LLVM's optimisation passes are
// skipped for these small shaders (GALLIVM_PERF=nopt: a third faster to compile, same results).
// Both only when the environment does not say otherwise.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

namespace test_support {

struct GpuRequirement {
    const char* what;  // what is missing, e.g. "headless OpenGL 4.5 context"
    bool failUnderCi;
};

// `unavailableReason()`: "" when the API can be used here, else why not.
template <class UnavailableReason>
int runGpuTests(int argc, char** argv, const GpuRequirement& requirement, UnavailableReason&& unavailableReason) {
    ::testing::InitGoogleTest(&argc, argv);
    if (GTEST_FLAG_GET(list_tests)) return RUN_ALL_TESTS();
#ifdef SSAM_BINARY_DIR
    setenv("MESA_SHADER_CACHE_DIR", (std::string(SSAM_BINARY_DIR) + "/mesa_shader_cache").c_str(), 0);
#endif
    setenv("GALLIVM_PERF", "nopt", 0);
    const std::string why = unavailableReason();
    if (why.empty()) return RUN_ALL_TESTS();
    const char* ci = std::getenv("CI");
    if (requirement.failUnderCi && ci && std::strcmp(ci, "true") == 0) {
        std::printf("FAILED: CI=true and no %s: %s\n", requirement.what, why.c_str());
        return 1;
    }
    std::printf("SKIPPED: no %s: %s\n", requirement.what, why.c_str());
    return 77;
}

}  // namespace test_support
