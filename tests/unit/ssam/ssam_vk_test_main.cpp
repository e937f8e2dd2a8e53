// SPDX-License-Identifier: MIT
// main() of unit_ssam_vk: ssam::vk is host-neutral, so its tests make their Vulkan the way a host
// does (the Vulkan examples' VulkanHost), not through the engine's backend. Skips (exit 77,
// ctest SKIP_RETURN_CODE) when there is no Vulkan device with the validation layer, and says why;
// with CI=true that is a failure instead (exit 1). Listing tests never needs Vulkan.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "vk_host.hpp"

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (GTEST_FLAG_GET(list_tests)) return RUN_ALL_TESTS();
#ifdef SSAM_BINARY_DIR
    setenv("MESA_SHADER_CACHE_DIR", (std::string(SSAM_BINARY_DIR) + "/mesa_shader_cache").c_str(), 0);
#endif
    setenv("GALLIVM_PERF", "nopt", 0);
    try {
        vk_example::VulkanHost probe(true);
    } catch (const std::exception& e) {
        const char* ci = std::getenv("CI");
        if (ci && std::strcmp(ci, "true") == 0) {
            std::printf("FAILED: CI=true and no Vulkan device with validation: %s\n", e.what());
            return 1;
        }
        std::printf("SKIPPED: no Vulkan device with validation: %s\n", e.what());
        return 77;
    }
    return RUN_ALL_TESTS();
}
