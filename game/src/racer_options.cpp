// SPDX-License-Identifier: MIT
#include "racer_options.hpp"

#include <CLI/CLI.hpp>

#include <regex>
#include <vector>

#include "engine/cli/command_line.hpp"
#include "engine/core/usage_error.hpp"
#include "engine/render/devices/create_device.hpp"
#include "on_off_option.hpp"
#include "racer_feature_modules.hpp"
#include "simd_flag.hpp"

namespace racer {

namespace {

// --backend: auto, or a render device kind as its table names it.
std::vector<std::string> backendNames() {
    std::vector<std::string> names{"auto"};
    for (const engine::render::DeviceKindInfo& k : engine::render::deviceKinds()) names.emplace_back(k.name);
    return names;
}

std::vector<std::string> techniqueNames() {
    std::vector<std::string> names;
    for (transparency::TechniqueKind kind : transparency::allTechniques())
        names.emplace_back(transparency::techniqueName(kind));
    return names;
}

}  // namespace

void addOptions(CLI::App& app, Options& o) {
    app.add_option("--backend", o.backend,
                   "render backend (auto: gl in a window, soft headless; vk: Vulkan, in a window or headless)")
        ->check(CLI::IsMember(backendNames()))
        ->capture_default_str();
    app.add_option("--device", o.device, "--backend vk: the Vulkan device (-1: the first usable)")
        ->capture_default_str();
    app.add_option("--technique", o.technique, "how foliage is drawn")
        ->check(CLI::IsMember(techniqueNames()))
        ->capture_default_str();
    app.add_option(
           "--ssam-preset", o.ssamPreset,
           "SSAM's knobs (technique ssam): paper ([Hathaway 2010]'s values) or measured (chosen by ssam-bench's "
           "sweep: lower error at the paper's cost; ssam/docs/knobs.md)")
        ->check(CLI::IsMember({ssam::presetName(ssam::Preset::Paper), ssam::presetName(ssam::Preset::Measured)}))
        ->capture_default_str();
    app.add_option("--ssam-depth-threshold", o.ssamDepthThreshold,
                   "technique ssam: the depth later passes (particles, grass, light shafts, water) test against "
                   "keeps the foliage only where SSAM's mask reaches this value (0: wherever the colour pass "
                   "wrote, the paper's; above 0 no unfogged rim round soft leaf edges, for a depth copy and a "
                   "depth-only redraw of the foliage)")
        ->check(CLI::Range(0.0f, 1.0f))
        ->capture_default_str();
    app.add_option("--size", o.size, "frame size WIDTHxHEIGHT (a window's first size: it renders at its window's)")
        ->capture_default_str();
    app.add_option_function<int>(
           "--frames", [&o](int n) { o.frames = n, o.framesGiven = true; },
           "frames to render (default 60 headless; a window runs until closed)")
        ->check(CLI::Range(1, 1000000));
    app.add_option_function<double>(
           "--fixed-dt", [&o](double dt) { o.fixedDt = dt, o.fixedDtGiven = true; },
           "simulation time step per frame, seconds (default 1/30 headless; a window follows the clock)")
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--camera", o.camera, "camera")
        ->check(CLI::IsMember({"chase", "pan", "free", "sky"}))
        ->capture_default_str();
    app.add_option("--seed", o.seed, "scene seed (track shape, placement)")->capture_default_str();
    app.add_option("--threads", o.threads, "soft backend threads (0: all)")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
    addSimdOption(app, o.simd);
    app.add_option("--capture", o.capturePath,
                   "write the last frame to this image: .png (8-bit sRGB) or .exr (linear float); checked before "
                   "the first frame, its directory created if missing");
    app.add_flag("--capture-layers", o.captureLayers,
                 "with a --capture .png: also write every layer of the technique to an EXR of the same name");
    app.add_flag("--headless", o.headless, "render offscreen even when a display is available");
    app.add_option("--content", o.contentDir, "content directory (the racing scene's models)")->capture_default_str();
    app.add_option("--msaa", o.msaa, "opaque-pass samples at least (1, 2, 4; Pure used 2; a2c always uses 4)")
        ->check(CLI::IsMember({1, 2, 4}))
        ->capture_default_str();
    app.add_option("--msaa-depth", o.msaaDepth,
                   "which sample an MSAA depth resolves to: closest (to the eye, [Hathaway 2010] 3.5.1) or any (the "
                   "implementation's choice: all --backend gles can do, ES 3.0 reads no sample)")
        ->check(CLI::IsMember({"closest", "any"}))
        ->capture_default_str();
    app.add_option(
        "--layer-pictures", o.layerPictures,
        "with --capture-layers: write each captured layer as a PNG into this directory (created if missing)");
    app.add_option("--dump-graph", o.dumpGraphPath,
                   "write the last frame's compiled frame graph to this Graphviz .dot file (passes culled or "
                   "skipped as empty are marked so; checked before the first frame)");
    app.add_option("--compare", o.compare,
                   "A,B: render the frame with technique A and with B, side by side (A left, B right), labelled, "
                   "with 4x insets of the crop where they differ most, e.g. ssam,alpha-test; in a window V toggles "
                   "it and B steps B");
    addOnOffOption(app, "--lod", o.lod,
                   "levels of detail for trees and bushes: on (the full model near, fewer and larger cards further, "
                   "an impostor far; switched by measured screen-space error) or off (every plant at full detail)");
    app.add_flag("--hud", o.hud,
                 "draw the HUD into the frame (and so into --capture): technique, backend, size, frame and pass "
                 "times; in a window H toggles it");
    // Hidden (empty group): drives the window from tests, e.g. "2:3,4:C,5:size=400x300,9:Esc".
    app.add_option("--script", o.script, "keys pressed and window changes at given frames")->group("");
    app.add_option("--scene", o.scenePath, "render this glTF 2.0 file (.gltf or .glb) instead of the racing scene");
    app.add_option("--scene-index", o.sceneIndex,
                   "with --scene: which of the file's scenes (default: its default scene)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--camera-index", o.cameraIndex, "with --scene: which of the file's cameras (default: its first)")
        ->check(CLI::NonNegativeNumber);
    // Living-scene modules: each one's flag flips its default (drops or adds its systems and
    // passes). The map's nodes never move, so each flag may hold on to its bool.
    for (const engine::scene::FeatureModule& m : featureModules())
        app.add_flag(m.flag, o.moduleFlagGiven[m.name], m.help);
    app.footer(engine::cli::contractHelpFooter());
}

void checkCombinations(const CLI::App& app, const Options& o) {
    auto given = [&](const char* flag) { return app.count(flag) > 0; };
    auto refuse = [](const std::string& why) { throw engine::UsageError(why); };
    if (given("--capture-layers") && !given("--capture"))
        refuse("--capture-layers writes the layers to an EXR beside the --capture image: give --capture too");
    if (given("--layer-pictures") && !given("--capture-layers"))
        refuse("--layer-pictures draws the layers that --capture-layers captures: give --capture-layers too");
    for (const char* flag : {"--scene-index", "--camera-index"})
        if (given(flag) && !given("--scene"))
            refuse(std::string(flag) + " picks from the --scene file: give --scene too");
    if (given("--scene")) {
        if (given("--camera"))
            refuse("--camera moves the racing scene's camera; a --scene file is seen through its own (--camera-index)");
        if (given("--seed")) refuse("--seed shapes the racing scene; a --scene file has nothing to seed");
        if (given("--content")) refuse("--content holds the racing scene's models; a --scene file brings its own");
        for (const engine::scene::FeatureModule& m : featureModules())
            if (given(m.flag))
                refuse(std::string(m.flag) + (m.enabledByDefault ? " turns off" : " turns on") +
                       " part of the racing scene's life; a --scene file has none");
    }
    if (given("--compare")) {
        parseCompare(o.compare);
        if (given("--technique")) refuse("--compare A,B sets the technique (A, on the left): drop --technique");
        if (given("--capture-layers"))
            refuse("--capture-layers captures one technique's layers; --compare shows two: drop one of them");
    }
    if (given("--script") && o.headless) refuse("--script drives a window; --headless has none");
    const std::optional<engine::render::DeviceKind> kind = engine::render::parseDeviceKind(o.backend);
    const bool gpu = kind && *kind != engine::render::DeviceKind::Soft;
    if (given("--threads") && gpu)
        refuse("--threads sets the soft backend's threads; --backend " + o.backend + " does not use them");
    if (given("--simd") && gpu) refuse("--simd picks the soft backend's kernels; --backend " + o.backend + " has none");
    if (given("--device") && kind != engine::render::DeviceKind::Vulkan)
        refuse("--device picks a Vulkan device: it needs --backend vk");
    simdFromFlag(o.simd);  // refuses a set this CPU does not run
}

std::map<std::string, bool> enabledModules(const Options& o) {
    std::map<std::string, bool> enabled;
    for (const engine::scene::FeatureModule& m : featureModules()) {
        const auto flag = o.moduleFlagGiven.find(m.name);
        enabled[m.name] = m.enabledByDefault != (flag != o.moduleFlagGiven.end() && flag->second);
    }
    return enabled;
}

FrameSize parseFrameSize(const std::string& size) {
    std::smatch m;
    static const std::regex sizePattern(R"((\d{1,5})x(\d{1,5}))");
    if (!std::regex_match(size, m, sizePattern))
        throw engine::UsageError("--size '" + size + "': expected WIDTHxHEIGHT, e.g. 1280x720");
    const FrameSize s{std::stoi(m[1]), std::stoi(m[2])};
    if (s.width < 1 || s.height < 1 || s.width > 16384 || s.height > 16384)
        throw engine::UsageError("--size '" + size + "': each dimension must be in 1..16384");
    return s;
}

ComparedPair parseCompare(const std::string& pair) {
    const std::size_t comma = pair.find(',');
    auto bad = [&](const std::string& why) {
        return engine::UsageError("--compare '" + pair + "': " + why +
                                  " (expected A,B, two of the techniques, e.g. ssam,alpha-test)");
    };
    if (comma == std::string::npos || pair.find(',', comma + 1) != std::string::npos) throw bad("not two names");
    const std::string left = pair.substr(0, comma), right = pair.substr(comma + 1);
    const auto a = transparency::parseTechnique(left), b = transparency::parseTechnique(right);
    if (!a) throw bad("unknown technique '" + left + "'");
    if (!b) throw bad("unknown technique '" + right + "'");
    return {*a, *b};
}

transparency::TechniqueKind parseTechniqueName(const std::string& name) {
    if (const auto kind = transparency::parseTechnique(name)) return *kind;
    throw engine::UsageError("--technique '" + name + "': unknown");
}

}  // namespace racer
