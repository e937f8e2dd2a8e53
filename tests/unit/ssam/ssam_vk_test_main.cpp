// SPDX-License-Identifier: MIT
// main() of unit_ssam_vk: ssam::vk is host-neutral, so its tests make their Vulkan the way a host
// does (the Vulkan examples' VulkanHost), not through the engine's backend. Skips (exit 77) when
// there is no Vulkan device with the validation layer, and says why; with CI=true that is a
// failure instead (exit 1; gpu_test_main.hpp).
#include <exception>
#include <string>

#include "gpu_test_main.hpp"
#include "vk_host.hpp"

int main(int argc, char** argv) {
    return test_support::runGpuTests(argc, argv, {"Vulkan device with validation", true}, []() -> std::string {
        try {
            vk_example::VulkanHost probe(true);
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    });
}
