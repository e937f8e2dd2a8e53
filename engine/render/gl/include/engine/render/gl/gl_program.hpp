// SPDX-License-Identifier: MIT
#pragma once
// GL program and framebuffer helpers the backend is built on, public so a module that brings
// a new program kind can compile its GLSL the same way (and tests can feed bad input).
// Need a current GL context.
#include <string>
#include <string_view>

namespace engine::render::gl {

// A linked program object, deleted with the object.
class GlProgram {
public:
    GlProgram() = default;
    GlProgram(std::string name, unsigned int id) : name_(std::move(name)), id_(id) {}
    GlProgram(GlProgram&& other) noexcept;
    GlProgram& operator=(GlProgram&& other) noexcept;
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;
    ~GlProgram();

    unsigned int id() const { return id_; }
    const std::string& name() const { return name_; }
    int uniform(const char* name) const;  // -1 when absent (optimised away)

private:
    std::string name_;
    unsigned int id_ = 0;
};

// Compiles and links; throws engine::Error naming the program and stage, with the info log.
GlProgram compileProgram(std::string name, std::string_view vertexSource, std::string_view fragmentSource);

// Throws engine::Error naming `what` and the status (GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT...)
// when the framebuffer object is not complete.
void checkFramebuffer(unsigned int framebuffer, const std::string& what);

// "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT" etc.
const char* framebufferStatusName(unsigned int status);

}  // namespace engine::render::gl
