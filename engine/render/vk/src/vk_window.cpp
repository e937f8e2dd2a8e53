// SPDX-License-Identifier: MIT
// The Vulkan backend's GLFW window (vk_window.hpp). GLFW is initialized once and never
// terminated, as for the GL window (glfw_context.cpp): glfwTerminate would unload what the
// drivers keep for good.
#include "engine/render/vk/vk_window.hpp"

#include <mutex>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"

namespace engine::render::vk {
namespace {

std::mutex gGlfwMutex;
std::string gLastGlfwError;

void onGlfwError(int code, const char* description) {
    gLastGlfwError = "GLFW error " + std::to_string(code) + ": " + (description ? description : "?");
    log::debug(gLastGlfwError);
}

void initGlfw() {
    std::lock_guard lock(gGlfwMutex);
    glfwSetErrorCallback(onGlfwError);
    gLastGlfwError.clear();
    // A second glfwInit (the GL window's) returns at once.
    if (!glfwInit())
        throw Error("GLFW window: glfwInit failed" +
                    (gLastGlfwError.empty() ? std::string() : " (" + gLastGlfwError + ")") +
                    "; is there a display (DISPLAY/WAYLAND_DISPLAY, or run under xvfb-run)?");
    if (!glfwVulkanSupported()) throw Error("GLFW window: GLFW finds no Vulkan loader");
}

}  // namespace

std::shared_ptr<VulkanWindow> VulkanWindow::create(const VulkanWindowOptions& options) {
    if (options.width <= 0 || options.height <= 0)
        throw Error("GLFW window '" + options.title + "': size " + std::to_string(options.width) + "x" +
                    std::to_string(options.height) + " is empty");
    initGlfw();
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_RESIZABLE, options.resizable ? GLFW_TRUE : GLFW_FALSE);
    gLastGlfwError.clear();
    std::shared_ptr<VulkanWindow> w(new VulkanWindow);
    w->window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!w->window_)
        throw Error("GLFW window '" + options.title + "': no window for Vulkan (" +
                    (gLastGlfwError.empty() ? std::string("failed") : gLastGlfwError) + ")");
    glfwSetWindowUserPointer(w->window_, w.get());
    glfwSetWindowIconifyCallback(w->window_, [](GLFWwindow* window, int iconified) {
        static_cast<VulkanWindow*>(glfwGetWindowUserPointer(window))->minimized_ = iconified == GLFW_TRUE;
    });
    return w;
}

VulkanWindow::~VulkanWindow() {
    if (window_) glfwDestroyWindow(window_);
}

std::vector<std::string> VulkanWindow::instanceExtensions() {
    initGlfw();
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw Error("GLFW window: no Vulkan surface extensions for this platform");
    return {names, names + count};
}

glm::ivec2 VulkanWindow::framebufferSize() const {
    if (minimized()) return {0, 0};
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {w, h};
}

void VulkanWindow::pollEvents() { glfwPollEvents(); }
bool VulkanWindow::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void VulkanWindow::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void VulkanWindow::setSize(int width, int height) {
    if (width <= 0 || height <= 0) {
        minimized_ = true;
        glfwIconifyWindow(window_);
        return;
    }
    if (minimized()) glfwRestoreWindow(window_);
    minimized_ = false;
    glfwSetWindowSize(window_, width, height);
}

bool VulkanWindow::minimized() const { return minimized_ || glfwGetWindowAttrib(window_, GLFW_ICONIFIED); }

}  // namespace engine::render::vk
