// SPDX-License-Identifier: MIT
#include "window_loop.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/error.hpp"
#include "hud_text.hpp"
#include "racer_options.hpp"
#include "render_size.hpp"
#include "window_keys.hpp"

namespace racer {

namespace {

using Clock = std::chrono::steady_clock;
using transparency::TechniqueKind;

constexpr double kTitleInterval = 0.25;                      // seconds between title updates
constexpr double kMaxWallStep = 0.1;                         // a stalled frame (window dragged) never jumps the car far
constexpr auto kWindowSettleTime = std::chrono::seconds(1);  // a scripted resize waits this long at most

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
    std::string title(TechniqueKind technique, CameraMode camera, bool paused, FrameSize size) const {
        char head[192];
        std::snprintf(head, sizeof head, "racer | %s | %s%s | %dx%d | %.1f fps | %.1f ms |",
                      transparency::techniqueName(technique), cameraName(camera), paused ? " (paused)" : "", size.width,
                      size.height, frames ? 1000.0 * frames / frameMs : 0.0, frames ? frameMs / frames : 0.0);
        std::string text = head;
        for (const auto& [name, ms] : passes) {
            char buf[96];
            std::snprintf(buf, sizeof buf, " %s %.1f", name.c_str(), ms / std::max(1, frames));
            text += buf;
        }
        if (camera == CameraMode::Free) text += std::string(" | ") + flyKeysHelp();
        if (camera == CameraMode::Chase) text += std::string(" | ") + driveKeysHelp();
        return text;
    }
    // The same means for the HUD (technique, backend and size filled in when it is drawn).
    HudFacts hudFacts() const {
        HudFacts f;
        f.timeSpan = "mean of " + std::to_string(frames) + " frames";
        f.frameMs = frames ? frameMs / frames : -1.0;
        for (const auto& [name, ms] : passes) f.passes.push_back({name, ms / std::max(1, frames), false});
        return f;
    }
};

bool trySetTechnique(FrameRenderer& frame, TechniqueKind kind) {
    try {
        frame.setTechnique(kind);
        std::printf("racer: technique %s (opaque pass %dx)\n", transparency::techniqueName(kind),
                    frame.opaqueSamples());
        return true;
    } catch (const engine::Error& e) {
        std::printf("racer: technique %s unavailable, keeping %s: %s\n", transparency::techniqueName(kind),
                    transparency::techniqueName(frame.technique()), e.what());
        return false;
    }
}

void printCompare(const FrameRenderer& frame) {
    if (const auto right = frame.comparedTechnique())
        std::printf("racer: compare %s (left) | %s (right)\n", transparency::techniqueName(frame.technique()),
                    transparency::techniqueName(*right));
    else std::printf("racer: compare off\n");
}

// V: compare with `with` (or the next technique that runs here after it), or stop comparing.
void toggleCompare(FrameRenderer& frame, TechniqueKind with) {
    if (frame.comparedTechnique()) {
        frame.setCompare(std::nullopt);
        printCompare(frame);
        return;
    }
    const auto all = transparency::allTechniques();
    const int n = int(all.size());
    const int first = int(std::find(all.begin(), all.end(), with) - all.begin());
    for (int k = 0; k < n; ++k) {
        try {
            frame.setCompare(all[std::size_t((first + k) % n)]);
            printCompare(frame);
            return;
        } catch (const engine::Error& e) {
            std::printf("racer: cannot compare with %s: %s\n",
                        transparency::techniqueName(all[std::size_t((first + k) % n)]), e.what());
        }
    }
}

// B: the next compared technique that runs here (while comparing).
void stepCompared(FrameRenderer& frame) {
    const auto current = frame.comparedTechnique();
    if (!current) return;
    const auto all = transparency::allTechniques();
    const int n = int(all.size());
    const int at = int(std::find(all.begin(), all.end(), *current) - all.begin());
    for (int k = 1; k < n; ++k) {
        const TechniqueKind next = all[std::size_t((at + k) % n)];
        try {
            frame.setCompare(next);
            printCompare(frame);
            return;
        } catch (const engine::Error& e) {
            std::printf("racer: cannot compare with %s: %s\n", transparency::techniqueName(next), e.what());
        }
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

// Resizes the window as a user dragging its border would, and waits (at most
// kWindowSettleTime) for it to take the size, so the next frame sees it: a window manager may
// adjust or delay a resize (Xvfb has none and is immediate).
void resizeWindow(LoopWindow& window, int width, int height) {
    window.setSize(width, height);
    const Clock::time_point deadline = Clock::now() + kWindowSettleTime;
    for (;;) {
        window.pollEvents();
        int w = 0, h = 0;
        glfwGetWindowSize(window.window(), &w, &h);
        if ((w == width && h == height) || Clock::now() >= deadline) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

// A scripted minimise's restore: when, and to the window's size before it.
struct ScriptedRestore {
    Clock::time_point at;
    int width = 0, height = 0;
};

// A scripted window change, as a user would make it; a minimise returns its restore.
std::optional<ScriptedRestore> applyWindowChange(LoopWindow& window, const ScriptedWindowChange& change) {
    if (change.minimizeMs == 0) {
        resizeWindow(window, change.width, change.height);
        return std::nullopt;
    }
    ScriptedRestore restore{Clock::now() + std::chrono::milliseconds(change.minimizeMs)};
    glfwGetWindowSize(window.window(), &restore.width, &restore.height);
    window.setSize(0, 0);
    return restore;
}

// While the framebuffer is empty (minimised) nothing is rendered or shown: the loop blocks in
// glfwWaitEvents until something happens (the restore) instead of spinning. A scripted
// minimise restores the window itself when its time is up. Entering and leaving are printed,
// leaving with the number of wake-ups (a handful, where a spinning loop would count thousands).
class MinimisedWait {
public:
    void wait(LoopWindow& window, std::optional<ScriptedRestore>& restore) {
        if (!waiting_) {
            std::printf("racer: window minimised, not rendering\n");
            waiting_ = true;
            since_ = Clock::now();
            wakeUps_ = 0;
        }
        if (!restore) {
            glfwWaitEvents();
        } else if (const double left = std::chrono::duration<double>(restore->at - Clock::now()).count(); left > 0.0) {
            glfwWaitEventsTimeout(left);
        } else {
            resizeWindow(window, restore->width, restore->height);
            restore.reset();
            return;
        }
        ++wakeUps_;
    }

    // Called when the framebuffer has a size again: true when the window was minimised.
    bool ended() {
        if (!waiting_) return false;
        waiting_ = false;
        std::printf("racer: window restored after %.2f s minimised (woke %d times)\n",
                    std::chrono::duration<double>(Clock::now() - since_).count(), wakeUps_);
        return true;
    }

private:
    bool waiting_ = false;
    Clock::time_point since_;
    int wakeUps_ = 0;
};

}  // namespace

WindowLoopResult runWindowLoop(LoopWindow& window, engine::render::Backend& renderer, FrameRenderer& frame,
                               const FrameSource& source, const WindowLoopSettings& settings) {
    const WindowScript script = parseWindowScript(settings.script);
    std::size_t nextKey = 0, nextChange = 0;
    std::optional<ScriptedRestore> restore;
    std::map<int, bool> wasDown;
    CameraMode camera = settings.camera;
    PlayerInput input;  // the free camera starts at the overview a headless --camera free run renders
    MouseLook mouse(window.window());
    RenderSize size(frame);
    MinimisedWait minimised;
    bool paused = false, hudShown = settings.hud;
    HudFacts hud;  // the last title update's means
    double time = 0.0, totalMs = 0.0;
    TitleStats stats;
    Clock::time_point last = Clock::now(), titleShown = last;
    WindowLoopResult result;
    if (camera == CameraMode::Free) std::printf("racer: free camera: %s\n", flyKeysHelp());
    if (camera == CameraMode::Chase) std::printf("racer: drive: %s\n", driveKeysHelp());

    while (settings.frames == 0 || result.frames < settings.frames) {
        window.pollEvents();
        if (window.shouldClose()) break;
        for (; nextChange < script.changes.size() && script.changes[nextChange].frame <= result.frames; ++nextChange)
            restore = applyWindowChange(window, script.changes[nextChange]);
        const glm::ivec2 framebuffer = window.framebufferSize();
        if (framebuffer.x <= 0 || framebuffer.y <= 0) {
            minimised.wait(window, restore);
            continue;
        }
        if (minimised.ended()) last = Clock::now();  // the time away is no simulation step
        size.follow(framebuffer);

        // Keys pressed since the last frame (edges of the polled state), then scripted ones.
        std::vector<KeyAction> actions;
        const bool shift = glfwGetKey(window.window(), GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                           glfwGetKey(window.window(), GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
        for (int key : watchedKeys()) {
            const bool down = glfwGetKey(window.window(), key) == GLFW_PRESS;
            if (down && !wasDown[key]) actions.push_back(actionForKey(key, shift));
            wasDown[key] = down;
        }
        for (; nextKey < script.keys.size() && script.keys[nextKey].frame <= result.frames; ++nextKey)
            actions.push_back(actionForKey(script.keys[nextKey].key, script.keys[nextKey].shift));
        bool quit = false;
        input.autopilot = false;
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
                    frame.cutHistory();  // a temporal technique must not blend the old view in
                    std::printf("racer: camera %s\n", cameraName(camera));
                    if (camera == CameraMode::Free) std::printf("racer: free camera: %s\n", flyKeysHelp());
                    if (camera == CameraMode::Chase) std::printf("racer: drive: %s\n", driveKeysHelp());
                    break;
                case WindowAction::ToggleHud:
                    hudShown = !hudShown;
                    std::printf("racer: HUD %s\n", hudShown ? "on" : "off");
                    break;
                case WindowAction::ToggleCompare: toggleCompare(frame, settings.compareWith); break;
                case WindowAction::NextCompared: stepCompared(frame); break;
                case WindowAction::Autopilot:
                    input.autopilot = true;
                    std::printf("racer: autopilot\n");
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
        // looked around); the chase camera's keys drive the car. Each camera's keys do
        // nothing with the others.
        const auto held = [&](int key) {
            return glfwGetKey(window.window(), key) == GLFW_PRESS || scriptHolds(script.keys, result.frames, key);
        };
        const glm::vec2 look = mouse.motion(camera == CameraMode::Free);
        if (camera == CameraMode::Free) {
            FlyControls controls = flyControls(held);
            controls.look = look;
            input.free = flyStep(input.free, controls, float(step));
        }
        input.drive = camera == CameraMode::Chase ? driveControls(held) : HeldDriveKeys{};
        // As the headless loop: frame i steps the world by dt and sees the camera at i * dt,
        // so a window with --fixed-dt shows the frames a headless run captures.
        const FrameSize rendering = size.current();
        const SceneFrame scene =
            source(float(time), float(dt), camera, input, float(rendering.width) / float(rendering.height));
        time += dt;
        if (hudShown) {
            hud.technique = transparency::techniqueName(frame.technique());
            hud.backend = renderer.name();
            hud.width = rendering.width;
            hud.height = rendering.height;
            hud.extra = std::string("camera ") + cameraName(camera) + (paused ? " (paused)" : "");
            if (const auto right = frame.comparedTechnique())
                hud.extra += "; " + compareHudLine(hud.technique, transparency::techniqueName(*right));
            hud.transientBytes = result.frames > 0 ? std::int64_t(frame.peakTransientBytes()) : -1;
            hud.levelsOfDetail = lodCountsLine(scene.lists);
            frame.setHud(hudLines(hud));
        } else {
            frame.setHud({});
        }
        try {
            frame.render(scene.lists, scene.camera);
        } catch (const engine::Error& e) {
            if (!size.recover(e)) throw;
            renderer.takeTimings();  // this frame is dropped; the next one renders at the size that works
            continue;
        }
        size.rendered();
        window.show(frame.color());
        // The frame ends when its pass times are in (takeTimings waits for the queue on GL and
        // Vulkan), so the frame time bounds their sum.
        const std::vector<engine::render::PassTiming> timings = renderer.takeTimings();
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        totalMs += ms;
        ++result.frames;
        stats.add(ms, timings);
        if (std::chrono::duration<double>(Clock::now() - titleShown).count() >= kTitleInterval) {
            glfwSetWindowTitle(window.window(), stats.title(frame.technique(), camera, paused, size.current()).c_str());
            hud = stats.hudFacts();
            stats = {};
            titleShown = Clock::now();
        }
    }
    if (camera == CameraMode::Free) printPose(input.free);
    result.meanFrameMs = totalMs / std::max(1, result.frames);
    return result;
}

}  // namespace racer
