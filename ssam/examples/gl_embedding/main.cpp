// SPDX-License-Identifier: MIT
// An OpenGL program that is not built on our engine (its own context, shaders, buffers and
// render targets) embedding SSAM through ssam::gl: the opaque scene is drawn into the program's
// own colour + depth textures, then ssam::gl::ScreenSpaceAlphaMaskGl runs the mask, colour and
// composite passes ([Hathaway 2010] §3.5), calling back into the program to draw its foliage cards.
//
//   ssam_gl_embedding               a GLFW window when a display is available
//   ssam_gl_embedding --headless --out frame.png
//                                   EGL surfaceless (EGL_PLATFORM_SURFACELESS_MESA), one frame
// Exit codes (arguments.hpp): 0 ok, 1 error, 2 usage error, 77 no OpenGL 3.3 core context could
// be created (tests skip).
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <ssam/gl/ssam_gl.hpp>

#include "arguments.hpp"
#include "png_writer.hpp"
#include "scene.hpp"

using namespace gl_embedding;

namespace {

constexpr int kNoContext = 77;

struct NoContext : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---- Contexts ---------------------------------------------------------------------------

struct EglSurfaceless {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    EglSurfaceless() {
        // libepoxy aborts when libEGL cannot be loaded: check first.
        if (!dlopen("libEGL.so.1", RTLD_LAZY | RTLD_LOCAL)) throw NoContext("libEGL.so.1 cannot be loaded");
        const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (!client || !std::strstr(client, "EGL_MESA_platform_surfaceless"))
            throw NoContext("EGL has no EGL_MESA_platform_surfaceless");
        display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr))
            throw NoContext("the surfaceless EGL display does not initialise");
        if (!eglBindAPI(EGL_OPENGL_API)) throw NoContext("eglBindAPI(EGL_OPENGL_API) failed");
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
        if (context == EGL_NO_CONTEXT) throw NoContext("no OpenGL 3.3 core context without a config");
        if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
            throw NoContext("eglMakeCurrent without a surface failed");
    }
    ~EglSurfaceless() {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
    }
};

struct GlfwWindow {
    GLFWwindow* window = nullptr;
    GlfwWindow() {
        if (!glfwInit()) throw NoContext("GLFW cannot initialise (no display?)");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        window = glfwCreateWindow(kWidth, kHeight, "ssam::gl embedding", nullptr, nullptr);
        if (!window) {
            glfwTerminate();
            throw NoContext("GLFW cannot create an OpenGL 3.3 core window");
        }
        glfwMakeContextCurrent(window);
        glfwSwapInterval(1);
    }
    ~GlfwWindow() {
        glfwDestroyWindow(window);
        glfwTerminate();
    }
};

// ---- The host program's own GL ------------------------------------------------------------

GLuint compile(GLenum stage, const char* source) {
    const GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("opaque shader: ") + log);
    }
    return s;
}

constexpr const char* kOpaqueVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_viewProj;
void main() { gl_Position = u_viewProj * vec4(a_position, 1.0); }
)";
constexpr const char* kOpaqueFragment = R"(#version 330 core
uniform vec4 u_color;
out vec4 o_color;
void main() { o_color = u_color; }
)";

// World (x, y, z in [0, 1]) to OpenGL's default clip space (z in [-w, w]).
glm::mat4 viewProjection() {
    glm::mat4 m(1.0f);
    m[2][2] = 2.0f;
    m[3][2] = -1.0f;
    return m;
}

struct Vertex {
    float x, y, z, u, v;
};

void appendQuad(std::vector<Vertex>& out, const Rect3& r) {
    const Vertex a{r.x0, r.y0, r.zLeft, 0, 0}, b{r.x1, r.y0, r.zRight, 1, 0}, c{r.x1, r.y1, r.zRight, 1, 1},
        d{r.x0, r.y1, r.zLeft, 0, 1};
    out.insert(out.end(), {a, b, c, a, c, d});
}

