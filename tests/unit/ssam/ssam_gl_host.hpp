// SPDX-License-Identifier: MIT
#pragma once
// The "host engine" of the ssam::gl tests: our GL backend in a headless EGL context draws the
// opaque pass, hands its GL texture names to ssam::gl and reads the results back; the host's
// foliage is a plain VAO of position + colour quads at ssam::gl::AttributeLocations (by default SSAM's, or the
// locations a test gives). SSAM gets
// the host's loader, eglGetProcAddress, as a real host would.
#include <gtest/gtest.h>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "engine/render/frame_targets.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "quad_scene.hpp"
#include "ssam/core/settings.hpp"
#include "ssam/ssam.hpp"
#include "ssam/gl/ssam_gl.hpp"

namespace ssam::testing {

inline constexpr int kGlSize = 16;
inline const glm::vec4 kOpaqueColor{0.2f, 0.4f, 0.6f, 1.0f};
inline const engine::render::DirectionalLight kUnlit{{0.0f, 0.0f, 1.0f}, glm::vec3(0.0f), glm::vec3(1.0f)};
// The crossing pair of ssam_cases.hpp: A (alpha 0.4, nearer) on the left, B (alpha 0.2) on the right.
inline const Quad kQuadA{-1.0f, -1.0f, 0.25f, 1.0f, 0.3f, {1.0f, 0.0f, 0.0f, 0.4f}};
inline const Quad kQuadB{-0.25f, -1.0f, 1.0f, 1.0f, 0.6f, {0.0f, 1.0f, 0.0f, 0.2f}};

// One setting a comparison runs: SSAM's settings (the same struct for the engine-hosted SSAM and
// ssam::gl) and the host's colour format.
struct ConfigCase {
    const char* name;
    Settings config;
    engine::render::Format colorFormat = engine::render::Format::RGBA8_UNORM;
};

// SSAM initialised with the host's loader; fails the test with SSAM's message otherwise.
inline std::unique_ptr<ssam::gl::ScreenSpaceAlphaMaskGl> initializedSsam(
    const ssam::gl::Settings& settings = {}, const ssam::gl::AttributeLocations& attributes = {}) {
    auto ssam = std::make_unique<ssam::gl::ScreenSpaceAlphaMaskGl>();
    const ssam::gl::Status status = ssam->initialize(eglGetProcAddress, settings, attributes);
    EXPECT_EQ(status, ssam::gl::Status::Ok) << ssam->lastMessage();
    return ssam;
}

// The host's foliage: one VAO and buffer of position + colour quads, drawn one quad per draw;
// with `instances`, each quad drawn as all of them (model and tint per instance, divisor 1).
struct HostFoliage {
    GLuint vao = 0, buffer = 0, instanceBuffer = 0;
    int quads = 0, instanceCount = 0;
    // `at`: where the host's VAO puts position and colour (the AttributeLocations given to SSAM must say the same).
    explicit HostFoliage(const std::vector<Quad>& qs, const ssam::gl::AttributeLocations& at = {},
                         const std::vector<engine::render::Instance>& instances = {})
        : quads(static_cast<int>(qs.size())), instanceCount(static_cast<int>(instances.size())) {
        std::vector<float> data;
        for (const Quad& q : qs)
            for (const engine::render::Vertex& v : quadVertices(q))
                data.insert(data.end(),
                            {v.position.x, v.position.y, v.position.z, v.color.r, v.color.g, v.color.b, v.color.a});
        glGenVertexArrays(1, &vao);
        glGenBuffers(1, &buffer);
        glBindVertexArray(vao);
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
        glEnableVertexAttribArray(at.position);
        glVertexAttribPointer(at.position, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
        glEnableVertexAttribArray(at.color);
        glVertexAttribPointer(at.color, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float),
                              reinterpret_cast<const void*>(3 * sizeof(float)));
        if (!instances.empty()) {
            using engine::render::Instance;
            glGenBuffers(1, &instanceBuffer);
            glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer);
            glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(instances.size() * sizeof(Instance)), instances.data(),
                         GL_STATIC_DRAW);
            const auto perInstance = [](GLuint location, std::size_t offset) {
                glEnableVertexAttribArray(location);
                glVertexAttribPointer(location, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                                      reinterpret_cast<const void*>(offset));
                glVertexAttribDivisor(location, 1);
            };
            for (unsigned int c = 0; c < 4; ++c) perInstance(at.instanceModel + c, c * sizeof(glm::vec4));
            perInstance(at.instanceTint, offsetof(Instance, tint));
        }
        glBindVertexArray(0);
    }
    ~HostFoliage() {
        glDeleteBuffers(1, &instanceBuffer);
        glDeleteBuffers(1, &buffer);
        glDeleteVertexArrays(1, &vao);
    }
    void draw() const {
        glBindVertexArray(vao);
        for (int i = 0; i < quads; ++i)
            if (instanceCount > 0) glDrawArraysInstanced(GL_TRIANGLES, i * 6, 6, instanceCount);
            else glDrawArrays(GL_TRIANGLES, i * 6, 6);
    }
};

