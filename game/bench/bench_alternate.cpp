// SPDX-License-Identifier: MIT
#include "bench_alternate.hpp"

#include <chrono>
#include <memory>
#include <vector>

#include "frame_timing.hpp"

namespace bench {

namespace {

// One subject drawing frames of its own sequence: its technique, targets, drawer (whose pool keeps
// the subject's transients, so no timed frame creates one) and frame index.
struct AlternatingSubject {
    std::unique_ptr<transparency::Technique> technique;
    std::unique_ptr<engine::render::FrameTargets> targets;
    FrameDrawer drawer;
    std::uint64_t frameIndex = 0;
    std::vector<double> times;

    AlternatingSubject(engine::render::Backend& backend, BenchScene& scene, const BenchSubject& s, int width,
                       int height)
        : drawer(backend, scene.library()) {
        if (s.kind) {
            transparency::TechniqueOptions options = s.options;
            options.depthFunc = kDepthFunc;
            technique = transparency::createTechnique(*s.kind, backend, options);
        }
        targets = std::make_unique<engine::render::FrameTargets>(
            backend, engine::render::FrameTargetsDesc{width, height, technique ? technique->opaqueSamples() : 1,
                                                      engine::render::Format::RGBA8_SRGB, kDepthFunc});
    }

    // One frame, timed to the end of its work (GL: the timings' results wait for it).
    double frame(engine::render::Backend& backend, const ViewUpload& view) {
        const auto start = std::chrono::steady_clock::now();
        drawer.draw(*targets, technique.get(), view, frameIndex, frameIndex == 0);
        ++frameIndex;
        backend.takeTimings();
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
};

}  // namespace

AlternatedTimes timeAlternately(engine::render::Backend& backend, BenchScene& scene, const ViewUpload& view,
                                const BenchSubject& a, const BenchSubject& b, int warmup, int reps, int width,
                                int height) {
    AlternatingSubject subjects[2] = {{backend, scene, a, width, height}, {backend, scene, b, width, height}};
    for (AlternatingSubject& s : subjects)  // a technique with history is never timed on its first frames
        while (s.frameIndex < (s.technique && s.technique->needsHistory() ? kHistoryFrames : 0)) s.frame(backend, view);
    backend.takeTimings();
    for (int i = 0; i < warmup + reps; ++i)
        for (AlternatingSubject& s : subjects) {
            const double ms = s.frame(backend, view);
            if (i >= warmup) s.times.push_back(ms);
        }
    return {median(subjects[0].times), median(subjects[1].times)};
}

}  // namespace bench
