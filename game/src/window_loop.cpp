#include "window_loop.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/error.hpp"
#include "racer_options.hpp"
#include "window_keys.hpp"

namespace racer {

namespace {

using Clock = std::chrono::steady_clock;
using engine::render::TextureHandle;
using transparency::TechniqueKind;

constexpr double kTitleInterval = 0.25;  // seconds between title updates
constexpr double kMaxWallStep = 0.1;     // a stalled frame (window dragged) never jumps the car far

// Frame and per-pass times summed since the last title update.
struct TitleStats {
    int frames = 0;
    double frameMs = 0.0;
    std::vector<std::pair<std::string, double>> passes;  // first-seen order

    void add(double ms, const std::vector<engine::render::PassTiming>& timings) {
        ++frames;
        frameMs += ms;
        for (const auto& t : timings) {
            auto it = std::find_if(passes.begin(), passes.end(), [&](const auto& p) { return p.first == t.pass; });
            if (it == passes.end()) passes.emplace_back(t.pass, t.milliseconds);
            else it->second += t.milliseconds;
        }
    }
    std::string title(TechniqueKind technique, CameraMode camera, bool paused) const {
        char head[160];
        std::snprintf(head, sizeof head, "racer | %s | %s%s | %.1f fps | %.1f ms |", transparency::techniqueName(technique),
                      cameraName(camera), paused ? " (paused)" : "", frames ? 1000.0 * frames / frameMs : 0.0,
                      frames ? frameMs / frames : 0.0);
        std::string text = head;
        for (const auto& [name, ms] : passes) {
            char buf[96];
            std::snprintf(buf, sizeof buf, " %s %.1f", name.c_str(), ms / std::max(1, frames));
            text += buf;
        }
        if (camera == CameraMode::Free) text += std::string(" | ") + flyKeysHelp();
        return text;
    }
};

bool trySetTechnique(FrameRenderer& frame, TechniqueKind kind) {
    try {
        frame.setTechnique(kind);
        std::printf("racer: technique %s (opaque pass %dx)\n", transparency::techniqueName(kind), frame.opaqueSamples());
        return true;
    } catch (const engine::Error& e) {
        std::printf("racer: technique %s unavailable, keeping %s: %s\n", transparency::techniqueName(kind),
                    transparency::techniqueName(frame.technique()), e.what());
        return false;
    }
}

// T / Shift+T: the next (previous) technique in allTechniques() order that can be created.
void stepTechnique(FrameRenderer& frame, int step) {
    const auto all = transparency::allTechniques();
    const int n = int(all.size());
    const int current = int(std::find(all.begin(), all.end(), frame.technique()) - all.begin());
    for (int k = 1; k < n; ++k)
        if (trySetTechnique(frame, all[std::size_t(((current + step * k) % n + n) % n)])) return;
}

CameraMode nextCamera(CameraMode mode) {
    switch (mode) {
        case CameraMode::Chase: return CameraMode::Pan;
        case CameraMode::Pan: return CameraMode::Free;
        default: return CameraMode::Chase;
    }
}

void printPose(const FreeCamera& c) {
    std::printf("racer: free camera at (%.2f, %.2f, %.2f), yaw %.1f deg, pitch %.1f deg\n", c.position.x, c.position.y,
                c.position.z, glm::degrees(c.yaw), glm::degrees(c.pitch));
}

// Mouse look: while the right button is held the cursor is hidden and captured (disabled,
// so it never leaves the window) and its motion turns the free camera.
class MouseLook {
public:
    explicit MouseLook(GLFWwindow* window) : window_(window) {}
    // Pixels moved since the last frame while the button is held; releases the cursor otherwise.
    glm::vec2 motion(bool active) {
        active = active && glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
        if (active != captured_) {
            glfwSetInputMode(window_, GLFW_CURSOR, active ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
            if (glfwRawMouseMotionSupported())
                glfwSetInputMode(window_, GLFW_RAW_MOUSE_MOTION, active ? GLFW_TRUE : GLFW_FALSE);
            captured_ = active;
            if (active) glfwGetCursorPos(window_, &x_, &y_);  // the first held frame does not jump
        }
        if (!active) return glm::vec2(0.0f);
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window_, &x, &y);
        const glm::vec2 moved(float(x - x_), float(y - y_));
        x_ = x;
        y_ = y;
        return moved;
    }

private:
    GLFWwindow* window_;
    bool captured_ = false;
    double x_ = 0.0, y_ = 0.0;
};

// The soft backend's frame as a GL texture: the stored sRGB codes (readback gives code/255)
// uploaded unchanged, so the window shows exactly the bytes a capture would hold.
TextureHandle uploadFrame(engine::render::gl::GlBackend& presenter, const engine::render::Readback& r) {
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
    return presenter.createTexture({"racer soft frame", r.width, r.height, r.format, 1, 1, engine::render::UsageSampled},
                                   &data);
}

}  // namespace

WindowLoopResult runWindowLoop(engine::render::gl::GlfwWindowContext& window, engine::render::gl::GlBackend& presenter,
                               engine::render::Backend& renderer, FrameRenderer& frame, const FrameSource& source,
                               const WindowLoopSettings& settings) {
    const std::vector<ScriptedKey> script = parseKeyScript(settings.keyScript);
    std::size_t nextScripted = 0;
    std::map<int, bool> wasDown;
    const bool uploads = static_cast<engine::render::Backend*>(&presenter) != &renderer;
    CameraMode camera = settings.camera;
    FreeCamera flyer;  // starts at the overview a headless --camera free run renders
    MouseLook mouse(window.window());
    bool paused = false;
    double time = 0.0, totalMs = 0.0;
    TitleStats stats;
    Clock::time_point last = Clock::now(), titleShown = last;
    WindowLoopResult result;
    if (camera == CameraMode::Free) std::printf("racer: free camera: %s\n", flyKeysHelp());

    while (settings.frames == 0 || result.frames < settings.frames) {
        window.pollEvents();
        if (window.shouldClose()) break;
        if (window.minimized()) {  // nothing to show: do not spin
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            last = Clock::now();
            continue;
        }

        // Keys pressed since the last frame (edges of the polled state), then scripted ones.
        std::vector<KeyAction> actions;
        const bool shift = glfwGetKey(window.window(), GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                           glfwGetKey(window.window(), GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
        for (int key : watchedKeys()) {
            const bool down = glfwGetKey(window.window(), key) == GLFW_PRESS;
            if (down && !wasDown[key]) actions.push_back(actionForKey(key, shift));
            wasDown[key] = down;
        }
        for (; nextScripted < script.size() && script[nextScripted].frame <= result.frames; ++nextScripted)
            actions.push_back(actionForKey(script[nextScripted].key, script[nextScripted].shift));
        bool quit = false;
        for (const KeyAction& a : actions) {
            switch (a.action) {
                case WindowAction::Quit: quit = true; break;
                case WindowAction::SelectTechnique:
                    trySetTechnique(frame, transparency::allTechniques()[std::size_t(a.technique)]);
                    break;
                case WindowAction::NextTechnique: stepTechnique(frame, +1); break;
                case WindowAction::PreviousTechnique: stepTechnique(frame, -1); break;
                case WindowAction::NextCamera:
                    camera = nextCamera(camera);
                    std::printf("racer: camera %s\n", cameraName(camera));
                    if (camera == CameraMode::Free) std::printf("racer: free camera: %s\n", flyKeysHelp());
                    break;
                case WindowAction::TogglePause:
                    paused = !paused;
                    std::printf("racer: %s\n", paused ? "paused" : "running");
                    break;
                case WindowAction::None: break;
            }
        }
        if (quit) {
            window.requestClose();
            break;
        }

        const Clock::time_point start = Clock::now();
        const double wall = std::chrono::duration<double>(start - last).count();
        last = start;
        const double step = settings.fixedDt > 0.0 ? settings.fixedDt : std::min(wall, kMaxWallStep);
        const double dt = paused ? 0.0 : step;
        // The free camera flies by the frame's step, paused or not (a paused frame can be
        // looked around); its keys do nothing with the other cameras.
        const glm::vec2 look = mouse.motion(camera == CameraMode::Free);
        if (camera == CameraMode::Free) {
            FlyControls controls = flyControls([&](int key) {
                return glfwGetKey(window.window(), key) == GLFW_PRESS || scriptHolds(script, result.frames, key);
            });
            controls.look = look;
            flyer = flyStep(flyer, controls, float(step));
        }
        // As the headless loop: frame i steps the world by dt and sees the camera at i * dt,
        // so a window with --fixed-dt shows the frames a headless run captures.
        const SceneFrame scene = source(float(time), float(dt), camera, flyer, settings.aspect);
        time += dt;
        frame.render(scene.lists, scene.camera);
        if (uploads) {
            const TextureHandle shown = uploadFrame(presenter, renderer.readback(frame.color()));
            presenter.present(shown);
            presenter.destroy(shown);
            presenter.takeTimings();  // the upload's, not the frame's
        } else {
            presenter.present(frame.color());
        }
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        totalMs += ms;
        ++result.frames;
        stats.add(ms, renderer.takeTimings());
        if (std::chrono::duration<double>(Clock::now() - titleShown).count() >= kTitleInterval) {
            glfwSetWindowTitle(window.window(), stats.title(frame.technique(), camera, paused).c_str());
            stats = {};
            titleShown = Clock::now();
        }
    }
    if (camera == CameraMode::Free) printPose(flyer);
    result.meanFrameMs = totalMs / std::max(1, result.frames);
    return result;
}

}  // namespace racer
