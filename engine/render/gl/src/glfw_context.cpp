// SPDX-License-Identifier: MIT
// A GLFW 3.3 window (glfw::Window, glfw_window.hpp: its size and minimise rules) with a core 4.5
// context, or the highest core >= 4.3 the display offers.
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/gl/gl_context.hpp"
#include "engine/render/glfw/glfw_window.hpp"

namespace engine::render::gl {

struct GlfwWindowContext::Impl {
    std::unique_ptr<glfw::Window> window;
    bool vsync = true;
    int major = 0, minor = 0;
    std::string description;
};

GlfwWindowContext::GlfwWindowContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlfwWindowContext::~GlfwWindowContext() = default;

std::unique_ptr<GlfwWindowContext> GlfwWindowContext::create(const GlfwWindowOptions& options) {
    auto impl = std::make_unique<Impl>();
    const glfw::WindowSpec spec{options.title, options.width, options.height, options.visible, options.resizable};
    std::string tried;
    for (int minor : {5, 4, 3}) {
        std::string whyNot;
        impl->window = glfw::Window::create(
            spec,
            [&] {
                glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
                glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
                glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, minor);
                glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
                glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
                glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
            },
            whyNot);
        if (impl->window) break;
        tried += (tried.empty() ? "" : "; ") + ("4." + std::to_string(minor) + ": ") + whyNot;
    }
    if (!impl->window) throw Error("GLFW window '" + options.title + "': no OpenGL core 4.3+ context (" + tried + ")");
    GLFWwindow* window = impl->window->handle();
    glfwMakeContextCurrent(window);
    impl->major = glfwGetWindowAttrib(window, GLFW_CONTEXT_VERSION_MAJOR);
    impl->minor = glfwGetWindowAttrib(window, GLFW_CONTEXT_VERSION_MINOR);
    impl->vsync = options.vsync;
    glfwSwapInterval(options.vsync ? 1 : 0);
    impl->description = "GLFW window '" + options.title + "', " +
                        reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + ", " +
                        reinterpret_cast<const char*>(glGetString(GL_VERSION));
    log::debug("GL: ", impl->description);
    return std::unique_ptr<GlfwWindowContext>(new GlfwWindowContext(std::move(impl)));
}

void GlfwWindowContext::makeCurrent() {
    if (glfwGetCurrentContext() != impl_->window->handle()) glfwMakeContextCurrent(impl_->window->handle());
}

std::string GlfwWindowContext::describe() const { return impl_->description; }
glm::ivec2 GlfwWindowContext::framebufferSize() const { return impl_->window->framebufferSize(); }
void GlfwWindowContext::swapBuffers() { glfwSwapBuffers(impl_->window->handle()); }
void GlfwWindowContext::pollEvents() { impl_->window->pollEvents(); }
bool GlfwWindowContext::shouldClose() const { return impl_->window->shouldClose(); }
void GlfwWindowContext::requestClose() { impl_->window->requestClose(); }
void GlfwWindowContext::setSize(int width, int height) { impl_->window->setSize(width, height); }
bool GlfwWindowContext::minimized() const { return impl_->window->minimized(); }

void GlfwWindowContext::setVsync(bool vsync) {
    makeCurrent();
    impl_->vsync = vsync;
    glfwSwapInterval(vsync ? 1 : 0);
}

bool GlfwWindowContext::vsync() const { return impl_->vsync; }
int GlfwWindowContext::glMajor() const { return impl_->major; }
int GlfwWindowContext::glMinor() const { return impl_->minor; }
GLFWwindow* GlfwWindowContext::window() const { return impl_->window->handle(); }

}  // namespace engine::render::gl
