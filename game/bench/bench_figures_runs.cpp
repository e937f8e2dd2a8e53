// SPDX-License-Identifier: MIT
#include "bench_figures_runs.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "bench_dolly.hpp"
#include "bench_goals.hpp"
#include "bench_motion.hpp"
#include "bench_verdict.hpp"

namespace bench {

namespace {

// The comparison's subjects named in `names` (with the comparison's options: its SSAM preset).
std::vector<BenchSubject> pick(const std::vector<BenchSubject>& subjects, const std::vector<std::string>& names) {
    std::vector<BenchSubject> out;
    for (const BenchSubject& s : subjects)
        if (std::find(names.begin(), names.end(), s.name) != names.end()) out.push_back(s);
    return out;
}

// The comparison's scenes among `kinds`.
std::vector<SceneKind> keep(const std::vector<SceneKind>& scenes, std::initializer_list<SceneKind> kinds) {
    std::vector<SceneKind> out;
    for (SceneKind k : scenes)
        if (std::find(kinds.begin(), kinds.end(), k) != kinds.end()) out.push_back(k);
    return out;
}

}  // namespace

FiguresRuns runFiguresRuns(const BenchOptions& comparison, int dollyFrames) {
    FiguresRuns runs;
    BenchOptions soft = comparison;
    soft.backends = {"soft"};
    soft.imagesDir.clear();

    BenchOptions lod = soft;
    lod.levelsOfDetail = !comparison.levelsOfDetail;
    lod.scenes = keep(comparison.scenes, {SceneKind::Tree, SceneKind::Forest, SceneKind::Vista});
    lod.subjects = pick(comparison.subjects, {"ssam", kSsamPaperRow, "ssam-plus", "alpha-test"});
    lod.temporalFrames = 0;  // the still goals read the still frame, its pan's flicker and the time
    runs.lodRowsHaveLevelsOfDetail = lod.levelsOfDetail;
    if (!lod.scenes.empty() && !lod.subjects.empty()) {
        std::printf("[ssam-bench --figures] the still goals with --lod %s\n", lod.levelsOfDetail ? "on" : "off");
        runs.lodRows = runBench(lod);
    }

    const std::vector<SceneKind> forest = keep(comparison.scenes, {SceneKind::Forest});
    if (forest.empty()) return runs;
    BenchOptions motion = soft;
    motion.scenes = forest;
    std::vector<std::string> motionNames{"ssam", "ssam-plus", "alpha-test"};
    for (const char* t : kShippedTechniques) motionNames.push_back(t);
    motion.subjects = pick(comparison.subjects, motionNames);
    if (!motion.subjects.empty()) {
        std::printf("[ssam-bench --figures] the forest in motion\n");
        runs.motion = runMotion(motion, availableMotions(), comparison.temporalFrames, /*motionVectors=*/true);
    }
    BenchOptions dolly = soft;
    dolly.scenes = forest;
    dolly.levelsOfDetail = true;
    dolly.subjects = pick(comparison.subjects, {"ssam", "ssam-plus", "alpha-test", "hashed"});
    if (!dolly.subjects.empty()) {
        std::printf("[ssam-bench --figures] popping along the forest's dolly\n");
        runs.dolly = runDolly(dolly, dollyFrames, comparison.crossfade);
    }
    return runs;
}

}  // namespace bench
