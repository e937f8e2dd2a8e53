// SPDX-License-Identifier: MIT
#pragma once
// A GLFW 3.3 window with no client API (GLFW_NO_API) for the Vulkan backend to present to
// (VulkanOptions::window): the backend makes its surface with glfwCreateWindowSurface and
// presents through a swapchain (Device::present). The window, its size and minimise rules
// are the GL window's (both are an engine::render::glfw::Window, glfw_window.hpp).
#include <memory>
#include <string>
#include <vector>

#include "engine/render/glfw/glfw_window.hpp"

namespace engine::render::vk {

struct VulkanWindowOptions {
    std::string title = "ssam";
    int width = 1280, height = 720;
    bool visible = true;
    bool resizable = true;
};

class VulkanWindow {
public:
    // Throws engine::Error when GLFW cannot initialise (no display) or has no Vulkan loader.
    static std::shared_ptr<VulkanWindow> create(const VulkanWindowOptions& options = {});
    VulkanWindow(const VulkanWindow&) = delete;
    VulkanWindow& operator=(const VulkanWindow&) = delete;

    // The instance extensions its surface needs (VK_KHR_surface and the platform's).
    static std::vector<std::string> instanceExtensions();

    glm::ivec2 framebufferSize() const { return window_->framebufferSize(); }  // 0x0 while minimised
    void pollEvents() { window_->pollEvents(); }
    bool shouldClose() const { return window_->shouldClose(); }
    void requestClose() { window_->requestClose(); }
    void setSize(int width, int height) { window_->setSize(width, height); }  // glfw::Window::setSize
    bool minimized() const { return window_->minimized(); }
    GLFWwindow* window() const { return window_->handle(); }

private:
    explicit VulkanWindow(std::unique_ptr<glfw::Window> window) : window_(std::move(window)) {}
    std::unique_ptr<glfw::Window> window_;
};

}  // namespace engine::render::vk
