// SPDX-License-Identifier: MIT
// The Vulkan backend's GLFW window (vk_window.hpp): a glfw::Window with no client API.
#include "engine/render/vk/vk_window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "engine/core/error.hpp"

namespace engine::render::vk {
namespace {

void initGlfwForVulkan() {
    glfw::initialize();
    if (!glfwVulkanSupported()) throw Error("GLFW window: GLFW finds no Vulkan loader");
}

}  // namespace

std::shared_ptr<VulkanWindow> VulkanWindow::create(const VulkanWindowOptions& options) {
    const glfw::WindowSpec spec{options.title, options.width, options.height, options.visible, options.resizable};
    if (spec.width > 0 && spec.height > 0) initGlfwForVulkan();  // an empty size: glfw::Window::create says so
    std::string whyNot;
    auto window = glfw::Window::create(
        spec, [] { glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API); }, whyNot);
    if (!window) throw Error("GLFW window '" + options.title + "': no window for Vulkan (" + whyNot + ")");
    return std::shared_ptr<VulkanWindow>(new VulkanWindow(std::move(window)));
}

std::vector<std::string> VulkanWindow::instanceExtensions() {
    initGlfwForVulkan();
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw Error("GLFW window: no Vulkan surface extensions for this platform");
    return {names, names + count};
}

}  // namespace engine::render::vk
