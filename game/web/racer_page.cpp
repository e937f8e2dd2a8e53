// SPDX-License-Identifier: MIT
// The racer as a web page (make web): the racing scene, its cameras and living scene, drawn
// by the GLES driver into the page's WebGL2 canvas, one frame per browser animation frame
// (emscripten_set_main_loop: a page must not block). The same racer sources as the native demo;
// what the page adds is its context, its keys (DOM events read as the GLFW codes window_keys.hpp
// maps) and the calls index.html makes: the technique switch, the side-by-side compare, the HUD,
// and for the browser test (tests/web) a fixed frame count, time step and size from the query
// string and the last frame's pixels. Frame times are the browser clock's (WebGL2 has no timer
// query in this driver; the HUD says so through the driver's CPU pass times).
#include <GLFW/glfw3.h>  // key codes only: window_keys.hpp speaks GLFW's
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "camera_rig.hpp"
#include "engine/core/error.hpp"
#include "engine/render/gl/gl_context.hpp"
#include "engine/render/gles/gles_backend.hpp"
#include "engine/scene/levels_of_detail.hpp"
#include "frame_renderer.hpp"
#include "hud_text.hpp"
#include "living_scene.hpp"
#include "plant_levels.hpp"
#include "racing_scene.hpp"
#include "transparency/technique.hpp"
#include "window_keys.hpp"

namespace {

using transparency::TechniqueKind;
namespace gl = engine::render::gl;

// The canvas's WebGL2 context, made by the page (there is no EGL in a browser) and handed to the
// GLES driver. preserveDrawingBuffer keeps the shown frame readable after the browser composited
// it (the browser test reads the canvas); no antialiasing, depth or alpha of its own: the engine
// renders into its own targets and presents into this one.
class CanvasContext final : public gl::GlContext {
public:
    CanvasContext() {
        EmscriptenWebGLContextAttributes attributes;
        emscripten_webgl_init_context_attributes(&attributes);
        attributes.majorVersion = 2;
        attributes.minorVersion = 0;
        attributes.alpha = false;
        attributes.depth = false;
        attributes.stencil = false;
        attributes.antialias = false;
        attributes.preserveDrawingBuffer = true;
        context_ = emscripten_webgl_create_context("#canvas", &attributes);
        if (context_ <= 0) throw engine::Error("racer page: this browser gives the canvas no WebGL2 context");
        makeCurrent();
    }
    void makeCurrent() override { emscripten_webgl_make_context_current(context_); }
    std::string describe() const override { return "WebGL2 canvas"; }
    bool hasWindow() const override { return true; }
    glm::ivec2 framebufferSize() const override {
        int width = 0, height = 0;
        emscripten_webgl_get_drawing_buffer_size(context_, &width, &height);
        return {width, height};
    }
    // The browser shows the canvas when the animation frame returns: nothing to swap.

private:
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context_ = 0;
};

// The DOM's legacy key codes as GLFW's: letters, digits and space are the same ASCII codes.
int glfwKeyOf(unsigned long dom) {
    switch (dom) {
        case 37: return GLFW_KEY_LEFT;
        case 38: return GLFW_KEY_UP;
        case 39: return GLFW_KEY_RIGHT;
        case 40: return GLFW_KEY_DOWN;
        case 16: return GLFW_KEY_LEFT_SHIFT;
        case 17: return GLFW_KEY_LEFT_CONTROL;
        case 27: return GLFW_KEY_ESCAPE;
        default: return int(dom);
    }
}

struct PageSettings {
    int width = 960, height = 540;
    TechniqueKind technique = TechniqueKind::Ssam;
    int frames = 0;        // 0: run until the page closes
    double fixedDt = 0.0;  // 0: the browser clock's step
    bool hud = true;
    racer::CameraMode camera = racer::CameraMode::Chase;
    // A2C's 4x depth keeps any one sample: WebGL2 (ES 3.0) cannot read the samples for the
    // closest (engine/render/docs/gles.md); msaa-depth=closest asks anyway, and a2c is refused.
    engine::render::DepthResolve msaaDepth = engine::render::DepthResolve::AnySample;
};

std::optional<TechniqueKind> techniqueNamed(const std::string& name) {
    for (const TechniqueKind kind : transparency::allTechniques())
        if (name == transparency::techniqueName(kind)) return kind;
    return std::nullopt;
}

// The page's arguments (index.html passes the query string's as --name value pairs).
PageSettings parseSettings(int argc, char** argv) {
    PageSettings s;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string name = argv[i], value = argv[i + 1];
        if (name == "--technique") {
            const auto kind = techniqueNamed(value);
            if (!kind) throw engine::Error("racer page: technique '" + value + "' is not one of the racer's");
            s.technique = *kind;
        } else if (name == "--frames") {
            s.frames = std::atoi(value.c_str());
        } else if (name == "--fixed-dt") {
            s.fixedDt = std::atof(value.c_str());
        } else if (name == "--size") {
            if (std::sscanf(value.c_str(), "%dx%d", &s.width, &s.height) != 2 || s.width < 16 || s.height < 16 ||
                s.width > 4096 || s.height > 4096)
                throw engine::Error("racer page: size '" + value + "' is not WIDTHxHEIGHT within 16..4096");
        } else if (name == "--hud") {
            s.hud = value != "0";
        } else if (name == "--camera") {
            s.camera = racer::parseCamera(value);
        } else if (name == "--msaa-depth") {
            if (value != "closest" && value != "any")
                throw engine::Error("racer page: msaa-depth '" + value + "' is not closest or any");
            s.msaaDepth =
                value == "any" ? engine::render::DepthResolve::AnySample : engine::render::DepthResolve::Closest;
        } else {
            throw engine::Error("racer page: unknown argument '" + name + "'");
        }
    }
    return s;
}

