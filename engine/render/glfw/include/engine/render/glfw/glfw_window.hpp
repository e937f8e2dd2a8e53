// SPDX-License-Identifier: MIT
#pragma once
// The GLFW 3.3 window under both backends' demo windows (the GL backend's GlfwWindowContext, the
// Vulkan backend's VulkanWindow), which add only their client API. Minimising (by the user, or
// setSize(0, 0)) makes framebufferSize() 0x0 so callers skip rendering; window managers differ on
// whether an iconified window keeps its framebuffer size, and Xvfb has no window manager at all,
// so the state is tracked here too. Windows are created and used on the thread that initialized
// GLFW (GLFW's rule).
#include <functional>
#include <memory>
#include <string>

#include <glm/vec2.hpp>

struct GLFWwindow;

namespace engine::render::glfw {

// Initializes GLFW once for the process; it is never terminated: glfwTerminate unloads the
// drivers, leaving what they keep for good to leak checkers as leaks from an unknown module (the
// same choice as for EGL displays in egl_context.cpp). Throws engine::Error when GLFW cannot
// initialise, with the likely cause (no display).
void initialize();

struct WindowSpec {
    std::string title = "ssam";
    int width = 1280, height = 720;  // in screen coordinates
    bool visible = true;
    bool resizable = true;
};

class Window {
public:
    // Initializes GLFW, sets the default hints, visibility and resizability, then the caller's
    // client-API hints (`apiHints`), and creates the window. Throws engine::Error on an empty size
    // or when GLFW cannot initialise; returns null when GLFW refuses the window, with its reason
    // in `whyNot`, so a caller can try other hints.
    static std::unique_ptr<Window> create(const WindowSpec& spec, const std::function<void()>& apiHints,
                                          std::string& whyNot);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    glm::ivec2 framebufferSize() const;  // 0x0 while minimised
    void pollEvents();
    bool shouldClose() const;
    void requestClose();
    // Resizes the window; 0 in either dimension minimises it (framebufferSize() is then 0x0
    // until a later non-zero size restores it), as a user minimising the window would.
    void setSize(int width, int height);
    bool minimized() const;

private:
    explicit Window(GLFWwindow* window);
    GLFWwindow* window_;
    bool minimized_ = false;  // by setSize(0, 0) or the iconify callback
};

}  // namespace engine::render::glfw
