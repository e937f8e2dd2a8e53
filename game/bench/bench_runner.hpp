#pragma once
// Runs the benchmark: every chosen technique (plus the opaque-only frame) on every chosen
// scene and backend, timed over repetitions after warm-up, judged against the exact
// reference (technique `reference` on the soft backend, computed once per scene), and its
// flicker measured over the scene's sideways pan.
#include <filesystem>
#include <string>
#include <vector>

#include "bench_result.hpp"
#include "bench_scenes.hpp"
#include "transparency/technique.hpp"

namespace bench {

struct BenchOptions {
    std::vector<SceneKind> scenes;
    std::vector<transparency::TechniqueKind> techniques;
    std::vector<std::string> backends;  // "soft", "gl"
    int width = 1280, height = 720;
    int reps = 5, warmup = 1;
    int panFrames = 8;  // frames of the flicker pan (at least 2)
    int threads = 0;    // soft backend threads, and LP_NUM_THREADS for llvmpipe; 0: all
    std::filesystem::path contentDir;
    std::filesystem::path imagesDir;  // when set: each still frame as <scene>_<technique>_<backend>.png
};

// Rows in the order scene, backend, then opaque-only followed by the techniques as given.
// Prints one progress line per repetition to stdout.
std::vector<BenchRow> runBench(const BenchOptions& options);

// The thread count `threads` stands for (0: the hardware's).
int resolvedThreads(int threads);

}  // namespace bench
