// SPDX-License-Identifier: MIT
// Instantiates the backend-agnostic conformance suites (tests/conformance/suites) for the Vulkan
// backend (lavapipe on CI) under the validation layer: any validation message fails the test
// that caused it. The suites' tolerances are the API's, as on GL.
#include "../backend_fixture.hpp"

#include "engine/render/devices/create_device.hpp"
#include "vk_validation.hpp"

namespace ssam::test {
namespace {

SSAM_INSTANTIATE_CONFORMANCE_SUITES(Vk, ::testing::Values(uncountedCase("lavapipe", [] {
                                        render::DeviceOptions options;
                                        options.vulkan = ssam::testing::validatedVulkanOptions();
                                        return render::createDevice(render::DeviceKind::Vulkan, options);
                                    })));

}  // namespace
}  // namespace ssam::test
