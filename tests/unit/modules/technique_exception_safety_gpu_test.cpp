// SPDX-License-Identifier: MIT
// Exception safety of every technique on GL and on Vulkan under validation (gpu_backend.hpp; on
// Vulkan any validation message fails the test), iterated from allTechniques() as on soft
// (technique_exception_safety.hpp says what is checked). A technique the device refuses when
// made (a2c8 without 8x MSAA, the reference anywhere but on soft) is skipped with the refusal,
// which TechniquesGl / TechniquesVk check.
#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "gpu_backend.hpp"
#include "technique_exception_safety.hpp"

namespace transparency::testing {
namespace {

class SSAM_GPU_SUITE(TechniqueExceptionSafety) : public ::testing::TestWithParam<TechniqueKind> {};

TEST_P(SSAM_GPU_SUITE(TechniqueExceptionSafety), LeaksNothingAndLeavesTheBackendUsableWhenACreateOrDrawThrows) {
    const auto inner = gpuBackend();
    try {
        createTechnique(GetParam(), *inner, {});
    } catch (const engine::Error& e) {
        GTEST_SKIP() << "refused on " << kGpuName << ": " << e.what();
    }
    expectTechniqueExceptionSafe(*inner, GetParam());
}

// INSTANTIATE_TEST_SUITE_P pastes its suite argument unexpanded: one macro level expands it first.
#define SSAM_INSTANTIATE(prefix, suite, ...) INSTANTIATE_TEST_SUITE_P(prefix, suite, __VA_ARGS__)
SSAM_INSTANTIATE(Every, SSAM_GPU_SUITE(TechniqueExceptionSafety),
                 ::testing::ValuesIn(allTechniques().begin(), allTechniques().end()), techniqueParamName);

}  // namespace
}  // namespace transparency::testing