// What the page's script (index.html) is told: the page is ready, the fixed frames are done, or
// the page failed (the message is shown, and the browser test fails on it).
// clang-format off
EM_JS(void, notifyReady, (), { Module.pageReady(); });
EM_JS(void, notifyFramesDone, (), { Module.pageFramesDone(); });
EM_JS(void, notifyFailed, (const char* message), { Module.pageFailed(UTF8ToString(message)); });
EM_JS(void, notifyRefused, (const char* technique, const char* why), {
    Module.techniqueRefused(UTF8ToString(technique), UTF8ToString(why));
});
// clang-format on

class Page {
public:
    explicit Page(const PageSettings& settings)
        : settings_(settings), context_(std::make_shared<CanvasContext>()),
          device_(engine::render::gles::createGlesBackend({.context = context_})),
          racing_(*device_, racer::SceneOptions{"/content", 1, {}, true}),
          frame_(*device_, racing_.library(), rendererOptions(settings, racing_)),
          living_(racing_.registry(), racing_.library(), livingOptions(racing_)), hudShown_(settings.hud),
          camera_(settings.camera) {
        frame_.setLivingScene(&living_);
        std::printf("racer page: %s, %dx%d, %s\n", transparency::techniqueName(frame_.technique()), settings.width,
                    settings.height, device_->driver().describe().c_str());
    }

    void keyDown(int key) {
        const bool shift = held_.count(GLFW_KEY_LEFT_SHIFT) != 0;
        held_.insert(key);
        const racer::KeyAction a = racer::actionForKey(key, shift);
        switch (a.action) {
            case racer::WindowAction::SelectTechnique:
                setTechnique(transparency::allTechniques()[std::size_t(a.technique)]);
                break;
            case racer::WindowAction::ToggleHud: hudShown_ = !hudShown_; break;
            case racer::WindowAction::ToggleCompare: toggleCompare(); break;
            case racer::WindowAction::TogglePause: paused_ = !paused_; break;
            case racer::WindowAction::Autopilot: autopilot_ = true; break;
            case racer::WindowAction::NextCamera: camera_ = racer::nextCamera(camera_); break;
            default: break;  // quitting and the free camera's flight are the native window's
        }
    }
    void keyUp(int key) { held_.erase(key); }

