// SPDX-License-Identifier: MIT
#pragma once
// racer's command line: every flag, its default and its check, in one place (README
// "The demo: racer" lists them). main() parses; run() turns them into renderer settings.
#include <cstdint>
#include <map>
#include <string>

#include "camera_rig.hpp"
#include "content_dir.hpp"
#include "ssam/core/settings.hpp"
#include "transparency/technique.hpp"

namespace CLI {
class App;
}

namespace racer {

struct Options {
    std::string backend = "auto";  // auto: gl in a window, soft headless
    std::string technique = "ssam";
    std::string ssamPreset = ssam::presetName(ssam::kRecommendedPreset);  // --ssam-preset: SSAM's knobs
    float ssamDepthThreshold = 0.0f;  // --ssam-depth-threshold: Settings::depthMaskThreshold
    std::string size = "1280x720";
    int frames = 60;  // headless; a window runs until closed unless --frames is given
    bool framesGiven = false;
    double fixedDt = 1.0 / 30.0;  // headless; a window steps by the wall clock unless --fixed-dt is given
    bool fixedDtGiven = false;
    std::string camera = "chase";
    std::uint32_t seed = 1;
    int threads = 0;
    int device = -1;            // --device: the Vulkan device (--backend vk)
    std::string simd = "auto";  // --simd: the soft backend's kernels' instruction set
    std::string capturePath;
    bool captureLayers = false;
    bool headless = false;
    std::string contentDir = defaultContentDir().string();
    int msaa = 1;
    std::string msaaDepth = "closest";  // --msaa-depth closest|any: which sample the MSAA depth keeps
    std::string layerPictures;
    std::string dumpGraphPath;  // --dump-graph: Graphviz dot of the last frame's graph
    std::string compare;        // --compare A,B: A on the left, B on the right
    bool hud = false;           // --hud: the HUD in the frame (the window's H toggles it)
    std::string lod = "on";     // --lod on|off: levels of detail for the plants
    std::string script;         // --script (hidden): keys and window changes at given frames, for tests
    std::string scenePath;      // --scene: a glTF file instead of the racing scene
    int sceneIndex = -1;
    int cameraIndex = -1;
    // Living-scene modules: whether each one's flag (--no-wind, ...; the registry's) was given,
    // by module name.
    std::map<std::string, bool> moduleFlagGiven;
};

// Living-scene modules on or off by name: each module's default, flipped where its flag was given.
std::map<std::string, bool> enabledModules(const Options& o);

// Registers every flag of `o` on `app` (checks included: a bad technique or camera is
// refused by CLI11 with "X not in {...}").
void addOptions(CLI::App& app, Options& o);

// After parsing: throws engine::UsageError, saying why, for a combination of flags that means
// nothing (--capture-layers without --capture, --camera with --scene, ...).
void checkCombinations(const CLI::App& app, const Options& o);

struct FrameSize {
    int width = 0;
    int height = 0;
    bool operator==(const FrameSize&) const = default;
};
// "WIDTHxHEIGHT", each 1..16384; throws engine::UsageError quoting the flag otherwise.
FrameSize parseFrameSize(const std::string& size);

transparency::TechniqueKind parseTechniqueName(const std::string& name);  // allTechniques()' names

// --compare's "A,B": two of allTechniques()' names (they may be the same); throws
// engine::UsageError quoting the flag otherwise.
struct ComparedPair {
    transparency::TechniqueKind left, right;
};
ComparedPair parseCompare(const std::string& pair);

}  // namespace racer