inline std::vector<ssam::gl::Box> boxesOf(const std::vector<Quad>& qs) {
    std::vector<ssam::gl::Box> out;
    for (const Quad& q : qs) out.push_back({{q.x0, q.y0, q.depth}, {q.x1, q.y1, q.depth}});
    return out;
}

struct GlHost {
    std::unique_ptr<engine::render::Device> backend = engine::render::gl::createGlBackend({});

    // Opaque targets cleared to kOpaqueColor and the far depth (plus optional opaque quads).
    std::unique_ptr<engine::render::FrameTargets> opaque(
        engine::render::CompareFunc depthFunc = engine::render::CompareFunc::Less,
        engine::render::Format format = engine::render::Format::RGBA8_UNORM, const std::vector<Quad>& quads = {}) {
        using namespace engine::render;
        auto targets = std::make_unique<engine::render::FrameTargets>(
            *backend, engine::render::FrameTargetsDesc{kGlSize, kGlSize, 1, format, depthFunc});
        PipelineDesc p;
        p.name = "opaque flat";
        p.depth = DepthState::testAndWrite(depthFunc);
        const PipelineHandle pipeline = backend->createPipeline(p);
        QuadBatches geometry(*backend, quads);
        backend->beginPass(targets->passDesc(kOpaqueColor));
        geometry.drawFlat(pipeline);
        backend->endPass();
        backend->destroy(pipeline);
        return targets;
    }

    ssam::gl::FrameDesc frameOf(const engine::render::FrameTargets& t) const {
        ssam::gl::FrameDesc f;
        f.colorTexture = engine::render::gl::glTexture(*backend, t.color());
        f.depthTexture = engine::render::gl::glTexture(*backend, t.depth());
        f.width = f.height = kGlSize;
        return f;  // identity viewProj, unlit
    }

    engine::render::Readback readGl(unsigned int name, engine::render::Format format) {
        using namespace engine::render;
        TextureDesc desc;
        desc.name = "ssam::gl target";
        desc.width = desc.height = kGlSize;
        desc.format = format;
        desc.usage = UsageRenderTarget | UsageSampled;
        const TextureHandle h = engine::render::gl::importTexture(*backend, name, desc);
        Readback r = backend->readback(h);
        backend->destroy(h);
        return r;
    }
};

// Where most ssam::gl tests start: a host with its opaque frame drawn and ssam::gl initialised,
// made in that order. `auto&& [host, targets, ssam] = HostWithSsam{};` names the three.
struct HostWithSsam {
    GlHost host;
    std::unique_ptr<engine::render::FrameTargets> targets = host.opaque();
    std::unique_ptr<ssam::gl::ScreenSpaceAlphaMaskGl> ssam = initializedSsam();
};