    // Empty when the technique now draws, else why the GLES driver refuses it (the current one kept).
    std::string setTechnique(TechniqueKind kind) {
        try {
            const TechniqueKind before = frame_.technique();
            frame_.setTechnique(kind);
            frame_.cutHistory();
            fallback_ = before;  // until it has drawn a frame: some refusals come at the first draw
            return {};
        } catch (const engine::Error& e) {
            return e.what();
        }
    }
    std::string toggleCompare() {
        if (frame_.comparedTechnique()) {
            frame_.setCompare(std::nullopt);
            return {};
        }
        // SSAM against the baseline it replaces, or against SSAM when SSAM is on the left.
        const TechniqueKind right =
            frame_.technique() == TechniqueKind::AlphaTest ? TechniqueKind::Ssam : TechniqueKind::AlphaTest;
        try {
            frame_.setCompare(right);
            return {};
        } catch (const engine::Error& e) {
            return e.what();
        }
    }

    // One animation frame: the world steps by the fixed step or the browser clock's (at most
    // 0.1 s: a tab in the background never jumps the car far), then the frame is drawn and shown.
    bool step() {
        const double now = emscripten_get_now();
        const double wall = last_ < 0.0 ? 0.0 : (now - last_) / 1000.0;
        last_ = now;
        const double dt = paused_ ? 0.0 : settings_.fixedDt > 0.0 ? settings_.fixedDt : std::min(wall, 0.1);
        const racer::HeldDriveKeys drive = racer::driveControls([&](int key) { return held_.count(key) != 0; });
        if (autopilot_) racing_.engageAutopilot();
        autopilot_ = false;
        if (drive.any || racing_.registry().get<racer::Car>(racing_.car()).driven) racing_.takeWheel(drive.controls);
        racing_.update(float(dt));
        const float aspect = float(settings_.width) / float(settings_.height);
        const racer::CameraView view = racer::cameraView(camera_, racing_, float(time_), aspect, racer::FreeCamera{});
        engine::scene::selectLevelsOfDetail(
            racing_.registry(), racing_.library(),
            {view.eye, engine::scene::focalPixels(view.projection, frame_.height()), 0.1f, racer::kLodCrossfade});
        living_.update(float(time_), float(dt), view);
        time_ += dt;
        const engine::scene::DrawLists lists =
            engine::scene::extractDrawLists(racing_.registry(), racing_.library(), view.viewProj, view.eye);
        frame_.setHud(hudShown_ ? hudLines(lists) : std::vector<std::string>{});
        try {
            frame_.render(lists, view);
        } catch (const engine::Error& e) {
            // A technique just chosen that the GLES driver refuses only when it draws (a2c's
            // closest-sample depth resolve under msaa-depth=closest): the switch is undone and
            // the page says why.
            if (!fallback_) throw;
            const TechniqueKind refused = frame_.technique();
            frame_.setTechnique(*std::exchange(fallback_, std::nullopt));
            device_->takeTimings();
            notifyRefused(transparency::techniqueName(refused), e.what());
            return true;
        }
        fallback_.reset();
        device_->present(frame_.color());
        lastPasses_ = device_->takeTimings();
        lastMs_ = emscripten_get_now() - now;
        ++frames_;
        return settings_.frames == 0 || frames_ < settings_.frames;
    }

    // The last frame as RGBA8 rows from the top (the engine's stored sRGB codes), for the test.
    const std::vector<unsigned char>& readFrame() {
        const engine::render::Readback r = device_->readback(frame_.color());
        pixels_.resize(std::size_t(r.width) * std::size_t(r.height) * 4);
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x)
                for (int c = 0; c < 4; ++c)
                    pixels_[(std::size_t(y) * std::size_t(r.width) + std::size_t(x)) * 4 + std::size_t(c)] =
                        c < r.channels ? (unsigned char)(r.at(x, y, c) * 255.0f + 0.5f) : 255;
        return pixels_;
    }
    int frames() const { return frames_; }
    double lastMs() const { return lastMs_; }
    TechniqueKind technique() const { return frame_.technique(); }

