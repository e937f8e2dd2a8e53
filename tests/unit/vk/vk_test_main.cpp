// SPDX-License-Identifier: MIT
// main() of the Vulkan test binaries: skips (exit 77) when no Vulkan 1.3 device with the
// validation layer exists here, and says why; with CI=true that is a failure instead (exit 1;
// gpu_test_main.hpp).
#include "engine/render/vk/vk_backend.hpp"
#include "gpu_test_main.hpp"

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
    return test_support::runGpuTests(argc, argv, {"Vulkan 1.3 device with validation", true}, [] {
#if defined(__SANITIZE_ADDRESS__)
        for (const char* library : {"libVkLayer_khronos_validation.so", "libvulkan_lvp.so"})
            dlopen(library, RTLD_NOW | RTLD_NODELETE);  // null where absent: nothing to pin
#endif
        engine::render::vk::VulkanOptions options;
        options.validation = true;
        return engine::render::vk::vulkanUnavailableReason(options);
    });
}
