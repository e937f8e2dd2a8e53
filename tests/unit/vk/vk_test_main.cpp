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

// Under the sanitizers (make test-asan): the Khronos validation layer (1.3.239) keeps allocations
// alive after vkDestroyInstance and is then unloaded (about 300 KiB in 1,300 blocks in
// vk_transparency, 560 KiB in conformance_vk); that is the layer's, not ours. Our own Vulkan objects
// left alive are reported by the layer itself when the device is destroyed, which fails the test,
// and our host allocations have our frames in their stacks, so nothing of ours is hidden. A
// library is named by module, which LeakSanitizer reads only while it is loaded: main() pins the
// layer (RTLD_NODELETE), as the Vulkan loader unloads it with the instance. lavapipe is pinned
// too and then needs no suppression: unloaded, the blocks it allocates once per load (128 bytes
// each time) would lose the globals that point to them and read as leaks.
extern "C" const char* __lsan_default_suppressions() { return "leak:libVkLayer_khronos_validation.so\n"; }
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
