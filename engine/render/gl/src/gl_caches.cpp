// SPDX-License-Identifier: MIT
#include "gl_caches.hpp"

#include <algorithm>

#include "engine/render/gl/gl_program.hpp"
#include "gl_enums.hpp"

namespace engine::render::gl {

GLuint GlSamplerCache::get(const SamplerState& s) {
    const std::size_t index = std::size_t(s.filter) * 9 + std::size_t(s.addressU) * 3 + std::size_t(s.addressV);
    GLuint& id = samplers_[index];
    if (!id) {
        glGenSamplers(1, &id);  // GL 3.3 and ES 3.0 alike (the GLES driver shares this cache)
        // Bilinear reads level 0 only: a non-mipmapped minification filter never leaves the base level.
        const GLenum minFilter = s.filter == Filter::Nearest    ? GL_NEAREST
                                 : s.filter == Filter::Bilinear ? GL_LINEAR
                                                                : GL_LINEAR_MIPMAP_LINEAR;
        glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
        glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, s.filter == Filter::Nearest ? GL_NEAREST : GL_LINEAR);
        glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GLint(glWrap(s.addressU)));
        glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GLint(glWrap(s.addressV)));
    }
    return id;
}

void GlSamplerCache::release() {
    for (GLuint& id : samplers_) {
        if (id) glDeleteSamplers(1, &id);
        id = 0;
    }
}

GLuint GlFramebufferCache::get(const std::vector<GLuint>& colors, GLuint depth, const std::string& what) {
    std::vector<GLuint> key = colors;
    key.push_back(0);
    key.push_back(depth);
    auto it = framebuffers_.find(key);
    if (it != framebuffers_.end()) return it->second;
    const GLuint fbo = make_(colors, depth, what);
    framebuffers_.emplace(std::move(key), fbo);
    return fbo;
}

// GL 4.5's maker (direct state access): the web page's build has only the GLES driver's.
#if !defined(__EMSCRIPTEN__)
GLuint makeDirectStateFramebuffer(const std::vector<GLuint>& colors, GLuint depth, const std::string& what) {
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    std::vector<GLenum> drawBuffers;
    for (std::size_t i = 0; i < colors.size(); ++i) {
        glNamedFramebufferTexture(fbo, GLenum(GL_COLOR_ATTACHMENT0 + i), colors[i], 0);
        drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
    }
    if (depth) glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth, 0);
    if (drawBuffers.empty()) glNamedFramebufferDrawBuffer(fbo, GL_NONE);
    else glNamedFramebufferDrawBuffers(fbo, GLsizei(drawBuffers.size()), drawBuffers.data());
    glNamedFramebufferReadBuffer(fbo, GL_NONE);
    try {
        checkFramebuffer(fbo, what);
    } catch (...) {
        glDeleteFramebuffers(1, &fbo);
        throw;
    }
    return fbo;
}
#endif

void GlFramebufferCache::forget(GLuint texture) {
    for (auto it = framebuffers_.begin(); it != framebuffers_.end();) {
        if (std::find(it->first.begin(), it->first.end(), texture) != it->first.end()) {
            glDeleteFramebuffers(1, &it->second);
            it = framebuffers_.erase(it);
        } else {
            ++it;
        }
    }
}

void GlFramebufferCache::release() {
    for (const auto& [key, fbo] : framebuffers_) glDeleteFramebuffers(1, &fbo);
    framebuffers_.clear();
}

}  // namespace engine::render::gl
