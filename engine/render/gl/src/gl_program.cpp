// SPDX-License-Identifier: MIT
#include "engine/render/gl/gl_program.hpp"

#include <cstdio>
#include <utility>

#include "gl_api.hpp"

#include "engine/core/error.hpp"
#include "engine/render/gl/plumbing/build_program.hpp"
#include "engine/render/gl/plumbing/framebuffer_status_name.hpp"

namespace engine::render::gl {

GlProgram::GlProgram(GlProgram&& other) noexcept : name_(std::move(other.name_)), id_(std::exchange(other.id_, 0u)) {}

GlProgram& GlProgram::operator=(GlProgram&& other) noexcept {
    if (this != &other) {
        if (id_) glDeleteProgram(id_);
        name_ = std::move(other.name_);
        id_ = std::exchange(other.id_, 0u);
    }
    return *this;
}

GlProgram::~GlProgram() {
    if (id_) glDeleteProgram(id_);
}

int GlProgram::uniform(const char* name) const { return glGetUniformLocation(id_, name); }

namespace {

// libepoxy's entry points (resolved on first call) as the table the shared builder takes.
plumbing::ProgramFunctions epoxyProgramFunctions() {
#define ENGINE_GL_FROM_EPOXY(type, name) gl##name,
    return {ENGINE_GL_PROGRAM_FUNCTIONS(ENGINE_GL_FROM_EPOXY)};
#undef ENGINE_GL_FROM_EPOXY
}

}  // namespace

GlProgram compileProgram(std::string name, std::string_view vertexSource, std::string_view fragmentSource) {
    auto built =
        plumbing::buildProgram(epoxyProgramFunctions(), "GL program '" + name + "'", vertexSource, fragmentSource);
    if (!built.id) throw Error(built.error);
    return GlProgram(std::move(name), built.id);
}

const char* framebufferStatusName(unsigned int status) { return plumbing::framebufferStatusName(status); }

// GL 4.5's check (direct state access); the GLES driver checks its framebuffers while bound
// (makeBoundFramebuffer), and the web page's build has no GL 4.5 driver.
#if !defined(__EMSCRIPTEN__)
void checkFramebuffer(unsigned int framebuffer, const std::string& what) {
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return;
    if (status == 0)
        throw Error(what + ": framebuffer status query failed (GL error 0x" + [] {
            char buf[16];
            std::snprintf(buf, sizeof buf, "%x", glGetError());
            return std::string(buf);
        }() + ")");
    throw Error(what + ": framebuffer incomplete (" + framebufferStatusName(status) + ")");
}
#endif

}  // namespace engine::render::gl
