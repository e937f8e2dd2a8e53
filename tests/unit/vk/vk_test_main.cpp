// SPDX-License-Identifier: MIT
// main() of the Vulkan test binaries: skips (exit 77, ctest SKIP_RETURN_CODE) when no Vulkan 1.3
// device with the validation layer exists here, and says why; with CI=true that is a failure
// instead (exit 1), so CI cannot pass without running them. Listing tests never needs Vulkan.
// lavapipe compiles with llvmpipe's gallivm: Mesa's shader cache is pointed into the build tree
// and LLVM's optimisation passes skipped (GALLIVM_PERF=nopt), as the GL tests do.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "engine/render/vk/vk_backend.hpp"

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (GTEST_FLAG_GET(list_tests)) return RUN_ALL_TESTS();
#ifdef SSAM_BINARY_DIR
    setenv("MESA_SHADER_CACHE_DIR", (std::string(SSAM_BINARY_DIR) + "/mesa_shader_cache").c_str(), 0);
#endif
    setenv("GALLIVM_PERF", "nopt", 0);
    engine::render::vk::VulkanOptions options;
    options.validation = true;
    const std::string why = engine::render::vk::vulkanUnavailableReason(options);
    if (!why.empty()) {
        const char* ci = std::getenv("CI");
        if (ci && std::strcmp(ci, "true") == 0) {
            std::printf("FAILED: CI=true and no Vulkan 1.3 device with validation: %s\n", why.c_str());
            return 1;
        }
        std::printf("SKIPPED: no Vulkan 1.3 device with validation: %s\n", why.c_str());
        return 77;
    }
    return RUN_ALL_TESTS();
}
