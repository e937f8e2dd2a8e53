// SPDX-License-Identifier: MIT
#pragma once
// A GLFW 3.3 window with no client API (GLFW_NO_API) for the Vulkan backend to present to
// (VulkanOptions::window): the backend makes its surface with glfwCreateWindowSurface and
// presents through a swapchain (VulkanBackend::present). The window's size rules are the GL
// window's (GlfwWindowContext): minimising (by the user, or setSize(0, 0)) makes
// framebufferSize() 0x0 so callers skip rendering; Xvfb has no window manager, so the state
// is tracked here too. Windows are created and used on the thread that initialized GLFW.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

struct GLFWwindow;

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
    ~VulkanWindow();
    VulkanWindow(const VulkanWindow&) = delete;
    VulkanWindow& operator=(const VulkanWindow&) = delete;

    // The instance extensions its surface needs (VK_KHR_surface and the platform's).
    static std::vector<std::string> instanceExtensions();

    glm::ivec2 framebufferSize() const;  // 0x0 while minimised
    void pollEvents();
    bool shouldClose() const;
    void requestClose();
    // Resizes the window; 0 in either dimension minimises it (framebufferSize() is then 0x0
    // until a later non-zero size restores it), as a user minimising the window would.
    void setSize(int width, int height);
    bool minimized() const;
    GLFWwindow* window() const { return window_; }

private:
    VulkanWindow() = default;
    GLFWwindow* window_ = nullptr;
    bool minimized_ = false;  // by setSize(0, 0) or the iconify callback
};

}  // namespace engine::render::vk
