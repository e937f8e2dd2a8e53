// SPDX-License-Identifier: MIT
#include "bench_dolly.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "bench_frame.hpp"
#include "frame_timing.hpp"
#include "engine/capture/metrics.hpp"
#include "engine/capture/readback_image.hpp"
#include "engine/render/devices/create_device.hpp"
#include "engine/render/frame_targets.hpp"
#include "report_text.hpp"

namespace bench {

using namespace engine::render;
using engine::capture::Image;

namespace {

// One technique drawing one of the two scenes (LOD or full detail) through the dolly.
struct Run {
    std::unique_ptr<transparency::Technique> technique;
    std::unique_ptr<FrameTargets> targets;
    std::unique_ptr<FrameDrawer> drawer;
    Image last;  // the frame before
};

struct Subject {
    DollyRow row;
    Run lod, full;
    Image lastPlants;  // the plant pixels of the frame before (channel 0: 1 or 0)
    double lodFlipSum = 0.0, lodFrameFlipSum = 0.0;
};

Image drawFrame(Backend& backend, Run& run, const ViewUpload& view, std::uint64_t index) {
    run.drawer->draw(*run.targets, run.technique.get(), view, index, index == 0);
    backend.takeTimings();
    return engine::capture::imageFromReadback(backend.readback(run.targets->color()));
}

// The mean of `map` over the pixels set in `a` or `b` (either may be empty); 0 without any.
double meanOver(const Image& map, const Image& a, const Image& b) {
    double sum = 0.0;
    std::size_t n = 0;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            if ((!a.pixels.empty() && a.at(x, y, 0) > 0.0f) || (!b.pixels.empty() && b.at(x, y, 0) > 0.0f)) {
                sum += map.at(x, y, 0);
                ++n;
            }
    return n ? sum / double(n) : 0.0;
}

// ꟻLIP's mean over the pixels set in `a` or `b`; `frame`: its mean over the whole frame.
double flipOver(const Image& reference, const Image& test, const Image& a, const Image& b, double* frame = nullptr) {
    Image map;
    const double whole = engine::capture::flip(reference, test, {}, &map);
    if (frame) *frame = whole;
    return meanOver(map, a, b);
}

}  // namespace

std::vector<DollyRow> runDolly(const BenchOptions& o, int frames, float crossfade) {
    frames = std::clamp(frames, 2, kDollyFrames);
    const float aspect = float(o.width) / float(o.height);
    const int threads = resolvedThreads(o.threads);
    DeviceOptions deviceOptions;
    deviceOptions.threads = threads;
    deviceOptions.soft = {.threads = threads, .tileSize = 64, .simd = o.simd};
    std::unique_ptr<Device> soft = createDevice(DeviceKind::Soft, deviceOptions);
    auto withDepth = [](transparency::TechniqueOptions options) {
        options.depthFunc = kDepthFunc;
        return options;
    };
    std::vector<DollyRow> rows;
    for (SceneKind kind : o.scenes) {
        BenchScene lodScene(*soft, kind, o.contentDir), fullScene(*soft, kind, o.contentDir);
        if (!lodScene.hasDolly()) continue;
        lodScene.useLevelsOfDetail(o.height, crossfade);
        FrameTargets opaqueTargets(*soft, {o.width, o.height, 1, Format::RGBA8_SRGB, kDepthFunc});
        FrameDrawer opaqueDrawer(*soft, fullScene.library());
        std::vector<Subject> subjects;
        for (const BenchSubject& s : o.subjects) {
            if (!s.kind) continue;
            Subject subject;
            subject.row = {sceneName(kind), s.name};
            subject.row.crossfade = crossfade;
            for (auto [run, scene] : {std::pair{&subject.lod, &lodScene}, std::pair{&subject.full, &fullScene}}) {
                run->technique = transparency::createTechnique(*s.kind, *soft, withDepth(s.options));
                run->targets = std::make_unique<FrameTargets>(
                    *soft, FrameTargetsDesc{o.width, o.height, run->technique->opaqueSamples(), Format::RGBA8_SRGB,
                                            kDepthFunc});
                run->drawer = std::make_unique<FrameDrawer>(*soft, scene->library());
            }
            subjects.push_back(std::move(subject));
        }
        std::printf("[ssam-bench] %s dolly: %d frames of %.1f m, %zu technique(s), crossfade %.2f\n", sceneName(kind),
                    frames, double(kDollyStep), subjects.size(), double(crossfade));
        // History first, on the dolly's first view, for the techniques that keep it.
        {
            const ViewUpload lodFirst(*soft, lodScene, lodScene.dollyCamera(aspect, 0));
            const ViewUpload fullFirst(*soft, fullScene, fullScene.dollyCamera(aspect, 0));
            for (Subject& s : subjects)
                if (s.lod.technique->needsHistory())
                    for (std::uint64_t i = 0; i < kHistoryFrames; ++i) {
                        s.lod.drawer->draw(*s.lod.targets, s.lod.technique.get(), lodFirst, i, i == 0);
                        s.full.drawer->draw(*s.full.targets, s.full.technique.get(), fullFirst, i, i == 0);
                    }
        }
        for (int k = 0; k < frames; ++k) {
            std::printf("[ssam-bench] %-6s dolly frame %d/%d\n", sceneName(kind), k + 1, frames);
            std::fflush(stdout);
            const ViewUpload lodView(*soft, lodScene, lodScene.dollyCamera(aspect, k));
            const ViewUpload fullView(*soft, fullScene, fullScene.dollyCamera(aspect, k));
            opaqueDrawer.draw(opaqueTargets, nullptr, fullView);
            const Image opaque = engine::capture::imageFromReadback(soft->readback(opaqueTargets.color()));
            for (Subject& s : subjects) {
                const std::uint64_t index = (s.lod.technique->needsHistory() ? kHistoryFrames : 0) + std::uint64_t(k);
                const Image lod = drawFrame(*soft, s.lod, lodView, index);
                const Image full = drawFrame(*soft, s.full, fullView, index);
                Image plants = Image::make(o.width, o.height, 1);
                for (int y = 0; y < o.height; ++y)
                    for (int x = 0; x < o.width; ++x)
                        for (int c = 0; c < 3; ++c)
                            if (lod.at(x, y, c) != opaque.at(x, y, c) || full.at(x, y, c) != opaque.at(x, y, c)) {
                                plants.at(x, y, 0) = 1.0f;
                                break;
                            }
                double frameFlip = 0.0;
                const double lodFlip = flipOver(full, lod, plants, {}, &frameFlip);
                s.lodFlipSum += lodFlip;
                s.lodFrameFlipSum += frameFlip;
                s.row.lodFlipWorst = std::max(s.row.lodFlipWorst, lodFlip);
                DollyFrame& measured = s.row.perFrame.emplace_back();
                measured.lodFlip = lodFlip;
                if (k > 0) {
                    Image lodMap, fullMap;
                    engine::capture::flip(s.lod.last, lod, {}, &lodMap);
                    engine::capture::flip(s.full.last, full, {}, &fullMap);
                    const double change = meanOver(lodMap, plants, s.lastPlants);
                    // Per pixel, what the levels add to the motion's own change.
                    for (std::size_t i = 0; i < lodMap.pixels.size(); ++i)
                        lodMap.pixels[i] = std::max(0.0f, lodMap.pixels[i] - fullMap.pixels[i]);
                    const double excess = meanOver(lodMap, plants, s.lastPlants);
                    measured.change = change;
                    measured.excess = excess;
                    if (change > s.row.pop) s.row.pop = change, s.row.popFrame = k;
                    if (excess > s.row.popLod) s.row.popLod = excess, s.row.popLodFrame = k;
                }
                s.lod.last = lod;
                s.full.last = full;
                s.lastPlants = std::move(plants);
            }
        }
        for (Subject& s : subjects) {
            s.row.frames = frames;
            s.row.lodFlipMean = s.lodFlipSum / double(frames);
            s.row.lodFrameFlipMean = s.lodFrameFlipSum / double(frames);
            std::vector<double> excess;
            for (const DollyFrame& f : s.row.perFrame)
                if (has(f.excess)) excess.push_back(f.excess);
            s.row.popLodMedian = median(excess);
            rows.push_back(s.row);
        }
    }
    return rows;
}

void writeDollyCsv(std::ostream& out, const std::vector<DollyRow>& rows) {
    out << "scene,technique,backend,frames,step_m,crossfade,pop_flip,pop_frame,pop_lod_flip,pop_lod_frame,"
           "lod_flip_mean,lod_flip_worst,lod_frame_flip_mean,pop_lod_median\n";
    for (const DollyRow& r : rows)
        out << formatted("%s,%s,%s,%d,%.2f,%.2f,%.5f,%d,%.5f,%d,%.5f,%.5f,%.5f,%.5f\n", r.scene.c_str(),
                         r.technique.c_str(), r.backend.c_str(), r.frames, double(kDollyStep), double(r.crossfade),
                         r.pop, r.popFrame, r.popLod, r.popLodFrame, r.lodFlipMean, r.lodFlipWorst, r.lodFrameFlipMean,
                         r.popLodMedian);
}

void writeDollyFramesCsv(std::ostream& out, const std::vector<DollyRow>& rows) {
    out << "scene,technique,frame,change_flip,lod_excess_flip,lod_flip\n";
    for (const DollyRow& r : rows)
        for (std::size_t k = 0; k < r.perFrame.size(); ++k) {
            const DollyFrame& f = r.perFrame[k];
            out << r.scene << "," << r.technique << "," << k << "," << num(f.change, "%.5f") << ","
                << num(f.excess, "%.5f") << "," << num(f.lodFlip, "%.5f") << "\n";
        }
}

void printDollyTable(const std::vector<DollyRow>& rows) {
    std::printf("%-8s %-14s %9s %9s %14s %13s %14s %19s\n", "scene", "technique", "pop", "pop_lod", "pop_lod_median",
                "lod_flip_mean", "lod_flip_worst", "lod_frame_flip_mean");
    for (const DollyRow& r : rows)
        std::printf("%-8s %-14s %9.4f %9.4f %14.4f %13.4f %14.4f %19.4f\n", r.scene.c_str(), r.technique.c_str(), r.pop,
                    r.popLod, r.popLodMedian, r.lodFlipMean, r.lodFlipWorst, r.lodFrameFlipMean);
}

}  // namespace bench