struct HostScene {
    GLuint opaqueProgram = 0, opaqueVao = 0, foliageVao = 0, buffers[2] = {0, 0}, leafTexture = 0;
    GLuint colorTexture = 0, depthTexture = 0, framebuffer = 0;
    GLint viewProjUniform = -1, colorUniform = -1;
    std::vector<engine::render::BoundingBox> foliageBounds;

    HostScene() {
        opaqueProgram = glCreateProgram();
        const GLuint vs = compile(GL_VERTEX_SHADER, kOpaqueVertex), fs = compile(GL_FRAGMENT_SHADER, kOpaqueFragment);
        glAttachShader(opaqueProgram, vs);
        glAttachShader(opaqueProgram, fs);
        glLinkProgram(opaqueProgram);
        glDeleteShader(vs);
        glDeleteShader(fs);
        viewProjUniform = glGetUniformLocation(opaqueProgram, "u_viewProj");
        colorUniform = glGetUniformLocation(opaqueProgram, "u_color");

        std::vector<Vertex> opaque, foliage;
        for (const Rect3& r : {kGround, kBox, kBoxTop}) appendQuad(opaque, r);
        for (const Rect3& r : kCards) {
            appendQuad(foliage, r);
            foliageBounds.push_back({{r.x0, r.y0, std::min(r.zLeft, r.zRight)}, {r.x1, r.y1, std::max(r.zLeft, r.zRight)}});
        }
        glGenBuffers(2, buffers);
        glGenVertexArrays(1, &opaqueVao);
        glBindVertexArray(opaqueVao);
        glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(opaque.size() * sizeof(Vertex)), opaque.data(), GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
        // The foliage VAO follows ssam::gl::AttributeLocations: position and uv; normal, colour
        // and the instance matrix are left to SSAM's defaults.
        glGenVertexArrays(1, &foliageVao);
        glBindVertexArray(foliageVao);
        glBindBuffer(GL_ARRAY_BUFFER, buffers[1]);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(foliage.size() * sizeof(Vertex)), foliage.data(), GL_STATIC_DRAW);
        using Loc = ssam::gl::AttributeLocations;
        glEnableVertexAttribArray(Loc::position);
        glVertexAttribPointer(Loc::position, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
        glEnableVertexAttribArray(Loc::uv);
        glVertexAttribPointer(Loc::uv, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<const void*>(3 * sizeof(float)));
        glBindVertexArray(0);

        std::vector<std::uint8_t> leaf;
        for (int y = 0; y < kLeafSize; ++y)
            for (int x = 0; x < kLeafSize; ++x)
                for (std::uint8_t c : leafTexel(x, y)) leaf.push_back(c);
        glGenTextures(1, &leafTexture);
        glBindTexture(GL_TEXTURE_2D, leafTexture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kLeafSize, kLeafSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, leaf.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

        // The host's render targets: what SSAM gets as "the engine's colour and depth".
        glGenTextures(1, &colorTexture);
        glBindTexture(GL_TEXTURE_2D, colorTexture);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kWidth, kHeight);
        glGenTextures(1, &depthTexture);
        glBindTexture(GL_TEXTURE_2D, depthTexture);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, kWidth, kHeight);
        glGenFramebuffers(1, &framebuffer);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colorTexture, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depthTexture, 0);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("the host framebuffer is incomplete");
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    ~HostScene() {
        glDeleteFramebuffers(1, &framebuffer);
        const GLuint textures[] = {colorTexture, depthTexture, leafTexture};
        glDeleteTextures(3, textures);
        glDeleteBuffers(2, buffers);
        glDeleteVertexArrays(1, &opaqueVao);
        glDeleteVertexArrays(1, &foliageVao);
        glDeleteProgram(opaqueProgram);
    }

    void drawOpaque() {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glViewport(0, 0, kWidth, kHeight);
        glClearColor(kSky[0], kSky[1], kSky[2], 1.0f);
        glClearDepth(1.0);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glUseProgram(opaqueProgram);
        glUniformMatrix4fv(viewProjUniform, 1, GL_FALSE, glm::value_ptr(viewProjection()));
        glBindVertexArray(opaqueVao);
        const Rect3 quads[] = {kGround, kBox, kBoxTop};
        for (int i = 0; i < 3; ++i) {
            glUniform4fv(colorUniform, 1, quads[i].color.data());
            glDrawArrays(GL_TRIANGLES, i * 6, 6);
        }
    }

    // SSAM's callback: runs once for the mask pass and once for the colour pass, with SSAM's
    // program, framebuffer and state set; draws the same cards in the same order both times.
    void drawFoliage(const ssam::gl::FoliageProgram& program) const {
        glBindVertexArray(foliageVao);
        program.bindBaseColorTexture(leafTexture);
        for (std::size_t i = 0; i < kCards.size(); ++i) {
            const auto& c = kCards[i].color;
            program.setBaseColorFactor({c[0], c[1], c[2], c[3]});
            glDrawArrays(GL_TRIANGLES, GLint(i * 6), 6);
        }
    }
};

