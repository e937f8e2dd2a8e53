// SPDX-License-Identifier: MIT
// racer: the project's main job. Renders the racing scene (or a --scene glTF file) with a
// chosen foliage technique, in a GLFW window (when there is a display and no --headless) or
// headless, and writes captures. Flags: racer_options.cpp; the window: window_loop.cpp.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>

#include "camera_rig.hpp"
#include "engine/capture/readback_image.hpp"
#include "engine/cli/command_line.hpp"
#include "engine/core/usage_error.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/vk/vk_backend.hpp"
#include "engine/render/vk/vk_window.hpp"
#include "engine/render/devices/create_device.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/rigid_motion.hpp"
#include "frame_renderer.hpp"
#include "frame_source.hpp"
#include "gltf_scene.hpp"
#include "hud_text.hpp"
#include "plant_levels.hpp"
#include "living_scene.hpp"
#include "racer_options.hpp"
#include "racer_outputs.hpp"
#include "racing_scene.hpp"
#include "simd_flag.hpp"
#include "ssam/core/settings.hpp"
#include "window_keys.hpp"
#include "window_loop.hpp"

namespace {

using namespace racer;
namespace gl = engine::render::gl;
namespace vk = engine::render::vk;

std::string passTimings(const std::vector<engine::render::PassTiming>& timings) {
    std::string passes;
    for (const auto& t : timings) {
        char buf[96];
        if (t.skipped) std::snprintf(buf, sizeof buf, " %s skipped", t.pass.c_str());
        else std::snprintf(buf, sizeof buf, " %s %.1f", t.pass.c_str(), t.milliseconds);
        passes += buf;
    }
    return passes;
}

// Offscreen: `frames` frames at the fixed step, a progress line with per-pass times every 10.
void runHeadless(const Options& o, engine::render::Backend& backend, FrameRenderer& frame, const FrameSource& source,
                 CameraMode camera, float aspect) {
    double totalMs = 0.0, lastMs = -1.0, updateMs = 0.0;
    std::vector<engine::render::PassTiming> lastTimings;
    SceneFrame last;
    for (int i = 0; i < o.frames; ++i) {
        // The HUD shows the frame before (a frame cannot time itself before it is drawn).
        if (o.hud) {
            const std::string technique = transparency::techniqueName(frame.technique());
            const auto right = frame.comparedTechnique();
            frame.setHud(
                hudLines({technique, backend.name(), frame.width(), frame.height(), "previous frame", lastMs,
                          lastTimings, right ? compareHudLine(technique, transparency::techniqueName(*right)) : "",
                          i > 0 ? std::int64_t(frame.peakTransientBytes()) : -1,
                          i > 0 ? lodCountsLine(last.lists) + " (previous frame)" : ""}));
        }
        const auto start = std::chrono::steady_clock::now();
        last = source(float(i * o.fixedDt), float(o.fixedDt), camera, PlayerInput{}, aspect);
        updateMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        frame.render(last.lists, last.camera);
        // The pass times come with the frame's results (takeTimings waits for them on GL and
        // Vulkan, whose queues run after render() returns): the frame ends there, so its time
        // bounds the passes' sum.
        lastTimings = backend.takeTimings();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        totalMs += ms;
        lastMs = ms;
        const std::string passes = passTimings(lastTimings);
        if (i == 0 || (i + 1) % 10 == 0 || i + 1 == o.frames)
            std::printf("frame %d/%d  %.1f ms  (ms:%s)\n", i + 1, o.frames, ms, passes.c_str());
    }
    std::printf("racer: mean frame %.1f ms\n", totalMs / std::max(1, o.frames));
    // The scene's update: the simulation, the levels of detail, the living scene's systems (the
    // wind's deformation) and extraction, before the frame graph.
    std::printf("racer: mean scene update %.2f ms (%.1f%% of the frame)\n", updateMs / std::max(1, o.frames),
                totalMs > 0.0 ? 100.0 * updateMs / totalMs : 0.0);
    std::printf("racer: last frame draws %zu opaque, %zu foliage, %zu blend batches\n", last.lists.opaque.size(),
                last.lists.mask.size(), last.lists.blend.size());
}

int run(const CLI::App& app, const Options& o) {
    // Everything the command line can get wrong is refused before any work (exit 2), and
    // every output is proven writable before the first frame (exit 1): a bad path fails at
    // once, not after a 1000-frame run (game/README.md "Command-line contract").
    checkCombinations(app, o);
    const FrameSize size = parseFrameSize(o.size);
    if (!o.script.empty()) parseWindowScript(o.script);
    if (o.scenePath.empty() && !std::filesystem::is_directory(o.contentDir))
        throw engine::Error("--content '" + o.contentDir + "': no such directory");
    const OutputPlan outputs = planOutputs(o);

    RendererOptions renderer;
    renderer.width = size.width;
    renderer.height = size.height;
    renderer.technique = parseTechniqueName(o.technique);
    std::optional<transparency::TechniqueKind> comparedWith;
    if (!o.compare.empty()) {
        const ComparedPair pair = parseCompare(o.compare);
        renderer.technique = pair.left;
        comparedWith = pair.right;
    }
    renderer.msaa = o.msaa;
    renderer.msaaDepth = o.msaaDepth == "any" ? engine::render::DepthResolve::AnySample
                                              : engine::render::DepthResolve::Closest;        // checked by CLI11
    renderer.techniqueOptions.ssam = ssam::presetSettings(*ssam::parsePreset(o.ssamPreset));  // checked by CLI11
    renderer.techniqueOptions.ssam.depthMaskThreshold = o.ssamDepthThreshold;
    renderer.captureLayers = o.captureLayers;
    const CameraMode cameraMode = parseCamera(o.camera);
    const float aspect = float(renderer.width) / float(renderer.height);

    // A window needs a display and no --headless. The window's GL context presents; the
    // frames are drawn by GL (auto, gl) or by the soft backend and uploaded (soft). With
    // --backend vk the window has no GL context (GLFW_NO_API) and the Vulkan backend presents
    // to it through a swapchain. A display or Vulkan surface that cannot be had is reported
    // and rendered headless, as without a display.
    auto displaySet = [](const char* name) { return std::getenv(name) && *std::getenv(name); };
    const bool wantWindow = !o.headless && (displaySet("DISPLAY") || displaySet("WAYLAND_DISPLAY"));
    using engine::render::DeviceKind;
    const std::optional<DeviceKind> requested = engine::render::parseDeviceKind(o.backend);  // nullopt: auto
    engine::render::DeviceOptions options;
    options.soft = {.threads = o.threads, .tileSize = 64, .simd = racer::simdFromFlag(o.simd)};
    options.vulkan.device = o.device;
    // SSAM_VK_VALIDATION=1: under the validation layer (the vk tests): every message is
    // printed, and any makes the run fail at its end.
    options.vulkan.validation = std::getenv("SSAM_VK_VALIDATION") != nullptr;
    std::shared_ptr<gl::GlfwWindowContext> window;
    if (wantWindow && requested != DeviceKind::Vulkan) {
        gl::GlfwWindowOptions wo;
        wo.title = "racer";
        wo.width = renderer.width;
        wo.height = renderer.height;
        wo.vsync = false;  // the title's fps and pass times are the renderer's, not the display's
        try {
            window = gl::GlfwWindowContext::create(wo);
        } catch (const engine::Error& e) {
            std::printf("racer: no window (%s); rendering headless\n", e.what());
        }
    }
    std::shared_ptr<vk::VulkanWindow> vkWindow;
    std::unique_ptr<engine::render::Device> device;
    if (requested == DeviceKind::Vulkan && wantWindow) {
        try {
            options.vulkan.window = vk::VulkanWindow::create({"racer", renderer.width, renderer.height});
            device = engine::render::createDevice(DeviceKind::Vulkan, options);
            vkWindow = options.vulkan.window;
        } catch (const engine::Error& e) {
            std::printf("racer: no window (%s); rendering headless\n", e.what());
            options.vulkan.window.reset();
        }
    }
    const bool windowed = window != nullptr || vkWindow != nullptr;
    const DeviceKind kind = requested ? *requested : windowed ? DeviceKind::Gl : DeviceKind::Soft;
    // A GL window presents: through the GL device that draws the frames, or through one of its
    // own when another device draws them (soft frames are uploaded to it).
    options.gl.context = window;
    if (!device) device = engine::render::createDevice(kind, options);
    std::unique_ptr<engine::render::Device> presenter;
    if (window && kind != DeviceKind::Gl) presenter = engine::render::createDevice(DeviceKind::Gl, options);
    engine::render::Device& backend = *device;

    // --scene FILE: the file's scene and camera replace the racing scene (gltf_scene.hpp).
    std::unique_ptr<RacingScene> racing;
    std::unique_ptr<GltfScene> gltf;
    if (!o.scenePath.empty()) {
        gltf = std::make_unique<GltfScene>(backend, GltfSceneOptions{o.scenePath, o.sceneIndex, o.cameraIndex});
        renderer.background = kNeutralBackground;
    } else {
        racing = std::make_unique<RacingScene>(backend, SceneOptions{o.contentDir, o.seed, {}, o.lod == "on"});
        renderer.sun = racing->sun();
    }
    engine::ecs::Registry& registry = gltf ? gltf->registry() : racing->registry();
    engine::scene::MeshLibrary& library = gltf ? gltf->library() : racing->library();
    FrameRenderer frame(backend, library, renderer);
    frame.setCompare(comparedWith);
    // The living scene (wind, water, ...; living_scene.hpp) on the racing scene.
    std::unique_ptr<LivingScene> living;
    if (racing) {
        LivingSceneOptions lo;
        lo.enabled = enabledModules(o);
        lo.seed = o.seed;
        lo.track = &racing->track();
        living = std::make_unique<LivingScene>(registry, library, lo);
        frame.setLivingScene(living.get());
    }
    engine::scene::RigidMotion rigidMotion(library);
    const FrameSource source = [&](float time, float dt, CameraMode camera, const PlayerInput& input,
                                   float frameAspect) {
        if (racing) {
            if (input.autopilot) racing->engageAutopilot();
            // The first drive key takes the wheel; once driven, released keys coast.
            if (input.drive.any || racing->registry().get<Car>(racing->car()).driven)
                racing->takeWheel(input.drive.controls);
            racing->update(dt);
        }
        const CameraView view =
            gltf ? gltf->camera(frameAspect).view : cameraView(camera, *racing, time, frameAspect, input.free);
        // The frame's culling picks each plant's level of detail first: the wind eases plants
        // to rest before they leave the full model (--lod off: every plant stays full).
        if (o.lod == "on")
            engine::scene::selectLevelsOfDetail(
                registry, library,
                {view.eye, engine::scene::focalPixels(view.projection, frame.height()), 0.1f, kLodCrossfade});
        if (living) living->update(time, dt, view, frame.needsMotionVectors());  // wind etc., before extraction
        rigidMotion.update(registry, frame.needsMotionVectors());                // the car's motion copies
        return SceneFrame{view, engine::scene::extractDrawLists(registry, library, view.viewProj, view.eye)};
    };

    std::printf("racer: %s, %dx%d, camera %s, backend %s, %s\n", transparency::techniqueName(renderer.technique),
                renderer.width, renderer.height, o.camera.c_str(), backend.driver().describe().c_str(),
                windowed ? "window" : "headless");
    if (living) {
        std::string names;
        for (const std::string& n : living->names()) names += " " + n;
        for (const std::string& n : living->missing()) names += " (" + n + ": not built)";
        std::printf("racer: living scene:%s\n", names.empty() ? " off" : names.c_str());
    }
    if (comparedWith)
        std::printf("racer: compare %s (left) | %s (right)\n", transparency::techniqueName(frame.technique()),
                    transparency::techniqueName(*comparedWith));
    if (gltf)
        std::printf("racer: scene %s (scene %d), camera %s\n", o.scenePath.c_str(), gltf->model().scene,
                    gltf->camera(aspect).description.c_str());
    if (windowed) {
        WindowLoopSettings ws;
        ws.frames = o.framesGiven ? o.frames : 0;
        ws.fixedDt = o.fixedDtGiven ? o.fixedDt : 0.0;
        ws.camera = cameraMode;
        ws.script = o.script;
        ws.hud = o.hud;
        if (comparedWith) ws.compareWith = *comparedWith;
        std::printf(
            "racer: keys 1-8 technique, T / Shift+T next / previous, C camera, P pause, H HUD, V compare, B compared technique, R autopilot, Esc quit\n");
        const std::unique_ptr<LoopWindow> shown =
            vkWindow ? vkLoopWindow(*vkWindow, backend)
                     : glLoopWindow(*window, presenter ? *presenter : backend, backend);
        const WindowLoopResult r = runWindowLoop(*shown, backend, frame, source, ws);
        std::printf("racer: %d frames, mean frame %.1f ms, last at %dx%d\n", r.frames, r.meanFrameMs, frame.width(),
                    frame.height());
        if (vkWindow)
            std::printf(
                "racer: Vulkan presented %llu frames, %llu swapchains made\n",
                static_cast<unsigned long long>(backend.driverAs<vk::VulkanDriver>().counters().framesPresented),
                static_cast<unsigned long long>(backend.driverAs<vk::VulkanDriver>().counters().swapchainsCreated));
    } else {
        if (!o.script.empty()) throw engine::UsageError("--script needs a window (a display and no --headless)");
        std::printf("racer: %d frames at dt %.4f s\n", o.frames, o.fixedDt);
        runHeadless(o, backend, frame, source, cameraMode, aspect);
    }

    if (racing) {
        const Car& car = racing->registry().get<Car>(racing->car());
        std::printf("racer: car at (%.2f, %.2f, %.2f), heading %.1f deg, speed %.2f m/s, %s\n", car.position.x,
                    car.position.y, car.position.z, glm::degrees(std::atan2(car.forward.x, car.forward.z)),
                    car.driven ? car.motion.speed : car.speed,
                    car.driven ? "driven by the player" : "on the autopilot");
    }

    if (frame.comparedTechnique()) {
        const hud::PixelRect crop = frame.compareCrop();
        std::printf("racer: compare insets: the %dx%d crop at (%d, %d), where the two differ most\n", crop.width,
                    crop.height, crop.x, crop.y);
    }

    const SceneCamera planes = gltf ? gltf->camera(float(frame.width()) / float(frame.height())) : SceneCamera{};
    // <technique>_<layer>.png, e.g. ssam_mask_max.png (the README's), alpha_test_result.png.
    std::string prefix = std::string(transparency::techniqueName(frame.technique())) + "_";
    std::replace(prefix.begin(), prefix.end(), '-', '_');
    if (!outputs.empty()) {
        FrameOutputs out;
        engine::capture::Image color;
        if (!outputs.capture.empty()) {
            color = engine::capture::imageFromReadback(backend.readback(frame.color()));
            out.color = &color;
        }
        out.layers = frame.layers();
        if (!outputs.graph.empty()) {
            std::ostringstream dot;
            frame.dumpGraph(dot);
            out.graphDot = dot.str();
        }
        writeOutputs(outputs, out, prefix, planes.nearPlane, planes.farPlane);
        if (!outputs.graph.empty())
            std::printf("racer: the last frame's transient targets peak at %llu bytes (lifetimes: %s)\n",
                        static_cast<unsigned long long>(frame.peakTransientBytes()), outputs.graph.string().c_str());
    }
    if (kind == DeviceKind::Vulkan && backend.driverAs<vk::VulkanDriver>().validationMessages() > 0)
        throw engine::Error("racer: " + std::to_string(backend.driverAs<vk::VulkanDriver>().validationMessages()) +
                            " Vulkan validation messages (above)");
    return 0;
}

}  // namespace

// Only declaring the options runs outside runTool's handler: an exception there is a bug of the
// tool itself (a flag declared twice), which the tool's --help test finds first.
int main(int argc, char** argv) {  // NOLINT(bugprone-exception-escape)
    CLI::App app{"racer: the SSAM racing-scene demo ([Hathaway 2010], Pure)"};
    Options o;
    addOptions(app, o);
    return engine::cli::runTool("racer", app, argc, argv, [&] { return run(app, o); });
}
