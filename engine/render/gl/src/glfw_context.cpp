// SPDX-License-Identifier: MIT
// A GLFW 3.3 window with a core 4.5 context, or the highest core >= 4.3 the display offers.
// Minimising (by the user, or setSize(0, 0)) makes framebufferSize() 0x0 so callers skip
// rendering; window managers differ on whether an iconified window keeps its framebuffer
// size, and Xvfb has no window manager at all, so the state is tracked here too.
// Windows are created and used on the thread that initialized GLFW (GLFW's rule).
#include <mutex>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/gl/gl_context.hpp"

namespace engine::render::gl {
namespace {

std::mutex gGlfwMutex;
bool gGlfwInitialized = false;
std::string gLastGlfwError;

void onGlfwError(int code, const char* description) {
    gLastGlfwError = "GLFW error " + std::to_string(code) + ": " + (description ? description : "?");
    log::debug(gLastGlfwError);
}

// GLFW is initialized once and never terminated: glfwTerminate unloads the GL driver, leaving
// what the driver keeps for good to leak checkers as leaks from an unknown module (the same
// choice as for EGL displays in egl_context.cpp).
void initGlfw() {
    std::lock_guard lock(gGlfwMutex);
    if (gGlfwInitialized) return;
    glfwSetErrorCallback(onGlfwError);
    gLastGlfwError.clear();
    if (!glfwInit())
        throw Error("GLFW window: glfwInit failed" +
                    (gLastGlfwError.empty() ? std::string() : " (" + gLastGlfwError + ")") +
                    "; is there a display (DISPLAY/WAYLAND_DISPLAY, or run under xvfb-run)?");
    gGlfwInitialized = true;
}

}  // namespace

struct GlfwWindowContext::Impl {
    GLFWwindow* window = nullptr;
    bool vsync = true;
    bool minimized = false;  // by setSize(0, 0) or the iconify callback
    int major = 0, minor = 0;
    std::string description;

    ~Impl() {
        if (window) glfwDestroyWindow(window);
    }
};

GlfwWindowContext::GlfwWindowContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlfwWindowContext::~GlfwWindowContext() = default;

std::unique_ptr<GlfwWindowContext> GlfwWindowContext::create(const GlfwWindowOptions& options) {
    if (options.width <= 0 || options.height <= 0)
        throw Error("GLFW window '" + options.title + "': size " + std::to_string(options.width) + "x" +
                    std::to_string(options.height) + " is empty");
    initGlfw();
    auto impl = std::make_unique<Impl>();
    std::string tried;
    for (int minor : {5, 4, 3}) {
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, minor);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_RESIZABLE, options.resizable ? GLFW_TRUE : GLFW_FALSE);
        gLastGlfwError.clear();
        impl->window = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
        if (impl->window) break;
        tried += (tried.empty() ? "" : "; ") + ("4." + std::to_string(minor) + ": ") +
                 (gLastGlfwError.empty() ? std::string("failed") : gLastGlfwError);
    }
    if (!impl->window) throw Error("GLFW window '" + options.title + "': no OpenGL core 4.3+ context (" + tried + ")");
    glfwMakeContextCurrent(impl->window);
    impl->major = glfwGetWindowAttrib(impl->window, GLFW_CONTEXT_VERSION_MAJOR);
    impl->minor = glfwGetWindowAttrib(impl->window, GLFW_CONTEXT_VERSION_MINOR);
    impl->vsync = options.vsync;
    glfwSwapInterval(options.vsync ? 1 : 0);
    glfwSetWindowUserPointer(impl->window, impl.get());
    glfwSetWindowIconifyCallback(impl->window, [](GLFWwindow* w, int iconified) {
        static_cast<Impl*>(glfwGetWindowUserPointer(w))->minimized = iconified == GLFW_TRUE;
    });
    impl->description = "GLFW window '" + options.title + "', " +
                        reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + ", " +
                        reinterpret_cast<const char*>(glGetString(GL_VERSION));
    log::debug("GL: ", impl->description);
    return std::unique_ptr<GlfwWindowContext>(new GlfwWindowContext(std::move(impl)));
}

void GlfwWindowContext::makeCurrent() {
    if (glfwGetCurrentContext() != impl_->window) glfwMakeContextCurrent(impl_->window);
}

std::string GlfwWindowContext::describe() const { return impl_->description; }

glm::ivec2 GlfwWindowContext::framebufferSize() const {
    if (impl_->minimized || glfwGetWindowAttrib(impl_->window, GLFW_ICONIFIED)) return {0, 0};
    int w = 0, h = 0;
    glfwGetFramebufferSize(impl_->window, &w, &h);
    return {w, h};
}

void GlfwWindowContext::swapBuffers() { glfwSwapBuffers(impl_->window); }
void GlfwWindowContext::pollEvents() { glfwPollEvents(); }
bool GlfwWindowContext::shouldClose() const { return glfwWindowShouldClose(impl_->window) == GLFW_TRUE; }
void GlfwWindowContext::requestClose() { glfwSetWindowShouldClose(impl_->window, GLFW_TRUE); }

void GlfwWindowContext::setSize(int width, int height) {
    if (width <= 0 || height <= 0) {
        impl_->minimized = true;
        glfwIconifyWindow(impl_->window);
        return;
    }
    if (impl_->minimized || glfwGetWindowAttrib(impl_->window, GLFW_ICONIFIED)) glfwRestoreWindow(impl_->window);
    impl_->minimized = false;
    glfwSetWindowSize(impl_->window, width, height);
}

bool GlfwWindowContext::minimized() const {
    return impl_->minimized || glfwGetWindowAttrib(impl_->window, GLFW_ICONIFIED);
}

void GlfwWindowContext::setVsync(bool vsync) {
    makeCurrent();
    impl_->vsync = vsync;
    glfwSwapInterval(vsync ? 1 : 0);
}

bool GlfwWindowContext::vsync() const { return impl_->vsync; }
int GlfwWindowContext::glMajor() const { return impl_->major; }
int GlfwWindowContext::glMinor() const { return impl_->minor; }
GLFWwindow* GlfwWindowContext::window() const { return impl_->window; }

}  // namespace engine::render::gl
