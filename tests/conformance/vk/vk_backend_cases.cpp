// SPDX-License-Identifier: MIT
// Instantiates the backend-agnostic conformance suites (tests/conformance/suites) for the Vulkan
// backend (lavapipe on CI) under the validation layer: any validation message fails the test
// that caused it. The suites' tolerances are the API's, as on GL.
#include "../backend_fixture.hpp"

#include "vk_validation.hpp"

namespace ssam::test {
namespace {

BackendCase vkCase(std::string name, engine::render::vk::VulkanOptions options) {
    return {std::move(name),
            [options] { return std::unique_ptr<render::Backend>(engine::render::vk::createVulkanBackend(options)); },
            {}};  // Vulkan does not count dropped triangles
}

SSAM_INSTANTIATE_CONFORMANCE_SUITES(Vk, ::testing::Values(vkCase("lavapipe", ssam::testing::validatedVulkanOptions())));

}  // namespace
}  // namespace ssam::test
