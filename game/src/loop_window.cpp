// SPDX-License-Identifier: MIT
#include "loop_window.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace racer {
namespace {

using engine::render::TextureHandle;

// The soft backend's frame as a GL texture: the stored sRGB codes (readback gives code/255)
// uploaded unchanged, so the window shows exactly the bytes a capture would hold.
TextureHandle uploadFrame(engine::render::Device& presenter, const engine::render::Readback& r) {
    std::vector<std::byte> bytes(std::size_t(r.width) * std::size_t(r.height) * 4);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const float v = c < r.channels ? r.at(x, y, c) : 1.0f;
                bytes[(std::size_t(y) * std::size_t(r.width) + std::size_t(x)) * 4 + std::size_t(c)] =
                    std::byte(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
            }
    engine::render::TextureData data;
    data.levels.push_back(bytes);
    return presenter.createTexture(
        {"racer soft frame", r.width, r.height, r.format, 1, 1, engine::render::UsageSampled}, &data);
}

// GLFW's GL context and the Vulkan window answer the loop's window questions alike; only
// show() differs.
template <typename Window>
class GlfwLoopWindow : public LoopWindow {
public:
    explicit GlfwLoopWindow(Window& window) : window_(window) {}
    GLFWwindow* window() const override { return window_.window(); }
    glm::ivec2 framebufferSize() const override { return window_.framebufferSize(); }
    void pollEvents() override { window_.pollEvents(); }
    bool shouldClose() const override { return window_.shouldClose(); }
    void requestClose() override { window_.requestClose(); }
    void setSize(int width, int height) override { window_.setSize(width, height); }

private:
    Window& window_;
};

class GlLoopWindow final : public GlfwLoopWindow<engine::render::gl::GlfwWindowContext> {
public:
    GlLoopWindow(engine::render::gl::GlfwWindowContext& window, engine::render::Device& presenter,
                 engine::render::Backend& renderer)
        : GlfwLoopWindow(window), presenter_(presenter), renderer_(renderer) {}
    bool show(TextureHandle color) override {
        if (static_cast<engine::render::Backend*>(&presenter_) == &renderer_) return presenter_.present(color);
        const TextureHandle shown = uploadFrame(presenter_, renderer_.readback(color));
        const bool presented = presenter_.present(shown);
        presenter_.destroy(shown);
        presenter_.takeTimings();  // the upload's, not the frame's
        return presented;
    }

private:
    engine::render::Device& presenter_;
    engine::render::Backend& renderer_;
};

class VkLoopWindow final : public GlfwLoopWindow<engine::render::vk::VulkanWindow> {
public:
    VkLoopWindow(engine::render::vk::VulkanWindow& window, engine::render::Device& backend)
        : GlfwLoopWindow(window), backend_(backend) {}
    bool show(TextureHandle color) override { return backend_.present(color); }

private:
    engine::render::Device& backend_;
};

}  // namespace

std::unique_ptr<LoopWindow> glLoopWindow(engine::render::gl::GlfwWindowContext& window,
                                         engine::render::Device& presenter, engine::render::Backend& renderer) {
    return std::make_unique<GlLoopWindow>(window, presenter, renderer);
}

std::unique_ptr<LoopWindow> vkLoopWindow(engine::render::vk::VulkanWindow& window, engine::render::Device& backend) {
    return std::make_unique<VkLoopWindow>(window, backend);
}

}  // namespace racer