// A host GL state unlike anything SSAM sets; expectRestored() checks that every piece is back.
struct HostGlState {
    GLuint fbo = 0, vao = 0, texture = 0;
    HostGlState() {
        glGenFramebuffers(1, &fbo);
        glGenVertexArrays(1, &vao);
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    }
    ~HostGlState() {
        glDisable(GL_COLOR_LOGIC_OP);
        glDisable(GL_STENCIL_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fbo);
        glDeleteVertexArrays(1, &vao);
        glDeleteTextures(1, &texture);
    }
    void set() const {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(1, 2, 3, 4);
        glScissor(5, 6, 7, 8);
        glEnable(GL_SCISSOR_TEST);
        glEnable(GL_CULL_FACE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GEQUAL);
        glDepthMask(GL_FALSE);
        glEnablei(GL_BLEND, 0);
        glDisablei(GL_BLEND, 1);
        glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MIN);
        glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA);
        glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glEnable(GL_COLOR_LOGIC_OP);
        glBindVertexArray(vao);
        glActiveTexture(GL_TEXTURE2);
        glBindTexture(GL_TEXTURE_2D, texture);
        glActiveTexture(GL_TEXTURE1);
        glVertexAttrib4f(3, 0.25f, 0.5f, 0.75f, 1.0f);
        glUseProgram(0);
    }
    void expectRestored() const {
        GLint i = 0, v[4] = {};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &i);
        EXPECT_EQ(GLuint(i), fbo);
        glGetIntegerv(GL_VIEWPORT, v);
        EXPECT_EQ((std::vector<GLint>(v, v + 4)), (std::vector<GLint>{1, 2, 3, 4}));
        glGetIntegerv(GL_SCISSOR_BOX, v);
        EXPECT_EQ((std::vector<GLint>(v, v + 4)), (std::vector<GLint>{5, 6, 7, 8}));
        EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
        EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
        EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST));
        EXPECT_FALSE(glIsEnabled(GL_FRAMEBUFFER_SRGB));
        EXPECT_TRUE(glIsEnabled(GL_COLOR_LOGIC_OP));
        glGetIntegerv(GL_DEPTH_FUNC, &i);
        EXPECT_EQ(i, GL_GEQUAL);
        GLboolean b[4] = {};
        glGetBooleanv(GL_DEPTH_WRITEMASK, b);
        EXPECT_FALSE(b[0]);
        EXPECT_TRUE(glIsEnabledi(GL_BLEND, 0));
        EXPECT_FALSE(glIsEnabledi(GL_BLEND, 1));
        glGetIntegerv(GL_BLEND_EQUATION_RGB, &i);
        EXPECT_EQ(i, GL_FUNC_SUBTRACT);
        glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &i);
        EXPECT_EQ(i, GL_MIN);
        glGetIntegerv(GL_BLEND_SRC_RGB, &i);
        EXPECT_EQ(i, GL_DST_COLOR);
        glGetIntegerv(GL_BLEND_DST_ALPHA, &i);
        EXPECT_EQ(i, GL_SRC_ALPHA);
        glGetIntegeri_v(GL_BLEND_EQUATION_RGB, 1, &i);
        EXPECT_EQ(i, GL_FUNC_SUBTRACT);
        glGetBooleanv(GL_COLOR_WRITEMASK, b);
        EXPECT_TRUE(b[0] && !b[1] && b[2] && !b[3]);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &i);
        EXPECT_EQ(GLuint(i), vao);
        glGetIntegerv(GL_CURRENT_PROGRAM, &i);
        EXPECT_EQ(i, 0);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &i);
        EXPECT_EQ(i, GL_TEXTURE1);
        glActiveTexture(GL_TEXTURE2);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &i);
        EXPECT_EQ(GLuint(i), texture);
        glActiveTexture(GL_TEXTURE1);
        GLfloat attribute[4] = {};
        glGetVertexAttribfv(3, GL_CURRENT_VERTEX_ATTRIB, attribute);
        EXPECT_EQ((std::vector<float>(attribute, attribute + 4)), (std::vector<float>{0.25f, 0.5f, 0.75f, 1.0f}));
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
};

inline void expectNear(const engine::render::Readback& a, const engine::render::Readback& b, float tolerance,
                       const std::string& what) {
    ASSERT_EQ(a.values.size(), b.values.size()) << what;
    int bad = 0;
    for (std::size_t i = 0; i < a.values.size(); ++i)
        if (!(std::fabs(a.values[i] - b.values[i]) <= tolerance) && bad++ < 5)
            ADD_FAILURE() << what << ": value " << i << " is " << a.values[i] << ", expected " << b.values[i];
}

}  // namespace ssam::testing
