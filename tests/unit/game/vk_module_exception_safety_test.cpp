// SPDX-License-Identifier: MIT
// Exception safety of every registered living-scene module on the Vulkan backend under
// validation (any message fails the test), iterated from the tests' registry as on soft
// (module_exception_safety.hpp says what is checked).
#include <gtest/gtest.h>

#include "module_exception_safety.hpp"
#include "test_feature_modules.hpp"
#include "vk_validation.hpp"

namespace racer::testing {
namespace {

class ModuleExceptionSafetyVk : public ::testing::TestWithParam<const engine::scene::FeatureModule*> {};

TEST_P(ModuleExceptionSafetyVk, LeaksNothingAndLeavesTheBackendUsableWhenACreateOrDrawThrows) {
    const auto vk = ssam::testing::validatedVulkanBackend();
    expectModuleExceptionSafe(*vk, *GetParam());
    EXPECT_EQ(engine::render::vk::vulkanDriver(*vk).validationMessages(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Registered, ModuleExceptionSafetyVk,
                         ::testing::ValuesIn(builtModules(ssam::testing::featureModules())), ModuleName{});

}  // namespace
}  // namespace racer::testing
