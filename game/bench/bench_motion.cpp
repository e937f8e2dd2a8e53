// SPDX-License-Identifier: MIT
#include "bench_motion.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

#include "bench_frame.hpp"
#include "engine/capture/metrics.hpp"
#include "engine/capture/readback_image.hpp"
#include "engine/core/usage_error.hpp"
#include "engine/render/devices/create_device.hpp"
#include "engine/render/frame_targets.hpp"
#include "engine/scene/rigid_motion.hpp"
#include "foliage_errors.hpp"
#include "report_text.hpp"
#if SSAM_BENCH_WIND
#include "wind/wind.hpp"
#include "wind/wind_system.hpp"
#endif

namespace bench {

using namespace engine::render;
using engine::capture::Image;

namespace {

constexpr float kWindStep = 1.0f / 60.0f;  // seconds a frame: the racer's fixed step

// One technique (or the reference) through the motion.
struct Subject {
    MotionRow row;
    std::unique_ptr<transparency::Technique> technique;
    std::unique_ptr<FrameTargets> targets;
    std::unique_ptr<FrameDrawer> drawer;
    std::vector<double> flip, rmse, ghost;
    Image last;  // the frame before, for the flicker
    double flickerSum = 0.0;
    int flickerPairs = 0;

    Image draw(Backend& backend, const ViewUpload& view, std::uint64_t index) {
        drawer->draw(*targets, technique.get(), view, index, index == 0);
        backend.takeTimings();
        Image image = engine::capture::imageFromReadback(backend.readback(targets->color()));
        if (!last.pixels.empty()) {
            flickerSum += engine::capture::temporalFlicker({last, image});
            ++flickerPairs;
        }
        last = image;
        return image;
    }
    double flicker() const { return flickerPairs ? flickerSum / double(flickerPairs) : 0.0; }
};

Subject makeSubject(Backend& backend, const BenchScene& scene, const BenchOptions& o, transparency::TechniqueKind kind,
                    transparency::TechniqueOptions options) {
    options.depthFunc = kDepthFunc;
    Subject s;
    s.technique = transparency::createTechnique(kind, backend, options);
    s.targets = std::make_unique<FrameTargets>(
        backend, FrameTargetsDesc{o.width, o.height, s.technique->opaqueSamples(), Format::RGBA8_SRGB, kDepthFunc});
    s.drawer = std::make_unique<FrameDrawer>(backend, scene.library());
    return s;
}

bool hasMotion(const BenchScene& scene, Motion motion) {
    switch (motion) {
        case Motion::Pan: return scene.hasPan();
        case Motion::Dolly: return scene.hasDolly();
        case Motion::Car: return scene.hasCar();
        case Motion::Wind: break;
    }
    return true;
}

// The mean of `map` over the pixels set in `mask`; nullopt without any.
std::optional<double> meanOver(const Image& map, const std::vector<char>& mask) {
    double sum = 0.0;
    std::size_t n = 0;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            if (mask[std::size_t(y) * map.width + x]) sum += map.at(x, y, 0), ++n;
    if (n == 0) return std::nullopt;
    return sum / double(n);
}

// One scene through one motion: a row per subject.
void measure(Backend& soft, SceneKind kind, Motion motion, const BenchOptions& o, int frames, bool motionVectors,
             std::vector<MotionRow>& rows) {
    BenchScene scene(soft, kind, o.contentDir);
    if (!hasMotion(scene, motion)) return;
    if (o.levelsOfDetail) scene.useLevelsOfDetail(o.height, o.crossfade);
#if SSAM_BENCH_WIND
    std::optional<wind::WindSystem> windSystem;
    if (motion == Motion::Wind) {
        scene.registry().add<wind::Wind>(scene.registry().create());
        windSystem.emplace(scene.library());
        windSystem->attach(scene.registry());
    }
#endif
    std::optional<engine::ecs::Entity> car;
    engine::scene::RigidMotion carMotion(scene.library());
    if (motion == Motion::Car) car = scene.addCar();
    const float aspect = float(o.width) / float(o.height);
    auto cameraAt = [&](int k) {
        switch (motion) {
            case Motion::Pan: return scene.panCamera(aspect, k);
            case Motion::Dolly: return scene.dollyCamera(aspect, kDollyFrames - frames + k);
            case Motion::Wind:
            case Motion::Car: break;
        }
        return scene.camera(aspect);
    };

    Subject reference = makeSubject(soft, scene, o, transparency::TechniqueKind::Reference, {});
    FrameTargets opaqueTargets(soft, {o.width, o.height, 1, Format::RGBA8_SRGB, kDepthFunc});
    FrameDrawer opaqueDrawer(soft, scene.library());
    std::vector<Subject> subjects;
    for (const BenchSubject& b : o.subjects) {
        if (!b.kind) continue;
        transparency::TechniqueOptions options = b.options;
        options.temporal.motionVectors = motionVectors;
        subjects.push_back(makeSubject(soft, scene, o, *b.kind, options));
        subjects.back().row = {sceneName(kind), motionName(motion), b.name};
        subjects.back().row.motionVectors = motionVectors;
    }
    std::printf("[ssam-bench] %s %s: %d frames, %zu technique(s), motion vectors %s\n", sceneName(kind),
                motionName(motion), frames, subjects.size(), motionVectors ? "on" : "off");

    // The wind makes its motion copies only for a technique that reads them (racer's rule).
    [[maybe_unused]] const bool readsMotion = std::any_of(
        subjects.begin(), subjects.end(), [](const Subject& s) { return s.technique->needsMotionVectors(); });
    Image lastReference;
    std::vector<char> lastFoliage;
    for (int j = 0; j < kHistoryFrames + frames; ++j) {
        const bool measured = j >= kHistoryFrames;
        const int k = measured ? j - kHistoryFrames : 0;
        const BenchCamera camera = cameraAt(k);
        std::string bent;
#if SSAM_BENCH_WIND
        if (windSystem) {
            windSystem->setFrame({float(j) * kWindStep, kWindStep, camera.eye, camera.viewProj, true, readsMotion});
            windSystem->update(scene.registry());
            bent = ", " + std::to_string(windSystem->stats().plantsDeformed) + " plants bent";
        }
#endif
        if (car) {  // the racer's order: move, then the motion copies, then extraction
            scene.placeCar(*car, j);
            carMotion.update(scene.registry(), readsMotion);
        }
        const ViewUpload view(soft, scene, camera);
        if (!measured) {  // history, for the techniques that keep it
            for (Subject& s : subjects)
                if (s.technique->needsHistory())
                    s.drawer->draw(*s.targets, s.technique.get(), view, std::uint64_t(j), j == 0);
            continue;
        }
        std::printf("[ssam-bench] %-6s %s frame %d/%d%s\n", sceneName(kind), motionName(motion), k + 1, frames,
                    bent.c_str());
        std::fflush(stdout);
        const Image ref = reference.draw(soft, view, 0);
        opaqueDrawer.draw(opaqueTargets, nullptr, view);
        const Image opaque = engine::capture::imageFromReadback(soft.readback(opaqueTargets.color()));
        std::size_t foliageCount = 0;
        const std::vector<char> foliage = foliagePixels(ref, opaque, foliageCount);
        // Moved pixels: foliage now or before, whose reference changed visibly.
        std::vector<char> moved(foliage.size(), 0);
        if (!lastReference.pixels.empty()) {
            Image change;
            engine::capture::flip(lastReference, ref, {}, &change);
            for (int y = 0; y < o.height; ++y)
                for (int x = 0; x < o.width; ++x) {
                    const std::size_t i = std::size_t(y) * o.width + x;
                    moved[i] = (car.has_value() || foliage[i] || lastFoliage[i]) && change.at(x, y, 0) > kMovedFlip;
                }
        }
        for (Subject& s : subjects) {
            const std::uint64_t index = std::uint64_t(s.technique->needsHistory() ? j : k);
            const Image image = s.draw(soft, view, index);
            if (foliageCount == 0) continue;  // nothing to judge in this frame
            Image map;
            const FoliageError error = foliageError(ref, image, foliage, foliageCount, &map);
            s.flip.push_back(error.flip);
            s.rmse.push_back(error.rmse);
            if (const std::optional<double> ghost = meanOver(map, moved)) s.ghost.push_back(*ghost);
        }
        lastReference = ref;
        lastFoliage = foliage;
    }
    for (Subject& s : subjects) {
        s.row.frames = int(s.flip.size());
        s.row.ghostFrames = int(s.ghost.size());
        s.row.flicker = s.flicker() - reference.flicker();
        summarize(s.flip, s.row.flip, s.row.flipWorst);
        summarize(s.rmse, s.row.rmse, s.row.rmseWorst);
        summarize(s.ghost, s.row.ghost, s.row.ghostWorst);
        rows.push_back(s.row);
    }
}

}  // namespace

std::vector<Motion> parseMotions(std::string_view list) {
    std::vector<Motion> motions;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = list.find(',', start);
        const std::string_view name = list.substr(start, comma == std::string_view::npos ? list.npos : comma - start);
        Motion m;
        if (name == "pan") m = Motion::Pan;
        else if (name == "dolly") m = Motion::Dolly;
        else if (name == "wind") m = Motion::Wind;
        else if (name == "car") m = Motion::Car;
        else throw engine::UsageError("--motion: '" + std::string(name) + "' is not one of pan, dolly, wind, car");
#if !SSAM_BENCH_WIND
        if (m == Motion::Wind) throw engine::UsageError("--motion: 'wind' needs modules/wind, left out of this build");
#endif
        if (std::find(motions.begin(), motions.end(), m) != motions.end())
            throw engine::UsageError("--motion: '" + std::string(name) + "' given twice");
        motions.push_back(m);
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return motions;
}

std::vector<Motion> availableMotions() {
#if SSAM_BENCH_WIND
    return {Motion::Pan, Motion::Dolly, Motion::Wind, Motion::Car};
#else
    return {Motion::Pan, Motion::Dolly, Motion::Car};
#endif
}

const char* motionName(Motion motion) {
    switch (motion) {
        case Motion::Pan: return "pan";
        case Motion::Dolly: return "dolly";
        case Motion::Wind: return "wind";
        case Motion::Car: return "car";
    }
    return "?";
}

std::vector<MotionRow> runMotion(const BenchOptions& o, const std::vector<Motion>& motions, int frames,
                                 bool motionVectors) {
    frames = std::clamp(frames, 2, kDollyFrames);
    const int threads = resolvedThreads(o.threads);
    DeviceOptions deviceOptions;
    deviceOptions.threads = threads;
    deviceOptions.soft = {.threads = threads, .tileSize = 64, .simd = o.simd};
    std::unique_ptr<Device> soft = createDevice(DeviceKind::Soft, deviceOptions);
    std::vector<MotionRow> rows;
    for (SceneKind kind : o.scenes)
        for (Motion motion : motions) measure(*soft, kind, motion, o, frames, motionVectors, rows);
    return rows;
}

void writeMotionCsv(std::ostream& out, const std::vector<MotionRow>& rows) {
    out << "scene,motion,technique,backend,motion_vectors,frames,flicker,flip,flip_worst,rmse,rmse_worst,"
           "ghost_frames,ghost,ghost_worst\n";
    for (const MotionRow& r : rows)
        out << formatted("%s,%s,%s,%s,%s,%d,%.5f,%.5f,%.5f,%.5f,%.5f,%d,%.5f,%.5f\n", r.scene.c_str(), r.motion.c_str(),
                         r.technique.c_str(), r.backend.c_str(), r.motionVectors ? "on" : "off", r.frames, r.flicker,
                         r.flip, r.flipWorst, r.rmse, r.rmseWorst, r.ghostFrames, r.ghost, r.ghostWorst);
}

void printMotionTable(const std::vector<MotionRow>& rows) {
    std::printf("%-7s %-6s %-15s %9s %8s %10s %8s %10s %8s %11s\n", "scene", "motion", "technique", "flicker", "flip",
                "flip_worst", "rmse", "rmse_worst", "ghost", "ghost_worst");
    for (const MotionRow& r : rows)
        std::printf("%-7s %-6s %-15s %9.5f %8.4f %10.4f %8.4f %10.4f %8.4f %11.4f\n", r.scene.c_str(), r.motion.c_str(),
                    r.technique.c_str(), r.flicker, r.flip, r.flipWorst, r.rmse, r.rmseWorst, r.ghost, r.ghostWorst);
}

}  // namespace bench
