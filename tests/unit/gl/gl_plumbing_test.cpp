// SPDX-License-Identifier: MIT
// The shared GL plumbing (no GL): buildProgram over a fake entry-point table, so its error text
// and its clean-up on every failure path are checked without a driver that happens to fail
// there, and the framebuffer status names.
#include <GL/glcorearb.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>

#include <gtest/gtest.h>

#include "engine/render/gl/plumbing/build_program.hpp"
#include "engine/render/gl/plumbing/framebuffer_status_name.hpp"

namespace engine::render::gl::plumbing {
namespace {

// What the fake driver answers and what it holds. GL entry points are plain function pointers,
// so the fake functions reach it through a global.
struct FakeGl {
    bool createShaderFails = false;
    GLint vertexCompiles = GL_TRUE, fragmentCompiles = GL_TRUE, links = GL_TRUE;
    std::string shaderLog, programLog;  // drivers end theirs with newlines and a NUL
    std::map<GLuint, GLenum> shaders;   // alive: name -> stage
    std::map<GLuint, std::string> sources;
    std::set<GLuint> programs;                     // alive
    std::set<std::pair<GLuint, GLuint>> attached;  // (program, shader)
    bool deletedAttachedShader = false;
    GLuint next = 1;
};
FakeGl* fake = nullptr;

GLuint APIENTRY createShader(GLenum stage) {
    if (fake->createShaderFails) return 0;
    fake->shaders[fake->next] = stage;
    return fake->next++;
}
void APIENTRY shaderSource(GLuint shader, GLsizei, const GLchar* const* text, const GLint* length) {
    fake->sources[shader] = length ? std::string(text[0], std::size_t(length[0])) : std::string(text[0]);
}
void APIENTRY compileShader(GLuint) {}
void copyLog(const std::string& log, GLsizei size, GLchar* out) {
    if (size > 0) std::memcpy(out, log.c_str(), std::min(std::size_t(size), log.size() + 1));
}
void APIENTRY getShaderiv(GLuint shader, GLenum name, GLint* out) {
    if (name == GL_COMPILE_STATUS)
        *out = fake->shaders.at(shader) == GL_VERTEX_SHADER ? fake->vertexCompiles : fake->fragmentCompiles;
    if (name == GL_INFO_LOG_LENGTH) *out = GLint(fake->shaderLog.size() + 1);
}
void APIENTRY getShaderInfoLog(GLuint, GLsizei size, GLsizei*, GLchar* out) { copyLog(fake->shaderLog, size, out); }
void APIENTRY deleteShader(GLuint shader) {
    for (const auto& [program, attached] : fake->attached) fake->deletedAttachedShader |= attached == shader;
    fake->shaders.erase(shader);
}
GLuint APIENTRY createProgram() {
    fake->programs.insert(fake->next);
    return fake->next++;
}
void APIENTRY attachShader(GLuint program, GLuint shader) { fake->attached.insert({program, shader}); }
void APIENTRY linkProgram(GLuint) {}
void APIENTRY detachShader(GLuint program, GLuint shader) { fake->attached.erase({program, shader}); }
void APIENTRY getProgramiv(GLuint, GLenum name, GLint* out) {
    if (name == GL_LINK_STATUS) *out = fake->links;
    if (name == GL_INFO_LOG_LENGTH) *out = GLint(fake->programLog.size() + 1);
}
void APIENTRY getProgramInfoLog(GLuint, GLsizei size, GLsizei*, GLchar* out) { copyLog(fake->programLog, size, out); }
void APIENTRY deleteProgram(GLuint program) { fake->programs.erase(program); }

class GlPlumbing : public ::testing::Test {
protected:
    void SetUp() override { fake = &gl_; }
    void TearDown() override { fake = nullptr; }
    // Nothing of a build is left but its program (on success).
    void expectOnly(std::set<GLuint> programs) const {
        EXPECT_TRUE(gl_.shaders.empty());
        EXPECT_TRUE(gl_.attached.empty());
        EXPECT_FALSE(gl_.deletedAttachedShader);
        EXPECT_EQ(gl_.programs, programs);
    }
    // A build fails with exactly `error` and leaves nothing behind.
    void expectFailure(const std::string& error) {
        const BuiltProgram built = buildProgram(table_, "GL program 'p'", "vertex source", "fragment source");
        EXPECT_EQ(built.id, 0u);
        EXPECT_EQ(built.error, error);
        expectOnly({});
    }

    FakeGl gl_;
    ProgramFunctions table_{.AttachShader = attachShader,
                            .CompileShader = compileShader,
                            .CreateProgram = createProgram,
                            .CreateShader = createShader,
                            .DeleteProgram = deleteProgram,
                            .DeleteShader = deleteShader,
                            .DetachShader = detachShader,
                            .GetProgramInfoLog = getProgramInfoLog,
                            .GetProgramiv = getProgramiv,
                            .GetShaderInfoLog = getShaderInfoLog,
                            .GetShaderiv = getShaderiv,
                            .LinkProgram = linkProgram,
                            .ShaderSource = shaderSource};
};

TEST_F(GlPlumbing, BuildsAndKeepsOnlyTheProgram) {
    // Sources go with their lengths: a view need not end in a NUL.
    const std::string_view vertex = std::string_view("void main() {}XYZ").substr(0, 14);
    const BuiltProgram built = buildProgram(table_, "GL program 'p'", vertex, "fragment source");
    ASSERT_NE(built.id, 0u);
    EXPECT_EQ(built.error, "");
    EXPECT_EQ(gl_.sources.at(1), "void main() {}");
    EXPECT_EQ(gl_.sources.at(2), "fragment source");
    expectOnly({built.id});
}

TEST_F(GlPlumbing, AStageThatDoesNotCompileIsNamedWithItsLog) {
    gl_.shaderLog = "0:1(1): error: syntax error\n\n";
    gl_.vertexCompiles = GL_FALSE;
    expectFailure("GL program 'p': vertex shader does not compile:\n0:1(1): error: syntax error");
    gl_.vertexCompiles = GL_TRUE;
    gl_.fragmentCompiles = GL_FALSE;
    expectFailure("GL program 'p': fragment shader does not compile:\n0:1(1): error: syntax error");
}

TEST_F(GlPlumbing, AProgramThatDoesNotLinkIsNamedWithItsLog) {
    gl_.programLog = "error: v_never_written not written\n";
    gl_.links = GL_FALSE;
    expectFailure("GL program 'p' does not link:\nerror: v_never_written not written");
}

TEST_F(GlPlumbing, NoShaderObjectIsAnError) {
    gl_.createShaderFails = true;
    expectFailure("GL program 'p': glCreateShader failed (no current context?)");
}

TEST(GlPlumbingNames, FramebufferStatusNames) {
    EXPECT_STREQ(framebufferStatusName(GL_FRAMEBUFFER_COMPLETE), "GL_FRAMEBUFFER_COMPLETE");
    EXPECT_STREQ(framebufferStatusName(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT),
                 "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT");
    EXPECT_STREQ(framebufferStatusName(GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS),
                 "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS");
    EXPECT_STREQ(framebufferStatusName(0), "unknown framebuffer status");
}

}  // namespace
}  // namespace engine::render::gl::plumbing
