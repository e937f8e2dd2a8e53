// SPDX-License-Identifier: MIT
#pragma once
// Exception safety of one technique over any backend (soft in unit_transparency, GL in
// gl_transparency, Vulkan in vk_transparency): the backend throws at each create and at each
// draw that making the technique and drawing its first frame reach, one at a time. After every
// throw the backend still runs a pass, and exactly the resources live before are live again.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/pass_scope.hpp"
#include "failing_backend.hpp"  // tests/support
#include "technique_fixture.hpp"

namespace transparency::testing {

// Whether `backend` still runs a pass: clears `target` to green and reads green back.
inline bool usable(Backend& backend, TextureHandle target) {
    PassDesc green;
    green.name = "usable";
    green.color[0] = {target, LoadOp::Clear, {0.0f, 1.0f, 0.0f, 1.0f}};
    PassScope(backend, green).end();
    const Readback r = backend.readback(target);
    return r.at(1, 1, 0) == 0.0f && r.at(1, 1, 1) == 1.0f;
}

// Adds a GoogleTest failure for each leak, missed throw or unusable backend; `inner` must accept
// the technique (a backend that refuses it is the caller's to skip).
inline void expectTechniqueExceptionSafe(Backend& inner, TechniqueKind kind) {
    const TechniqueOptions options;
    const int samples = createTechnique(kind, inner, options)->opaqueSamples();
    ssam::testing::FailingBackend backend(inner);
    // Two overlapping translucent quads: every technique has foliage to draw.
    TechniqueFrame frame(backend, samples,
                         {{-0.8f, -0.8f, 0.5f, 0.5f, 0.5f, {1.0f, 0.0f, 0.0f, 0.5f}},
                          {-0.5f, -0.5f, 0.8f, 0.8f, 0.3f, {0.0f, 1.0f, 0.0f, 0.7f}}});
    frame.opaquePass();
    const TextureHandle probe = backend.createTexture(renderTargetDesc("probe", 4, 4, Format::RGBA8_UNORM), nullptr);
    const int live = backend.live;
    const auto firstFrame = [&] {
        test_support::runTechnique(backend, *createTechnique(kind, backend, options), frame.opaque, frame.frame());
    };

    // A clean first frame: how many creates and draws it reaches.
    const int createsBefore = backend.creates, drawsBefore = backend.draws;
    firstFrame();
    const int creates = backend.creates - createsBefore, draws = backend.draws - drawsBefore;
    EXPECT_EQ(backend.live, live) << "a clean first frame leaked";
    EXPECT_GT(creates, 0);
    EXPECT_GT(draws, 0);

    // Makes the `n`th of the first frame's `count` creates (or draws) throw, for every n:
    // `failAt` is the backend's trigger, `calls` its running count of those calls.
    const auto failEachCall = [&](const char* call, int count, int& failAt, const int& calls) {
        for (int n = 0; n < count; ++n) {
            failAt = calls + n;
            EXPECT_THROW(firstFrame(), engine::Error) << call << " " << n << " of " << count << " was not reached";
            failAt = -1;
            EXPECT_EQ(backend.live, live) << "leaked after " << call << " " << n << " of " << count << " threw";
            EXPECT_TRUE(usable(backend, probe))
                << "unusable (a pass left open?) after " << call << " " << n << " threw";
        }
    };
    failEachCall("create", creates, backend.failAt, backend.creates);
    failEachCall("draw", draws, backend.failDrawAt, backend.draws);
    backend.destroy(probe);
}

// The test parameter's name: "hashed+taa" is "hashed_taa", "alpha-test" is "alpha_test".
inline std::string techniqueParamName(const ::testing::TestParamInfo<TechniqueKind>& info) {
    std::string name = techniqueName(info.param);
    std::replace(name.begin(), name.end(), '-', '_');
    std::replace(name.begin(), name.end(), '+', '_');
    return name;
}

}  // namespace transparency::testing