void renderFrame(HostScene& scene, ssam::gl::ScreenSpaceAlphaMaskGl& ssam) {
    scene.drawOpaque();
    ssam::gl::FrameDesc frame;
    frame.colorTexture = scene.colorTexture;
    frame.depthTexture = scene.depthTexture;
    frame.width = kWidth;
    frame.height = kHeight;
    frame.viewProj = viewProjection();
    frame.foliageBounds = std::span<const engine::render::BoundingBox>(scene.foliageBounds);
    ssam.render(frame, [&](const ssam::gl::FoliageProgram& p) { scene.drawFoliage(p); });
}

int runHeadless(const std::string& out) {
    EglSurfaceless context;
    std::printf("OpenGL: %s, %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));
    HostScene scene;
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;  // ssam::Config{}: the paper's defaults
    renderFrame(scene, ssam);
    std::vector<std::uint8_t> pixels(std::size_t(kWidth) * kHeight * 4), flipped(pixels.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, scene.framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    const std::size_t row = std::size_t(kWidth) * 4;
    for (int y = 0; y < kHeight; ++y)  // GL's row 0 is the bottom; PNG's the top
        std::copy_n(pixels.begin() + std::ptrdiff_t((kHeight - 1 - y) * row), row, flipped.begin() + std::ptrdiff_t(y * row));
    if (const std::string why = writePng(out, kWidth, kHeight, flipped); !why.empty()) {
        printError(why);
        return kExitFailure;
    }
    std::printf("wrote %s (%dx%d)\n", out.c_str(), kWidth, kHeight);
    return 0;
}

int runWindow(int frames) {
    GlfwWindow window;
    HostScene scene;
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    for (int frame = 0; !glfwWindowShouldClose(window.window) && (frames <= 0 || frame < frames); ++frame) {
        renderFrame(scene, ssam);
        int w = 0, h = 0;
        glfwGetFramebufferSize(window.window, &w, &h);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, scene.framebuffer);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, kWidth, kHeight, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        glfwSwapBuffers(window.window);
        glfwPollEvents();
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Arguments args;
    try {
        args = parseArguments(argc, argv);
    } catch (const UsageError& e) {
        printError(std::string(e.what()) + " (see --help)");
        return kExitUsage;
    }
    if (args.help) {
        std::fputs(usage().c_str(), stdout);
        return 0;
    }
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) args.headless = true;
    // The output is proven writable before a context is made or a frame drawn.
    if (args.headless) {
        if (const std::string why = checkWritable(args.out); !why.empty()) {
            printError(why);
            return kExitFailure;
        }
    }
    try {
        return args.headless ? runHeadless(args.out) : runWindow(args.frames);
    } catch (const NoContext& e) {
        std::printf("SKIPPED: no OpenGL 3.3 core context: %s\n", e.what());
        return kNoContext;
    } catch (const std::exception& e) {
        printError(e.what());
        return kExitFailure;
    }
}
