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

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>

// Under the sanitizers (make test-asan) the validation layer and lavapipe are pinned (RTLD_NODELETE):
// the Vulkan loader unloads both with the instance, and LeakSanitizer can name a module only while
// it is loaded. Unloaded, lavapipe would also lose the globals that point to the blocks it
// allocates once per load (128 bytes each time), which would then read as leaks of no module.
// What these libraries leak themselves is suppressed by name (tests/lsan.supp says why nothing of
// ours hides behind that).
#endif

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (GTEST_FLAG_GET(list_tests)) return RUN_ALL_TESTS();
#if defined(__SANITIZE_ADDRESS__)
    for (const char* library : {"libVkLayer_khronos_validation.so", "libvulkan_lvp.so"})
        dlopen(library, RTLD_NOW | RTLD_NODELETE);  // null where absent: nothing to pin
#endif
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
