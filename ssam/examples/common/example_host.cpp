// SPDX-License-Identifier: MIT
#include "example_host.hpp"

#include <epoxy/egl.h>
#include <GLFW/glfw3.h>
#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "png_writer.hpp"
#include "scene.hpp"

namespace gl_example {

namespace {

constexpr int kNoContext = 77;

struct NoContext : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---- Contexts ---------------------------------------------------------------------------

// A context without a window or a config (EGL_KHR_no_config_context, surfaceless make-current) on
// `display`, or "" and a reason: OpenGL 3.3 core, or OpenGL ES 3.0 (EGL_OPENGL_ES_API; EGL 1.5
// §3.7.1 gives the newest ES version compatible with 3.0, e.g. 3.2 on Mesa).
EGLContext createContext(EGLDisplay display, ContextApi api, std::string& why) {
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
        why = "the EGL display does not initialise";
        return EGL_NO_CONTEXT;
    }
    const bool es = api == ContextApi::Gles;
    if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
        why = es ? "eglBindAPI(EGL_OPENGL_ES_API) failed" : "eglBindAPI(EGL_OPENGL_API) failed";
        return EGL_NO_CONTEXT;
    }
    const EGLint desktop[] = {
        EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    const EGLint gles[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    const EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, es ? gles : desktop);
    if (context == EGL_NO_CONTEXT)
        why = es ? "no OpenGL ES 3.0 context without a config" : "no OpenGL 3.3 core context without a config";
    else if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        why = "eglMakeCurrent without a surface failed";
        eglDestroyContext(display, context);
        return EGL_NO_CONTEXT;
    }
    return context;
}

// A headless context on EGL_EXT_platform_device (each device in turn, e.g. an NVIDIA or AMD GPU,
// or Mesa's software device) or on Mesa's surfaceless platform. `description` names the one taken.
struct EglHeadless {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    std::string description;
    EglHeadless(EglPlatform platform, ContextApi api) : api_(api) {
        // libepoxy aborts when libEGL cannot be loaded: check first.
        if (!dlopen("libEGL.so.1", RTLD_LAZY | RTLD_LOCAL)) throw NoContext("libEGL.so.1 cannot be loaded");
        const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        const std::string client = extensions ? extensions : "";
        std::string why;
        if (platform != EglPlatform::Surfaceless && !onDevice(client, why) && platform == EglPlatform::Device)
            throw NoContext("EGL device platform: " + why);
        if (context == EGL_NO_CONTEXT && !onSurfaceless(client, why))
            throw NoContext(platform == EglPlatform::Auto ? "neither EGL platform gives one: " + why
                                                          : "EGL surfaceless platform: " + why);
    }
    ~EglHeadless() {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
    }
    EglHeadless(const EglHeadless&) = delete;
    EglHeadless& operator=(const EglHeadless&) = delete;

private:
    ContextApi api_;
    bool onDevice(const std::string& client, std::string& why) {
        if (client.find("EGL_EXT_platform_device") == std::string::npos ||
            client.find("EGL_EXT_device_enumeration") == std::string::npos) {
            why = "EGL has no EGL_EXT_platform_device / EGL_EXT_device_enumeration";
            return false;
        }
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (!eglQueryDevicesEXT(16, devices, &count) || count == 0) {
            why = "eglQueryDevicesEXT lists no device";
            return false;
        }
        for (EGLint i = 0; i < count && context == EGL_NO_CONTEXT; ++i) {
            display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
            context = createContext(display, api_, why);
            if (context == EGL_NO_CONTEXT) continue;
            const char* names = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
            description = "EGL device " + std::to_string(i) + " of " + std::to_string(count) + " (" +
                          (names ? names : "no device extensions") + ")";
        }
        return context != EGL_NO_CONTEXT;
    }
    bool onSurfaceless(const std::string& client, std::string& why) {
        if (client.find("EGL_MESA_platform_surfaceless") == std::string::npos) {
            why += (why.empty() ? "" : "; ") + std::string("EGL has no EGL_MESA_platform_surfaceless");
            return false;
        }
        display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        context = createContext(display, api_, why);
        description = "EGL surfaceless platform";
        return context != EGL_NO_CONTEXT;
    }
};

