// SPDX-License-Identifier: MIT
// The parameter-block probe (tests/support/param_block_probe.hpp) on the Vulkan driver, under
// the validation layer: the std140 block and samplers its block gives compile to SPIR-V and
// every member reaches the body with the value the struct holds (unit_param_block: the soft
// kernel's bits).
#include <gtest/gtest.h>

#include "param_block_probe.hpp"
#include "vk_validation.hpp"

namespace {

TEST(VkParamBlock, EveryMemberReachesTheBody) {
    const auto vulkan = ssam::testing::validatedVulkanBackend();
    const ssam::testing::ProbeParams p = ssam::testing::probeValues();
    for (const bool withDetail : {false, true})
        EXPECT_EQ(ssam::testing::probeMismatches(ssam::testing::drawProbe(*vulkan, p, withDetail), p, withDetail), 0)
            << (withDetail ? "with" : "without") << " the detail texture";
    EXPECT_EQ(engine::render::vk::vulkanDriver(*vulkan).validationMessages(), 0u);
}

}  // namespace
