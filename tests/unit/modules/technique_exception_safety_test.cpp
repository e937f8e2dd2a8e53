// SPDX-License-Identifier: MIT
// Exception safety of every technique on the soft backend, iterated from allTechniques() so that
// a new one is covered without editing this file (technique_exception_safety.hpp says what is
// checked; technique_exception_safety_gpu_test.cpp runs the same on GL and Vulkan).
#include <gtest/gtest.h>

#include "technique_exception_safety.hpp"

namespace transparency::testing {
namespace {

class TechniqueExceptionSafety : public ::testing::TestWithParam<TechniqueKind> {};

TEST_P(TechniqueExceptionSafety, LeaksNothingAndLeavesTheBackendUsableWhenACreateOrDrawThrows) {
    const auto inner = soft::createSoftBackend({1, 64, false});
    expectTechniqueExceptionSafe(*inner, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Every, TechniqueExceptionSafety,
                         ::testing::ValuesIn(allTechniques().begin(), allTechniques().end()), techniqueParamName);

}  // namespace
}  // namespace transparency::testing
