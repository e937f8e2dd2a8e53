// SPDX-License-Identifier: MIT
// Exception safety of every registered living-scene module on the soft backend, iterated from
// the tests' registry (racer's modules and the test-only ones), so a new module is covered
// without editing this file (module_exception_safety.hpp says what is checked;
// vk_module_exception_safety_test.cpp runs the same on Vulkan).
#include <gtest/gtest.h>

#include "engine/render/soft/soft_backend.hpp"
#include "module_exception_safety.hpp"
#include "test_feature_modules.hpp"

namespace racer::testing {
namespace {

class ModuleExceptionSafety : public ::testing::TestWithParam<const engine::scene::FeatureModule*> {};

TEST_P(ModuleExceptionSafety, LeaksNothingAndLeavesTheBackendUsableWhenACreateOrDrawThrows) {
    const auto soft = engine::render::soft::createSoftBackend({1, 64, false});
    expectModuleExceptionSafe(*soft, *GetParam());
}

INSTANTIATE_TEST_SUITE_P(Registered, ModuleExceptionSafety,
                         ::testing::ValuesIn(builtModules(ssam::testing::featureModules())), ModuleName{});

}  // namespace
}  // namespace racer::testing
