// SPDX-License-Identifier: MIT
// Differential test on Vulkan: the random scenes of tests/support/differential_scenes.hpp on the
// soft backend and the Vulkan backend (lavapipe here) under validation, compared pixel by pixel
// with GL's tolerances (written there, and why they hold for lavapipe too). Every case GL runs,
// none left out.
#include <gtest/gtest.h>

#include "differential_scenes.hpp"
#include "vk_validation.hpp"

namespace ssam::test {
namespace {

namespace vk = engine::render::vk;

class VkDifferential : public ::testing::TestWithParam<differential::Case> {};

TEST_P(VkDifferential, RandomScenesMatchTheSoftBackend) {
    vk::VulkanOptions options = ssam::testing::validatedVulkanOptions();
    options.failModes = GetParam().perTriangle ? vk::FailModeStrategy::PerTriangle : vk::FailModeStrategy::TwoPass;
    auto backend = ssam::testing::validatedVulkanBackend(options);
    differential::expectRandomScenesMatchSoft(*backend, "vk", GetParam());
    EXPECT_EQ(engine::render::vk::vulkanDriver(*backend).validationMessages(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Scenes, VkDifferential, ::testing::ValuesIn(differential::cases()),
                         [](const auto& info) { return differential::caseName(info.param); });

}  // namespace
}  // namespace ssam::test
