// SPDX-License-Identifier: MIT
#pragma once
// Where the GL backend's context comes from. A GlContext owns (or wraps) one OpenGL 4.5
// core context and says whether it has a window to present to:
//   HeadlessEglContext  EGL without any surface (Mesa's surfaceless platform, then the EGL
//                       device platform for NVIDIA); the backend renders into FBOs only.
//   GlfwWindowContext   a GLFW 3.3 window: core 4.5, or the highest core >= 4.3 available
//                       (which then needs ARB_clip_control + ARB_direct_state_access).
// Contexts are current on one thread at a time; the backend makes its context current when
// it is created and expects it to stay current on that thread.
#include <memory>
#include <string>

#include <glm/glm.hpp>

struct GLFWwindow;

namespace engine::render::gl {

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual void makeCurrent() = 0;
    // "EGL surfaceless (Mesa Project) 4.5" etc., for logs and errors.
    virtual std::string describe() const = 0;
    virtual bool hasWindow() const { return false; }
    // Default framebuffer size in pixels; 0x0 when there is none or the window is minimised
    // (callers skip rendering then).
    virtual glm::ivec2 framebufferSize() const { return {0, 0}; }
    virtual void swapBuffers() {}
};

struct HeadlessEglOptions {
    int major = 4, minor = 5;  // core profile, at least 4.5 is what the backend needs
    bool debug = false;        // ask for a debug context (KHR_debug messages go to the log)
    // -1: Mesa's surfaceless platform first, then every EGL device in order;
    // >= 0: only that EGL device (EGL_EXT_device_enumeration order).
    int device = -1;
    // An OpenGL ES context of version major.minor (EGL_OPENGL_ES_API, an ES3 config) instead of
    // a core one: the GLES driver's (engine/render/gles), which asks for 3.0. Last, so that a
    // host's positional {major, minor, debug, device} keeps its meaning.
    bool es = false;
};

class HeadlessEglContext final : public GlContext {
public:
    // Throws engine::Error saying what is missing (no EGL, no platform, no 4.5 core context).
    static std::unique_ptr<HeadlessEglContext> create(const HeadlessEglOptions& options = {});
    // Empty when a headless context can be created here, else why not (for test skips).
    static std::string unavailableReason(const HeadlessEglOptions& options = {});
    ~HeadlessEglContext() override;

    void makeCurrent() override;
    std::string describe() const override;

    struct Impl;

private:
    explicit HeadlessEglContext(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

struct GlfwWindowOptions {
    std::string title = "ssam";
    int width = 1280, height = 720;  // window size in screen coordinates
    bool vsync = true;               // swap interval 1, else 0
    bool visible = true;
    bool resizable = true;
    bool debug = false;
};

class GlfwWindowContext final : public GlContext {
public:
    // Throws engine::Error when GLFW cannot initialise (no display) or no core >= 4.3 context exists.
    static std::unique_ptr<GlfwWindowContext> create(const GlfwWindowOptions& options = {});
    ~GlfwWindowContext() override;

    void makeCurrent() override;
    std::string describe() const override;
    bool hasWindow() const override { return true; }
    glm::ivec2 framebufferSize() const override;
    void swapBuffers() override;

    void pollEvents();
    bool shouldClose() const;
    void requestClose();
    // Resizes the window; 0 in either dimension minimises it (framebufferSize() is then
    // 0x0 until a later non-zero size restores it), as a user minimising the window would.
    void setSize(int width, int height);
    bool minimized() const;
    void setVsync(bool vsync);
    bool vsync() const;
    int glMajor() const;
    int glMinor() const;
    GLFWwindow* window() const;

    struct Impl;

private:
    explicit GlfwWindowContext(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace engine::render::gl
