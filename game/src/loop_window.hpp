// SPDX-License-Identifier: MIT
#pragma once
// What racer's window loop needs of its window, whichever API shows the frames: a GL window
// (the GL backend's context presents; a soft frame is read back and uploaded to it) or a
// Vulkan window (the Vulkan backend presents through its swapchain).
#include <memory>

#include <glm/vec2.hpp>

#include "engine/render/backend.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/gl/gl_context.hpp"
#include "engine/render/vk/vk_backend.hpp"
#include "engine/render/vk/vk_window.hpp"

struct GLFWwindow;

namespace racer {

class LoopWindow {
public:
    virtual ~LoopWindow() = default;
    virtual GLFWwindow* window() const = 0;
    virtual glm::ivec2 framebufferSize() const = 0;  // 0x0 while minimised
    virtual void pollEvents() = 0;
    virtual bool shouldClose() const = 0;
    virtual void requestClose() = 0;
    virtual void setSize(int width, int height) = 0;  // 0 in either: minimise
    // Shows the frame's colour (after FrameRenderer::render); false when nothing was shown.
    virtual bool show(engine::render::TextureHandle color) = 0;
};

// `presenter` owns the window's context; `renderer` draws the frames: the same backend, or
// another (soft) whose colour is read back and uploaded each frame.
std::unique_ptr<LoopWindow> glLoopWindow(engine::render::gl::GlfwWindowContext& window,
                                         engine::render::Device& presenter, engine::render::Backend& renderer);
// `backend` was made with `window` (VulkanOptions::window) and draws the frames.
std::unique_ptr<LoopWindow> vkLoopWindow(engine::render::vk::VulkanWindow& window, engine::render::Device& backend);

}  // namespace racer
