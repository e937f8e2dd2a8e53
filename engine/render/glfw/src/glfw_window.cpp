// SPDX-License-Identifier: MIT
// The GLFW window both backends' demo windows share (glfw_window.hpp).
#include "engine/render/glfw/glfw_window.hpp"

#include <mutex>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"

namespace engine::render::glfw {
namespace {

std::mutex gGlfwMutex;
bool gGlfwInitialized = false;
std::string gLastGlfwError;

void onGlfwError(int code, const char* description) {
    gLastGlfwError = "GLFW error " + std::to_string(code) + ": " + (description ? description : "?");
    log::debug(gLastGlfwError);
}

}  // namespace

void initialize() {
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

std::unique_ptr<Window> Window::create(const WindowSpec& spec, const std::function<void()>& apiHints,
                                       std::string& whyNot) {
    if (spec.width <= 0 || spec.height <= 0)
        throw Error("GLFW window '" + spec.title + "': size " + std::to_string(spec.width) + "x" +
                    std::to_string(spec.height) + " is empty");
    initialize();
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, spec.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_RESIZABLE, spec.resizable ? GLFW_TRUE : GLFW_FALSE);
    apiHints();
    gLastGlfwError.clear();
    GLFWwindow* window = glfwCreateWindow(spec.width, spec.height, spec.title.c_str(), nullptr, nullptr);
    if (!window) {
        whyNot = gLastGlfwError.empty() ? std::string("failed") : gLastGlfwError;
        return nullptr;
    }
    std::unique_ptr<Window> w(new Window(window));
    glfwSetWindowUserPointer(window, w.get());
    glfwSetWindowIconifyCallback(window, [](GLFWwindow* handle, int iconified) {
        static_cast<Window*>(glfwGetWindowUserPointer(handle))->minimized_ = iconified == GLFW_TRUE;
    });
    return w;
}

Window::Window(GLFWwindow* window) : window_(window) {}
Window::~Window() { glfwDestroyWindow(window_); }

glm::ivec2 Window::framebufferSize() const {
    if (minimized()) return {0, 0};
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {w, h};
}

void Window::pollEvents() { glfwPollEvents(); }
bool Window::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void Window::setSize(int width, int height) {
    if (width <= 0 || height <= 0) {
        minimized_ = true;
        glfwIconifyWindow(window_);
        return;
    }
    if (minimized()) glfwRestoreWindow(window_);
    minimized_ = false;
    glfwSetWindowSize(window_, width, height);
}

bool Window::minimized() const { return minimized_ || glfwGetWindowAttrib(window_, GLFW_ICONIFIED); }

}  // namespace engine::render::glfw
