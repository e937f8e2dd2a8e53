// SPDX-License-Identifier: MIT
// main() of the Vulkan test binaries: skips (exit 77) when no Vulkan 1.3 device with the
// validation layer exists here, and says why; with CI=true that is a failure instead (exit 1;
// gpu_test_main.hpp).
#include "engine/render/vk/vk_backend.hpp"
#include "gpu_test_main.hpp"
#include "pin_vulkan_libraries.hpp"

int main(int argc, char** argv) {
    return test_support::runGpuTests(argc, argv, {"Vulkan 1.3 device with validation", true}, [] {
        test_support::pinVulkanLibrariesForLeakSanitizer();
        engine::render::vk::VulkanOptions options;
        options.validation = true;
        return engine::render::vk::vulkanUnavailableReason(options);
    });
}
