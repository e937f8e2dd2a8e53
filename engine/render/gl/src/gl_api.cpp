// SPDX-License-Identifier: MIT
// The current context's API, version and extensions (gl_api.hpp): libepoxy's answers natively,
// WebGL2's through Emscripten's GLES calls in the web page's build.
#include "gl_api.hpp"

#include <cstring>

namespace engine::render::gl {

#if defined(__EMSCRIPTEN__)
bool glIsDesktop() { return false; }

int glVersion() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    return 10 * major + minor;
}

bool glHasExtension(const char* name) {
    // Emscripten lists each WebGL extension twice, as WebGL names it and with "GL_" ahead; both
    // are accepted so that the answer does not hang on that setting.
    const char* bare = std::strncmp(name, "GL_", 3) == 0 ? name + 3 : name;
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* offered = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        if (offered && (std::strcmp(offered, name) == 0 || std::strcmp(offered, bare) == 0)) return true;
    }
    return false;
}
#else
bool glIsDesktop() { return epoxy_is_desktop_gl(); }
int glVersion() { return epoxy_gl_version(); }
bool glHasExtension(const char* name) { return epoxy_has_gl_extension(name); }
#endif

}  // namespace engine::render::gl
