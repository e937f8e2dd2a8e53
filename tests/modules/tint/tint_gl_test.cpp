// SPDX-License-Identifier: MIT
// The tint on the GL backend: its GLSL gives the frame the soft kernel gives, within one code
// of the RGBA8 target. Made through the tests' registry, like every module.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/pass_scope.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/mesh_library.hpp"
#include "test_feature_modules.hpp"
#include "tint/tint_module.hpp"
#include "run_feature.hpp"

namespace {

using namespace engine;

constexpr int kW = 16, kH = 8;
const glm::vec4 kFrame{0.8f, 0.6f, 0.4f, 0.7f};

// An RGBA8 frame cleared to kFrame, then the tint's pass over it.
render::Readback tinted(render::Backend& backend) {
    const scene::FeatureModule* tint = nullptr;
    for (const scene::FeatureModule& m : ssam::testing::featureModules())
        if (std::string(m.name) == "tint") tint = &m;
    if (!tint) throw std::runtime_error("tint is not in the tests' registry");
    ecs::Registry registry;
    scene::MeshLibrary library(backend);
    const render::TextureHandle color =
        backend.createTexture(render::renderTargetDesc("frame", kW, kH, render::Format::RGBA8_UNORM), nullptr);
    const render::TextureHandle depth =
        backend.createTexture(render::renderTargetDesc("depth", kW, kH, render::Format::D32F), nullptr);
    render::PassDesc clear;
    clear.name = "frame";
    clear.color[0] = {color, render::LoadOp::Clear, kFrame};
    render::PassScope(backend, clear).end();
    {
        const std::unique_ptr<scene::Feature> feature = tint->make({registry, library, 1, {}});
        const scene::DrawLists lists;
        test_support::runFeatures({feature.get()}, {backend,
                                                    library,
                                                    lists,
                                                    color,
                                                    depth,
                                                    kW,
                                                    kH,
                                                    glm::mat4(1.0f),
                                                    glm::mat4(1.0f),
                                                    glm::mat4(1.0f),
                                                    glm::vec3(0.0f),
                                                    {},
                                                    0.0f,
                                                    render::CompareFunc::Less});
    }
    render::Readback r = backend.readback(color);
    backend.destroy(color);
    backend.destroy(depth);
    return r;
}

TEST(TintGl, MultipliesTheFrameAsOnSoft) {
    const auto soft = render::soft::createSoftBackend({1, 64, false});
    const auto gl = render::gl::createGlBackend();
    const render::Readback onSoft = tinted(*soft), onGl = tinted(*gl);
    ASSERT_EQ(onGl.values.size(), onSoft.values.size());
    float worst = 0.0f;
    for (std::size_t i = 0; i < onGl.values.size(); ++i)
        worst = std::max(worst, std::abs(onGl.values[i] - onSoft.values[i]));
    EXPECT_LE(worst, 1.0f / 255.0f + 1e-6f);
    EXPECT_NEAR(onGl.at(kW / 2, kH / 2, 1), kFrame.g * tint::kTint[1], 1.0f / 255.0f + 1e-6f);
    EXPECT_NEAR(onGl.at(kW / 2, kH / 2, 3), kFrame.a, 1.0f / 255.0f + 1e-6f);
}

}  // namespace