struct GlfwWindow {
    GLFWwindow* window = nullptr;
    GlfwWindow(const char* title, ContextApi api) {
        if (!glfwInit()) throw NoContext("GLFW cannot initialise (no display?)");
        const bool es = api == ContextApi::Gles;
        glfwWindowHint(GLFW_CLIENT_API, es ? GLFW_OPENGL_ES_API : GLFW_OPENGL_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, es ? 0 : 3);
        if (!es) {
            glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
            glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        }
        window = glfwCreateWindow(kWidth, kHeight, title, nullptr, nullptr);
        if (!window) {
            glfwTerminate();
            throw NoContext(es ? "GLFW cannot create an OpenGL ES 3.0 window"
                               : "GLFW cannot create an OpenGL 3.3 core window");
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

// The host's GLSL 3.30 sources on an OpenGL ES context: the same text after an ES 3.00 first
// line with highp defaults (ES 3.00 §4.5.4: fragment floats have none), as ssam::gl's own; they
// use nothing GLSL ES 3.00 lacks.
std::string forThisContext(const char* source) {
    constexpr std::string_view kDesktop = "#version 330 core\n";
    const std::string text = source;
    if (epoxy_is_desktop_gl() || text.compare(0, kDesktop.size(), kDesktop) != 0) return text;
    return "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n" +
           text.substr(kDesktop.size());
}

GLuint compileStage(GLenum stage, const char* glsl330, const std::string& what) {
    const GLuint s = glCreateShader(stage);
    const std::string text = forThisContext(glsl330);
    const char* source = text.c_str();
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        glDeleteShader(s);
        throw std::runtime_error(what + ": " + log);
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

// World (x, y, z in [0, 1]) to OpenGL's default clip space (z in [-w, w]), column-major.
constexpr float kViewProj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2, 0, 0, 0, -1, 1};

constexpr GLsizei kCardVertices = kCardRows * 6;

}  // namespace

GLuint linkProgram(const char* vertexSource, const char* fragmentSource, const std::string& what) {
    const GLuint program = glCreateProgram();
    try {
        const std::pair<GLenum, const char*> stages[] = {{GL_VERTEX_SHADER, vertexSource},
                                                         {GL_FRAGMENT_SHADER, fragmentSource}};
        for (const auto& [stage, source] : stages) {
            const GLuint shader = compileStage(stage, source, what);
            glAttachShader(program, shader);
            glDeleteShader(shader);  // goes with the program
        }
    } catch (...) {
        glDeleteProgram(program);
        throw;
    }
    glLinkProgram(program);
    return program;
}

HostScene::HostScene(float wind) {
    opaqueProgram_ = linkProgram(kOpaqueVertex, kOpaqueFragment, "opaque shader");
    viewProjUniform_ = glGetUniformLocation(opaqueProgram_, "u_viewProj");
    colorUniform_ = glGetUniformLocation(opaqueProgram_, "u_color");

    std::vector<Vertex> opaque, cards;
    for (const Rect3& r : {kGround, kBox, kBoxTop, kMist}) appendStrip(opaque, r, 1);
    for (const Rect3& r : kCards) {
        appendStrip(cards, r, kCardRows);
        // Bounds hold every pixel the card can reach, bent or not (or the composite's scissor
        // would cut the bend off): the wind moves its top |wind| at most, in x.
        cardBounds_.push_back({{r.x0 + std::min(wind, 0.0f), r.y0, std::min(r.zLeft, r.zRight)},
                               {r.x1 + std::max(wind, 0.0f), r.y1, std::max(r.zLeft, r.zRight)}});
    }
    glGenBuffers(2, buffers_);
    glGenVertexArrays(1, &opaqueVao_);
    glBindVertexArray(opaqueVao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(opaque.size() * sizeof(Vertex)), opaque.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
    // The cards' VAO at SSAM's default ssam::gl::AttributeLocations: position and uv; normal,
    // colour, the instance matrix and tint are left to SSAM's generic values. (A host whose VAOs use
    // other locations passes them to initialize() as AttributeLocations instead.)
    glGenVertexArrays(1, &cardsVao_);
    glBindVertexArray(cardsVao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[1]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(cards.size() * sizeof(Vertex)), cards.data(), GL_STATIC_DRAW);
    const ssam::gl::AttributeLocations at;
    glEnableVertexAttribArray(at.position);
    glVertexAttribPointer(at.position, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
    glEnableVertexAttribArray(at.uv);
    glVertexAttribPointer(at.uv, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(3 * sizeof(float)));
    glBindVertexArray(0);

    std::vector<std::uint8_t> leaf;
    for (int y = 0; y < kLeafSize; ++y)
        for (int x = 0; x < kLeafSize; ++x)
            for (std::uint8_t c : leafTexel(x, y)) leaf.push_back(c);
    glGenTextures(1, &leafTexture_);
    glBindTexture(GL_TEXTURE_2D, leafTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kLeafSize, kLeafSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, leaf.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    // The host's render targets: what SSAM gets as "the host's colour and depth".
    glGenTextures(1, &colorTexture_);
    glBindTexture(GL_TEXTURE_2D, colorTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kWidth, kHeight, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenTextures(1, &depthTexture_);
    glBindTexture(GL_TEXTURE_2D, depthTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, kWidth, kHeight, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    for (GLuint t : {colorTexture_, depthTexture_}) {
        glBindTexture(GL_TEXTURE_2D, t);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    }
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colorTexture_, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depthTexture_, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the host framebuffer is incomplete");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

HostScene::~HostScene() {
    glDeleteFramebuffers(1, &framebuffer_);
    const GLuint textures[] = {colorTexture_, depthTexture_, leafTexture_};
    glDeleteTextures(3, textures);
    glDeleteBuffers(2, buffers_);
    glDeleteVertexArrays(1, &opaqueVao_);
    glDeleteVertexArrays(1, &cardsVao_);
    glDeleteProgram(opaqueProgram_);
}

void HostScene::drawOpaque() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(kSky[0], kSky[1], kSky[2], 1.0f);
    if (epoxy_is_desktop_gl()) glClearDepth(1.0);
    else glClearDepthf(1.0f);  // ES has only the float form
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(opaqueProgram_);
    glUniformMatrix4fv(viewProjUniform_, 1, GL_FALSE, kViewProj);
    glBindVertexArray(opaqueVao_);
    const Rect3 quads[] = {kGround, kBox, kBoxTop};
    for (int i = 0; i < 3; ++i) {
        glUniform4fv(colorUniform_, 1, quads[i].color.data());
        glDrawArrays(GL_TRIANGLES, i * 6, 6);
    }
}

void HostScene::drawMist() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, kWidth, kHeight);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);  // a transparent pass tests depth, writes none
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // the frame stays opaque
    glUseProgram(opaqueProgram_);
    glUniformMatrix4fv(viewProjUniform_, 1, GL_FALSE, kViewProj);
    glUniform4fv(colorUniform_, 1, kMist.color.data());
    glBindVertexArray(opaqueVao_);
    glDrawArrays(GL_TRIANGLES, 3 * 6, 6);  // after the ground, the box and its top
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

void HostScene::drawCards(const std::function<void(const float tint[4])>& setTint) const {
    glBindVertexArray(cardsVao_);
    for (std::size_t i = 0; i < kCards.size(); ++i) {
        setTint(kCards[i].color.data());
        glDrawArrays(GL_TRIANGLES, GLint(i) * kCardVertices, kCardVertices);
    }
}

ssam::gl::FrameDesc HostScene::frame() const {
    ssam::gl::FrameDesc frame;
    frame.colorTexture = colorTexture_;
    frame.depthTexture = depthTexture_;
    frame.width = kWidth;
    frame.height = kHeight;
    std::copy(std::begin(kViewProj), std::end(kViewProj), frame.viewProj);
    frame.foliageBounds = cardBounds_.data();
    frame.foliageBoundsCount = cardBounds_.size();
    return frame;
}

void check(const ssam::gl::ScreenSpaceAlphaMaskGl& ssam, ssam::gl::Status status, const char* call) {
    if (status != ssam::gl::Status::Ok)
        throw std::runtime_error(std::string(call) + ": " + ssam::gl::statusName(status) + ": " + ssam.lastMessage());
}

namespace {

// A texture's RGBA8 pixels, top row first (GL's row 0 is the bottom; PNG's the top).
std::vector<std::uint8_t> readTexture(GLuint texture) {
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    std::vector<std::uint8_t> pixels(std::size_t(kWidth) * kHeight * 4), flipped(pixels.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    const std::size_t row = std::size_t(kWidth) * 4;
    for (int y = 0; y < kHeight; ++y)
        std::copy_n(pixels.begin() + std::ptrdiff_t((kHeight - 1 - y) * row), row,
                    flipped.begin() + std::ptrdiff_t(y * row));
    return flipped;
}

void writeOrThrow(const std::string& path, GLuint texture) {
    if (const std::string why = writePng(path, kWidth, kHeight, readTexture(texture)); !why.empty())
        throw std::runtime_error(why);
    std::printf("wrote %s (%dx%d)\n", path.c_str(), kWidth, kHeight);
}

// SSAM's initialisation line on stdout, its warnings (a GL error the host left pending) on
// stderr; its errors come back as a Status and are reported once, by check().
void printSsamMessage(void* tool, ssam::gl::Severity severity, const char* message) {
    if (severity == ssam::gl::Severity::Info) std::printf("%s\n", message);
    else if (severity == ssam::gl::Severity::Warning)
        std::fprintf(stderr, "%s: ssam warning: %s\n", static_cast<const Tool*>(tool)->name, message);
}

ssam::gl::MaskPrecision maskPrecisionOf(Arguments::Precision p) {
    switch (p) {
        case Arguments::Precision::Rgba8: break;
        case Arguments::Precision::Rgba16f: return ssam::gl::MaskPrecision::Rgba16f;
        case Arguments::Precision::Rg16f: return ssam::gl::MaskPrecision::Rg16f;
    }
    return ssam::gl::MaskPrecision::Rgba8;
}

// SSAM resolves its GL functions through the host's loader (EGL's headless, GLFW's in a window):
// the paper's settings but for --depth-threshold and --precision.
template <class GetProcAddress>
void initializeSsam(ssam::gl::ScreenSpaceAlphaMaskGl& ssam, const Tool& tool, const Arguments& args,
                    GetProcAddress getProcAddress) {
    ssam.setMessageCallback(printSsamMessage, const_cast<Tool*>(&tool));
    ssam::gl::Settings settings;
    settings.depthMaskThreshold = args.depthMaskThreshold;
    settings.maskPrecision = maskPrecisionOf(args.precision);
    const ssam::gl::Api api = args.api == ContextApi::Gles ? ssam::gl::Api::Gles30 : ssam::gl::Api::Gl33;
    check(ssam, ssam.initialize(getProcAddress, settings, {}, api), "ssam::gl initialize");
}

int runHeadless(const Tool& tool, const Arguments& args, const MakeFoliageRenderer& makeRenderer) {
    EglHeadless context(args.egl, args.api);
    std::printf("OpenGL: %s, %s on the %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION),
                context.description.c_str());
    HostScene scene(args.wind);
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    initializeSsam(ssam, tool, args, eglGetProcAddress);
    const std::unique_ptr<FoliageRenderer> foliage = makeRenderer(scene, args);
    std::vector<double> milliseconds;
    for (int i = 0; i < args.repeat; ++i) {
        scene.drawOpaque();
        if (args.mist == Arguments::Mist::Before) scene.drawMist();
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        foliage->render(ssam, scene.frame());
        glFinish();
        milliseconds.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        // Later transparent passes after SSAM: they see the foliage depth.
        if (args.mist == Arguments::Mist::After) scene.drawMist();
    }
    if (args.repeat > 1) {
        std::sort(milliseconds.begin(), milliseconds.end());
        std::printf("ssam passes: median %.3f ms over %d frames (%dx%d)\n", milliseconds[milliseconds.size() / 2],
                    args.repeat, kWidth, kHeight);
    }
    writeOrThrow(args.out, scene.frame().colorTexture);
    if (!args.mask.empty()) writeOrThrow(args.mask, ssam.intermediates().mask);
    return 0;
}

int runWindow(const Tool& tool, const Arguments& args, const MakeFoliageRenderer& makeRenderer) {
    GlfwWindow window(tool.name, args.api);
    std::printf("OpenGL: %s, %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));
    HostScene scene(args.wind);
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    initializeSsam(ssam, tool, args, glfwGetProcAddress);
    const std::unique_ptr<FoliageRenderer> foliage = makeRenderer(scene, args);
    for (int frame = 0; !glfwWindowShouldClose(window.window) && (args.frames <= 0 || frame < args.frames); ++frame) {
        scene.drawOpaque();
        if (args.mist == Arguments::Mist::Before) scene.drawMist();
        foliage->render(ssam, scene.frame());
        if (args.mist == Arguments::Mist::After) scene.drawMist();
        int w = 0, h = 0;
        glfwGetFramebufferSize(window.window, &w, &h);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, scene.framebuffer());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, kWidth, kHeight, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        glfwSwapBuffers(window.window);
        glfwPollEvents();
    }
    return 0;
}

}  // namespace

int runExample(const Tool& tool, int argc, char** argv, const MakeFoliageRenderer& makeRenderer) {
    Arguments args;
    try {
        args = parseArguments(tool, argc, argv);
    } catch (const UsageError& e) {
        printError(tool, std::string(e.what()) + " (see --help)");
        return kExitUsage;
    }
    if (args.help) {
        std::fputs(usage(tool).c_str(), stdout);
        return 0;
    }
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) args.headless = true;
    // The outputs are proven writable before a context is made or a frame drawn.
    if (const std::string why = args.headless ? checkWritable({args.out, args.mask}) : ""; !why.empty()) {
        printError(tool, why);
        return kExitFailure;
    }
    try {
        return args.headless ? runHeadless(tool, args, makeRenderer) : runWindow(tool, args, makeRenderer);
    } catch (const NoContext& e) {
        std::printf("SKIPPED: no OpenGL %s context: %s\n", args.api == ContextApi::Gles ? "ES 3.0" : "3.3", e.what());
        return kNoContext;
    } catch (const std::exception& e) {
        printError(tool, e.what());
        return kExitFailure;
    }
}

}  // namespace gl_example
