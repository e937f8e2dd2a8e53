// SPDX-License-Identifier: MIT
#pragma once
// GL objects the backend makes once and reuses: sampler objects per SamplerState and
// framebuffer objects per attachment set. Both are released explicitly (release()), while
// the backend's context is current, never by a destructor that may run without one.
#include <array>
#include <map>
#include <string>
#include <vector>

#include "gl_api.hpp"

#include "engine/render/texture.hpp"

namespace engine::render::gl {

class GlSamplerCache {
public:
    GLuint get(const SamplerState& state);
    void release();

private:
    std::array<GLuint, 27> samplers_{};  // 3 filters x 3 U modes x 3 V modes
};

// Makes a complete framebuffer of these attachments (throws engine::Error naming `what` when
// GL finds it incomplete). GL 4.5's by direct state access; the GLES driver's binds to attach.
using MakeFramebuffer = GLuint (*)(const std::vector<GLuint>& colors, GLuint depth, const std::string& what);
GLuint makeDirectStateFramebuffer(const std::vector<GLuint>& colors, GLuint depth, const std::string& what);

class GlFramebufferCache {
public:
    explicit GlFramebufferCache(MakeFramebuffer make = makeDirectStateFramebuffer) : make_(make) {}
    // The framebuffer with these colour attachments (in order) and depth attachment (0: none);
    // throws engine::Error naming `what` when GL finds it incomplete.
    GLuint get(const std::vector<GLuint>& colors, GLuint depth, const std::string& what);
    // Deletes every framebuffer that has `texture` attached (it is being deleted).
    void forget(GLuint texture);
    void release();

private:
    MakeFramebuffer make_;
    std::map<std::vector<GLuint>, GLuint> framebuffers_;  // colours, 0, depth -> framebuffer
};

}  // namespace engine::render::gl