private:
    static racer::RendererOptions rendererOptions(const PageSettings& s, racer::RacingScene& racing) {
        racer::RendererOptions o;
        o.width = s.width;
        o.height = s.height;
        o.technique = s.technique;
        o.msaaDepth = s.msaaDepth;
        o.sun = racing.sun();
        return o;
    }
    static racer::LivingSceneOptions livingOptions(racer::RacingScene& racing) {
        racer::LivingSceneOptions o;
        o.track = &racing.track();
        return o;
    }
    std::vector<std::string> hudLines(const engine::scene::DrawLists& lists) const {
        racer::HudFacts f;
        f.technique = transparency::techniqueName(frame_.technique());
        f.backend = device_->name() + " (WebGL2)";
        f.width = settings_.width;
        f.height = settings_.height;
        f.timeSpan = "previous frame, browser clock";
        f.frameMs = frames_ > 0 ? lastMs_ : -1.0;
        f.passes = lastPasses_;
        if (const auto right = frame_.comparedTechnique())
            f.extra = racer::compareHudLine(f.technique, transparency::techniqueName(*right));
        f.levelsOfDetail = racer::lodCountsLine(lists);
        return racer::hudLines(f);
    }

    PageSettings settings_;
    std::shared_ptr<CanvasContext> context_;
    std::unique_ptr<engine::render::Device> device_;
    racer::RacingScene racing_;
    racer::FrameRenderer frame_;
    racer::LivingScene living_;
    std::set<int> held_;
    std::optional<TechniqueKind> fallback_;  // the technique before a switch that has not drawn yet
    bool hudShown_ = true, paused_ = false, autopilot_ = false;
    racer::CameraMode camera_ = racer::CameraMode::Chase;  // C cycles chase, pan, free (the free camera at its start)
    double time_ = 0.0, last_ = -1.0, lastMs_ = -1.0;
    int frames_ = 0;
    std::vector<engine::render::PassTiming> lastPasses_;
    std::vector<unsigned char> pixels_;
};

std::unique_ptr<Page> page;
std::string lastMessage;  // what the last call from index.html has to say (empty: done)

void reportError(const char* what) {
    std::fprintf(stderr, "racer page: error: %s\n", what);
    notifyFailed(what);
}

void animationFrame() {
    try {
        if (!page->step()) {
            emscripten_cancel_main_loop();
            notifyFramesDone();
        }
    } catch (const engine::Error& e) {
        emscripten_cancel_main_loop();
        reportError(e.what());
    }
}

EM_BOOL onKey(int type, const EmscriptenKeyboardEvent* event, void*) {
    if (!page) return EM_FALSE;
    const int key = glfwKeyOf(event->keyCode);
    if (type == EMSCRIPTEN_EVENT_KEYDOWN && !event->repeat) page->keyDown(key);
    if (type == EMSCRIPTEN_EVENT_KEYUP) page->keyUp(key);
    return key == GLFW_KEY_UP || key == GLFW_KEY_DOWN || key == ' ';  // the page does not scroll
}

}  // namespace

// The calls index.html makes (exported by name; each returns its message, empty when it worked).
extern "C" {
EMSCRIPTEN_KEEPALIVE const char* racer_page_set_technique(const char* name) {
    const auto kind = techniqueNamed(name);
    lastMessage = !kind ? std::string("unknown technique ") + name : page->setTechnique(*kind);
    return lastMessage.c_str();
}
EMSCRIPTEN_KEEPALIVE const char* racer_page_toggle_compare() {
    lastMessage = page->toggleCompare();
    return lastMessage.c_str();
}
EMSCRIPTEN_KEEPALIVE const char* racer_page_technique() { return transparency::techniqueName(page->technique()); }
EMSCRIPTEN_KEEPALIVE double racer_page_frame_ms() { return page->lastMs(); }
EMSCRIPTEN_KEEPALIVE int racer_page_frames() { return page ? page->frames() : 0; }
EMSCRIPTEN_KEEPALIVE const unsigned char* racer_page_read_frame() { return page->readFrame().data(); }
}

int main(int argc, char** argv) {
    try {
        const PageSettings settings = parseSettings(argc, argv);
        emscripten_set_canvas_element_size("#canvas", settings.width, settings.height);
        page = std::make_unique<Page>(settings);
        emscripten_set_keydown_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, true, onKey);
        emscripten_set_keyup_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, true, onKey);
        notifyReady();
        emscripten_set_main_loop(animationFrame, 0, false);
    } catch (const engine::Error& e) {
        reportError(e.what());
        return 1;
    }
    return 0;
}
