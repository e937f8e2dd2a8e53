// SPDX-License-Identifier: MIT
#include "bench_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <thread>

#include "bench_alternate.hpp"
#include "bench_frame.hpp"
#include "bench_goals.hpp"
#include "bench_temporal.hpp"
#include "counting_backend.hpp"
#include "engine/capture/image_write.hpp"
#include "engine/capture/metrics.hpp"
#include "engine/capture/readback_image.hpp"
#include "engine/core/error.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/devices/create_device.hpp"
#include "engine/render/vk/vk_backend.hpp"
#include "frame_timing.hpp"
#include "rss_peak.hpp"

namespace bench {

using namespace engine::render;
using engine::capture::Image;
using transparency::TechniqueKind;

namespace {

// The exact reference of one scene: the still frame and the pan, on the soft backend.
struct ReferenceFrames {
    std::optional<Image> still;
    std::optional<double> panFlicker;  // temporalFlicker of the reference pan
    std::string note;                  // why there is none
};

// The scene's views, uploaded once on one backend.
struct SceneViews {
    std::unique_ptr<ViewUpload> still;
    std::vector<std::unique_ptr<ViewUpload>> pan;
};

SceneViews uploadViews(Backend& backend, BenchScene& scene, float aspect, int panFrames) {
    SceneViews v;
    v.still = std::make_unique<ViewUpload>(backend, scene, scene.camera(aspect));
    if (scene.hasPan())
        for (int k = 0; k < panFrames; ++k)
            v.pan.push_back(std::make_unique<ViewUpload>(backend, scene, scene.panCamera(aspect, k)));
    return v;
}

// The subject's options with the scenes' depth function (reverse-Z).
transparency::TechniqueOptions withSceneDepth(transparency::TechniqueOptions o) {
    o.depthFunc = kDepthFunc;
    return o;
}

Image frameImage(Backend& backend, const engine::render::FrameTargets& targets) {
    return engine::capture::imageFromReadback(backend.readback(targets.color()));
}

std::vector<Image> panImages(Backend& backend, FrameDrawer& drawer, engine::render::FrameTargets& targets,
                             transparency::Technique* technique, const SceneViews& views) {
    std::vector<Image> frames;
    std::uint64_t index = 0;
    // A technique with history starts the pan converged on its first view (the first drawn cut).
    if (technique && technique->needsHistory())
        for (; index < kHistoryFrames; ++index) drawer.draw(targets, technique, *views.pan.front(), index, index == 0);
    for (const auto& view : views.pan) {
        drawer.draw(targets, technique, *view, index, index == 0);
        ++index;
        backend.takeTimings();
        frames.push_back(frameImage(backend, targets));
    }
    return frames;
}

ReferenceFrames computeReference(Backend& soft, BenchScene& scene, const SceneViews& views, const BenchOptions& o) {
    ReferenceFrames ref;
    try {
        auto technique = transparency::createTechnique(TechniqueKind::Reference, soft, withSceneDepth({}));
        engine::render::FrameTargets targets(
            soft, {o.width, o.height, technique->opaqueSamples(), Format::RGBA8_SRGB, kDepthFunc});
        FrameDrawer drawer(soft, scene.library());
        drawer.draw(targets, technique.get(), *views.still);
        soft.takeTimings();
        ref.still = frameImage(soft, targets);
        if (!o.imagesDir.empty()) {
            std::filesystem::create_directories(o.imagesDir);
            engine::capture::writePng(o.imagesDir / (std::string(sceneName(scene.kind())) + "_reference.png"),
                                      *ref.still);
        }
        if (!views.pan.empty())
            ref.panFlicker = engine::capture::temporalFlicker(panImages(soft, drawer, targets, technique.get(), views));
    } catch (const std::exception& e) {
        ref.note = std::string("no reference: ") + e.what();
    }
    return ref;
}

BenchRow skippedRow(const std::string& scene, const std::string& technique, const std::string& backend,
                    const BenchOptions& o) {
    BenchRow row;
    row.scene = scene;
    row.technique = technique;
    row.backend = backend;
    row.width = o.width;
    row.height = o.height;
    return row;
}

BenchRow measure(Backend& backend, const std::string& backendName, BenchScene& scene, const SceneViews& views,
                 const BenchSubject& subject, const ReferenceFrames& ref, const BenchOptions& o) {
    BenchRow row;
    row.scene = sceneName(scene.kind());
    row.technique = subject.name;
    row.backend = backendName;
    row.width = o.width;
    row.height = o.height;
    std::printf("[ssam-bench] %-6s %-14s %-4s ", row.scene.c_str(), row.technique.c_str(), backendName.c_str());
    std::fflush(stdout);
    try {
        ResourceCount count;
        const std::unique_ptr<Backend> counting = makeCountingBackend(backend, count);
        const RssPeak rss;
        std::unique_ptr<transparency::Technique> technique;
        if (subject.kind)
            technique = transparency::createTechnique(*subject.kind, *counting, withSceneDepth(subject.options));
        engine::render::FrameTargets targets(
            *counting, {o.width, o.height, technique ? technique->opaqueSamples() : 1, Format::RGBA8_SRGB, kDepthFunc});
        FrameDrawer drawer(backend, scene.library());
        // A technique with history is measured after kHistoryFrames of the still view, never on
        // its first frame; the timed frames continue the sequence.
        std::uint64_t frameIndex = 0;
        if (technique && technique->needsHistory())
            for (; frameIndex < kHistoryFrames; ++frameIndex)
                drawer.draw(targets, technique.get(), *views.still, frameIndex, frameIndex == 0);
        backend.takeTimings();  // drop whatever earlier work left

        std::vector<double> times, cpuTimes;
        std::vector<std::string> passOrder;
        std::map<std::string, std::vector<double>> passTimes;
        for (int i = 0; i < o.warmup + o.reps; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const double cpuStart = processCpuMs();
            drawer.draw(targets, technique.get(), *views.still, frameIndex, frameIndex == 0);
            ++frameIndex;
            // GL: waiting for the passes' GL_TIME_ELAPSED results also waits for the frame.
            const std::vector<PassTiming> timings = backend.takeTimings();
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            const double cpuMs = processCpuMs() - cpuStart;
            const bool timed = i >= o.warmup;
            if (timed) std::printf(" rep %d/%d %.1f ms", i - o.warmup + 1, o.reps, ms);
            else std::printf(" warm-up %.1f ms", ms);
            std::fflush(stdout);
            if (!timed) continue;
            times.push_back(ms);
            cpuTimes.push_back(cpuMs);
            std::map<std::string, double> frame;  // several passes of one name in a frame add up
            for (const PassTiming& t : timings) {
                if (!frame.count(t.pass) && !passTimes.count(t.pass)) passOrder.push_back(t.pass);
                frame[t.pass] += t.milliseconds;
            }
            for (const auto& [pass, msPass] : frame) passTimes[pass].push_back(msPass);
        }
        // RSS growth of creation and the timed frames only (readbacks and metrics below allocate too).
        row.peakRssMb = rss.growthMb();
        row.ran = true;
        row.timeMedianMs = median(times);
        row.cpuMedianMs = median(cpuTimes);
        row.timeMinMs = *std::min_element(times.begin(), times.end());
        row.timeMaxMs = *std::max_element(times.begin(), times.end());
        for (const std::string& pass : passOrder) row.passes.push_back({pass, median(passTimes[pass])});

        const Image image = frameImage(backend, targets);
        const std::string imageStem = row.scene + "_" + row.technique + "_" + backendName;
        if (!o.imagesDir.empty()) {
            std::filesystem::create_directories(o.imagesDir);
            engine::capture::writePng(o.imagesDir / (imageStem + ".png"), image);
        }
        if (ref.still) {
            namespace cap = engine::capture;
            row.rmseLinear = cap::rmseLinear(*ref.still, image);
            row.psnrLinear = cap::psnrLinear(*ref.still, image);
            row.rmseSrgb = cap::rmseSrgb(*ref.still, image);
            row.psnrSrgb = cap::psnrSrgb(*ref.still, image);
            row.ssim = cap::ssim(*ref.still, image);
            Image flipMap;
            row.flipMean = cap::flip(*ref.still, image, {}, o.imagesDir.empty() ? nullptr : &flipMap);
            // Where the error is: the map shows what the mean hides (edges, interiors, halos).
            if (!o.imagesDir.empty()) engine::capture::writePng(o.imagesDir / (imageStem + "_flip.png"), flipMap);
        } else {
            row.note = ref.note;
        }
        if (!views.pan.empty()) {
            row.flickerRaw =
                engine::capture::temporalFlicker(panImages(backend, drawer, targets, technique.get(), views));
            if (ref.panFlicker) row.flicker = row.flickerRaw - *ref.panFlicker;
        }
        row.peakMemMb = double(count.peakBytes()) / (1024.0 * 1024.0);
        std::printf("  -> median %.2f ms", row.timeMedianMs);
        if (has(row.flipMean)) std::printf(", FLIP %.4f", row.flipMean);
        std::printf("\n");
    } catch (const std::exception& e) {
        row = skippedRow(row.scene, row.technique, row.backend, o);
        row.note = std::string("skipped: ") + e.what();
        std::printf(" %s\n", row.note.c_str());
    }
    std::fflush(stdout);
    return row;
}

// The time goal's pair, ssam and ssam-paper, timed alternately (bench_alternate.hpp) where the run
// measured both on this scene and backend: their rows get timeAlternatedMs.
void timePresetsAlternately(Backend& backend, const std::string& backendName, BenchScene& scene,
                            const SceneViews& views, const BenchOptions& o, std::vector<BenchRow>& rows) {
    const std::string sceneLabel = sceneName(scene.kind()), ssam = transparency::techniqueName(TechniqueKind::Ssam);
    const auto subject = [&](const std::string& name) -> const BenchSubject* {
        const auto s =
            std::find_if(o.subjects.begin(), o.subjects.end(), [&](const auto& x) { return x.name == name; });
        return s == o.subjects.end() ? nullptr : &*s;
    };
    const auto row = [&](const std::string& technique) -> BenchRow* {
        const auto r = std::find_if(rows.begin(), rows.end(), [&](const BenchRow& x) {
            return x.scene == sceneLabel && x.technique == technique && x.backend == backendName && x.ran;
        });
        return r == rows.end() ? nullptr : &*r;
    };
    const BenchSubject *a = subject(ssam), *b = subject(kSsamPaperRow);
    BenchRow *ra = row(ssam), *rb = row(kSsamPaperRow);
    if (!a || !b || !ra || !rb) return;
    std::printf("[ssam-bench] %-6s %s and %s alternately, %s:", sceneLabel.c_str(), ssam.c_str(), kSsamPaperRow,
                backendName.c_str());
    std::fflush(stdout);
    try {
        const AlternatedTimes t =
            timeAlternately(backend, scene, *views.still, *a, *b, o.warmup, o.reps, o.width, o.height);
        ra->timeAlternatedMs = t.aMedianMs;
        rb->timeAlternatedMs = t.bMedianMs;
        std::printf(" medians %.2f and %.2f ms, ratio %.3f\n", t.aMedianMs, t.bMedianMs, t.aMedianMs / t.bMedianMs);
    } catch (const std::exception& e) {
        std::printf(" not timed: %s\n", e.what());
    }
    std::fflush(stdout);
}

}  // namespace

std::vector<BenchSubject> techniqueSubjects(const std::vector<TechniqueKind>& techniques) {
    std::vector<BenchSubject> subjects{{kOpaqueOnly, std::nullopt, {}}};
    for (TechniqueKind k : techniques) subjects.push_back({transparency::techniqueName(k), k, {}});
    return subjects;
}

int resolvedThreads(int threads) {
    return threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

std::vector<BenchRow> runBench(const BenchOptions& o) {
    const float aspect = float(o.width) / float(o.height);
    const int threads = resolvedThreads(o.threads);
    // Every device of the run through the one table, with the same threads (soft's, and
    // LP_NUM_THREADS for llvmpipe and lavapipe); one that cannot be made here is reported and
    // its rows are skipped with why.
    engine::render::DeviceOptions deviceOptions;
    deviceOptions.threads = threads;
    deviceOptions.soft = {.threads = threads, .tileSize = 64, .simd = o.simd};
    std::unique_ptr<engine::render::Device> soft =
        engine::render::createDevice(engine::render::DeviceKind::Soft, deviceOptions);
    std::map<std::string, std::unique_ptr<engine::render::Device>> devices;
    std::map<std::string, std::string> unavailable;
    for (const std::string& name : o.backends) {
        const engine::render::DeviceKind kind = *engine::render::parseDeviceKind(name);  // checked by the options
        if (kind == engine::render::DeviceKind::Soft || devices.count(name) || unavailable.count(name)) continue;
        try {
            devices[name] = engine::render::createDevice(kind, deviceOptions);
            std::printf("[ssam-bench] %s (LP_NUM_THREADS=%d)\n", devices[name]->driver().describe().c_str(), threads);
        } catch (const std::exception& e) {
            unavailable[name] = name + " backend unavailable: " + e.what();
            std::printf("[ssam-bench] %s\n", unavailable[name].c_str());
        }
    }
    std::printf("[ssam-bench] %dx%d, %d rep(s) after %d warm-up, %d pan frames, soft backend %d thread(s)\n", o.width,
                o.height, o.reps, o.warmup, o.panFrames, threads);

    std::vector<BenchRow> rows;
    for (SceneKind kind : o.scenes) {
        BenchScene softScene(*soft, kind, o.contentDir);
        if (o.levelsOfDetail) softScene.useLevelsOfDetail(o.height, o.crossfade);
        const SceneViews softViews = uploadViews(*soft, softScene, aspect, o.panFrames);
        std::printf("[ssam-bench] scene %s: %zu foliage instances in view; computing the reference\n", sceneName(kind),
                    softViews.still->foliageInstances());
        std::fflush(stdout);
        const ReferenceFrames ref = computeReference(*soft, softScene, softViews, o);
        if (!ref.note.empty()) std::printf("[ssam-bench] %s\n", ref.note.c_str());

        // The soft backend first: its reference judges every backend's frames.
        std::vector<TemporalBackend> temporal{{"soft", soft.get(), &softScene}};
        std::vector<std::unique_ptr<BenchScene>> glScenes;  // kept for the temporal pan
        for (const std::string& backendName : o.backends) {
            if (unavailable.count(backendName)) {
                for (const BenchSubject& s : o.subjects) {
                    BenchRow row = skippedRow(sceneName(kind), s.name, backendName, o);
                    row.note = unavailable[backendName];
                    rows.push_back(row);
                }
                continue;
            }
            Backend& backend = devices.count(backendName) ? *devices[backendName] : *soft;
            std::unique_ptr<BenchScene> ownScene;
            SceneViews ownViews;
            if (&backend != soft.get()) {
                ownScene = std::make_unique<BenchScene>(backend, kind, o.contentDir);
                if (o.levelsOfDetail) ownScene->useLevelsOfDetail(o.height, o.crossfade);
                ownViews = uploadViews(backend, *ownScene, aspect, o.panFrames);
            }
            BenchScene& scene = ownScene ? *ownScene : softScene;
            const SceneViews& views = ownScene ? ownViews : softViews;
            for (const BenchSubject& s : o.subjects)
                rows.push_back(measure(backend, backendName, scene, views, s, ref, o));
            timePresetsAlternately(backend, backendName, scene, views, o, rows);
            if (ownScene)
                temporal.push_back({backendName, &backend, ownScene.get()}), glScenes.push_back(std::move(ownScene));
        }
        // Every backend's techniques through the pan, frame by frame against the soft reference.
        measureTemporal(temporal, o, rows);
    }
    return rows;
}

}  // namespace bench
