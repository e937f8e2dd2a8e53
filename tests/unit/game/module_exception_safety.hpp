// SPDX-License-Identifier: MIT
#pragma once
// Exception safety of one registered living-scene module over any backend (soft in
// unit_module_registry, Vulkan in vk_module_registry): the backend throws at each create and at
// each draw that the module's construction and first frame reach, one at a time. After every
// throw the backend still runs a pass, and exactly the resources live before are live again.
#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "module_bench.hpp"

namespace racer::testing {

// Adds a GoogleTest failure for each leak, missed throw or unusable backend.
inline void expectModuleExceptionSafe(engine::render::Backend& inner, const engine::scene::FeatureModule& module) {
    ModuleBench bench(inner);
    ssam::testing::FailingBackend& backend = bench.backend;
    const int live = backend.live;

    // A clean first frame: how many creates and draws it reaches.
    const int createsBefore = backend.creates, drawsBefore = backend.draws;
    bench.firstFrame(module);
    const int creates = backend.creates - createsBefore, draws = backend.draws - drawsBefore;
    EXPECT_EQ(backend.live, live) << "a clean construction and frame leaked";
    EXPECT_GT(creates + draws, 0) << "the first frame reached no create and no draw: nothing is checked";

    for (int n = 0; n < creates; ++n) {
        backend.failAt = backend.creates + n;
        EXPECT_THROW(bench.firstFrame(module), engine::Error)
            << "create " << n << " of " << creates << " was not reached";
        backend.failAt = -1;
        EXPECT_EQ(backend.live, live) << "leaked after create " << n << " of " << creates << " threw";
        EXPECT_TRUE(bench.usable()) << "unusable after create " << n << " threw";
    }
    for (int n = 0; n < draws; ++n) {
        backend.failDrawAt = backend.draws + n;
        EXPECT_THROW(bench.firstFrame(module), engine::Error) << "draw " << n << " of " << draws << " was not reached";
        backend.failDrawAt = -1;
        EXPECT_EQ(backend.live, live) << "leaked after draw " << n << " of " << draws << " threw";
        EXPECT_TRUE(bench.usable()) << "unusable (a pass left open?) after draw " << n << " threw";
    }
}

}  // namespace racer::testing
