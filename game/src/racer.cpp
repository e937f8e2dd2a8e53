// racer: the project's main job. Renders the racing scene with a chosen technique, in a
// window (GL backend) or headless (soft backend by default), and writes captures.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>

#include "camera_rig.hpp"
#include "engine/capture/image_write.hpp"
#include "engine/capture/readback_image.hpp"
#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/draw_lists.hpp"
#include "frame_renderer.hpp"
#include "layer_pictures.hpp"
#include "racing_scene.hpp"

namespace {

using namespace racer;

struct Options {
    std::string backend = "soft";
    std::string technique = "ssam";
    std::string size = "1280x720";
    int frames = 60;
    double fixedDt = 1.0 / 30.0;
    std::string camera = "chase";
    std::uint32_t seed = 1;
    int threads = 0;
    std::string capturePath;
    bool captureLayers = false;
    bool headless = false;
    std::string contentDir = SSAM_CONTENT_DIR;
    int msaa = 1;
    std::string layerPictures;
};

int run(const Options& o) {
    const std::map<std::string, Technique> techniques{{"ssam", Technique::Ssam}, {"alpha-test", Technique::AlphaTest}};
    const std::map<std::string, CameraMode> cameras{
        {"chase", CameraMode::Chase}, {"pan", CameraMode::Pan}, {"free", CameraMode::Free}};

    std::smatch m;
    static const std::regex sizePattern(R"((\d{1,5})x(\d{1,5}))");
    if (!std::regex_match(o.size, m, sizePattern))
        throw engine::Error("--size '" + o.size + "': expected WIDTHxHEIGHT, e.g. 1280x720");
    RendererOptions renderer;
    renderer.width = std::stoi(m[1]);
    renderer.height = std::stoi(m[2]);
    if (renderer.width < 1 || renderer.height < 1 || renderer.width > 16384 || renderer.height > 16384)
        throw engine::Error("--size '" + o.size + "': each dimension must be in 1..16384");
    renderer.technique = techniques.at(o.technique);
    renderer.opaqueSamples = o.msaa;
    renderer.captureLayers = o.captureLayers;
    const CameraMode cameraMode = cameras.at(o.camera);

    const bool windowed = !o.headless && std::getenv("DISPLAY") != nullptr;
    if (windowed) engine::log::info("racer: the window mode is not built yet; rendering headless");

    // GL renders headless through EGL (Mesa llvmpipe without a GPU); --threads applies to soft.
    std::unique_ptr<engine::render::Backend> backend;
    if (o.backend == "gl")
        backend = engine::render::gl::createGlBackend({});
    else
        backend = engine::render::soft::createSoftBackend({o.threads, 64, false});
    RacingScene scene(*backend, {o.contentDir, o.seed});
    FrameRenderer frame(*backend, scene.library(), renderer);
    const float aspect = float(renderer.width) / float(renderer.height);
    const FreeCamera freeCamera;

    std::printf("racer: %s, %dx%d, %d frames at dt %.4f s, camera %s, backend %s (%d threads)\n",
                techniqueName(renderer.technique), renderer.width, renderer.height, o.frames, o.fixedDt,
                o.camera.c_str(), backend->name().c_str(), o.threads);
    double totalMs = 0.0;
    for (int i = 0; i < o.frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const float time = float(i * o.fixedDt);
        scene.update(float(o.fixedDt));
        const CameraView camera = cameraView(cameraMode, scene, time, aspect, freeCamera);
        const engine::scene::DrawLists lists =
            engine::scene::extractDrawLists(scene.registry(), scene.library(), camera.viewProj, camera.eye);
        frame.render(lists, camera);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        totalMs += ms;
        std::string passes;
        for (const auto& t : backend->takeTimings()) {
            char buf[64];
            std::snprintf(buf, sizeof buf, " %s %.1f", t.pass.c_str(), t.milliseconds);
            passes += buf;
        }
        if (i == 0 || (i + 1) % 10 == 0 || i + 1 == o.frames)
            std::printf("frame %d/%d  %.1f ms  (ms:%s)\n", i + 1, o.frames, ms, passes.c_str());
    }
    std::printf("racer: mean frame %.1f ms\n", totalMs / std::max(1, o.frames));

    if (!o.capturePath.empty()) {
        const std::filesystem::path path(o.capturePath);
        if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
        engine::capture::writePng(path, engine::capture::imageFromReadback(backend->readback(frame.color())));
        std::printf("racer: wrote %s\n", path.string().c_str());
        if (o.captureLayers) {
            std::filesystem::path exr = path;
            exr.replace_extension(".exr");
            engine::capture::writeLayersExr(exr, frame.layers());
            std::printf("racer: wrote %s (%zu layers)\n", exr.string().c_str(), frame.layers().size());
        }
    }
    if (!o.layerPictures.empty()) {
        if (frame.layers().empty()) throw engine::Error("--layer-pictures needs --capture-layers");
        const int n = writeLayerPictures(o.layerPictures, "ssam_", frame.layers(), kNearPlane, kFarPlane);
        std::printf("racer: wrote %d layer pictures to %s\n", n, o.layerPictures.c_str());
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"racer: the SSAM racing-scene demo (seeds/000, Pure)"};
    Options o;
    app.add_option("--backend", o.backend, "render backend")->check(CLI::IsMember({"soft", "gl"}))->capture_default_str();
    app.add_option("--technique", o.technique, "how foliage is drawn")
        ->check(CLI::IsMember({"ssam", "alpha-test"}))
        ->capture_default_str();
    app.add_option("--size", o.size, "frame size WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--frames", o.frames, "frames to render")->check(CLI::Range(1, 1000000))->capture_default_str();
    app.add_option("--fixed-dt", o.fixedDt, "simulation time step per frame, seconds")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    app.add_option("--camera", o.camera, "camera")->check(CLI::IsMember({"chase", "pan", "free"}))->capture_default_str();
    app.add_option("--seed", o.seed, "scene seed (track shape, placement)")->capture_default_str();
    app.add_option("--threads", o.threads, "soft backend threads (0: all)")->check(CLI::Range(0, 256))->capture_default_str();
    app.add_option("--capture", o.capturePath, "write the last frame to this PNG");
    app.add_flag("--capture-layers", o.captureLayers, "also write every SSAM layer to an EXR next to the PNG");
    app.add_flag("--headless", o.headless, "render offscreen even when a display is available");
    app.add_option("--content", o.contentDir, "content directory")->check(CLI::ExistingDirectory)->capture_default_str();
    app.add_option("--msaa", o.msaa, "opaque-pass samples (1, 2, 4; Pure used 2)")
        ->check(CLI::IsMember({1, 2, 4}))
        ->capture_default_str();
    app.add_option("--layer-pictures", o.layerPictures, "write each captured layer as a PNG into this directory");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "racer: error: %s\n", e.what());
        return 1;
    }
}
