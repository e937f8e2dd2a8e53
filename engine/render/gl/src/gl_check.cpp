// SPDX-License-Identifier: MIT
#include "gl_check.hpp"

#include <cstdio>

#include "gl_api.hpp"

#include "engine/core/error.hpp"

namespace engine::render::gl {

std::string hex(unsigned value) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04x", value);
    return buf;
}

void drainGlErrors() {
    for (int i = 0; i < 64 && glGetError() != GL_NO_ERROR; ++i) {}
}

void checkGl(const std::string& what) {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR) return;
    drainGlErrors();
    const char* name = error == GL_OUT_OF_MEMORY       ? "GL_OUT_OF_MEMORY"
                       : error == GL_INVALID_ENUM      ? "GL_INVALID_ENUM"
                       : error == GL_INVALID_VALUE     ? "GL_INVALID_VALUE"
                       : error == GL_INVALID_OPERATION ? "GL_INVALID_OPERATION"
                                                       : "GL error";
    throw Error(what + ": " + name + " (" + hex(error) + ")");
}

}  // namespace engine::render::gl
