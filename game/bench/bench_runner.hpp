// SPDX-License-Identifier: MIT
#pragma once
// Runs the benchmark: every subject (a technique with its options, or the opaque-only
// frame) on every chosen scene and backend, timed over repetitions after warm-up, judged
// against the exact reference (technique `reference` on the soft backend, computed once per
// scene), and its flicker measured over the scene's sideways pan.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench_result.hpp"
#include "bench_scenes.hpp"
#include "plant_levels.hpp"
#include "engine/render/kernel/simd_isa.hpp"
#include "transparency/create_technique.hpp"

namespace bench {

// One thing measured: a technique with its options (the knob sweep measures SSAM under
// many ssam::Settings values), or the opaque-only frame.
struct BenchSubject {
    std::string name;                                 // the rows' technique column and image names
    std::optional<transparency::TechniqueKind> kind;  // none: the opaque-only frame
    // options.depthFunc is overwritten with the scenes' (reverse-Z, kDepthFunc).
    transparency::TechniqueOptions options;
};

// The opaque-only frame, then each technique with the default options: the comparison run.
std::vector<BenchSubject> techniqueSubjects(const std::vector<transparency::TechniqueKind>& techniques);

struct BenchOptions {
    std::vector<SceneKind> scenes;
    std::vector<BenchSubject> subjects;
    std::vector<std::string> backends;  // "soft", "gl", "vk"
    int width = 1280, height = 720;
    int reps = 5, warmup = 1;
    int panFrames = 8;        // frames of the flicker pan (at least 2)
    int temporalFrames = 32;  // frames of the pan measured frame by frame (bench_temporal.hpp); 0: none
    int threads = 0;          // soft backend threads, and LP_NUM_THREADS for llvmpipe; 0: all
    std::optional<engine::render::soft::SimdIsa> simd;  // the soft kernels' instruction set; unset: the widest
    std::filesystem::path contentDir;
    bool levelsOfDetail = true;              // --lod: the plants' levels of detail, chosen for `height`
    float crossfade = racer::kLodCrossfade;  // --crossfade: their crossfade band (LodView::crossfade); 0: none
    // When set: each still frame as <scene>_<technique>_<backend>.png, and its per-pixel ꟻLIP
    // error against the reference as <scene>_<technique>_<backend>_flip.png.
    std::filesystem::path imagesDir;
};

// Rows in the order scene, backend, then the subjects as given.
// Prints one progress line per repetition to stdout.
std::vector<BenchRow> runBench(const BenchOptions& options);

// The thread count `threads` stands for (0: the hardware's).
int resolvedThreads(int threads);

}  // namespace bench
