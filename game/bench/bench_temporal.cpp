// SPDX-License-Identifier: MIT
#include "bench_temporal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "bench_frame.hpp"
#include "foliage_errors.hpp"
#include "engine/capture/metrics.hpp"
#include "engine/capture/readback_image.hpp"
#include "engine/render/frame_targets.hpp"

namespace bench {

using namespace engine::render;
using engine::capture::Image;

namespace {

// One technique on one backend through the whole pan.
struct Subject {
    BenchRow* row = nullptr;
    std::size_t backend = 0;
    std::unique_ptr<transparency::Technique> technique;
    std::unique_ptr<FrameTargets> targets;
    std::unique_ptr<FrameDrawer> drawer;
    std::vector<double> flip, rmse;
};

Image draw(Backend& backend, FrameDrawer& drawer, FrameTargets& targets, transparency::Technique* technique,
           const ViewUpload& view, std::uint64_t index) {
    drawer.draw(targets, technique, view, index, index == 0);
    backend.takeTimings();
    return engine::capture::imageFromReadback(backend.readback(targets.color()));
}

}  // namespace

void measureTemporal(const std::vector<TemporalBackend>& backends, const BenchOptions& o, std::vector<BenchRow>& rows) {
    if (o.temporalFrames <= 0 || backends.empty() || !backends.front().scene->hasPan()) return;
    const float aspect = float(o.width) / float(o.height);
    Backend& soft = *backends.front().backend;
    BenchScene& softScene = *backends.front().scene;
    const std::string scene = sceneName(softScene.kind());
    auto withDepth = [](transparency::TechniqueOptions options) {
        options.depthFunc = kDepthFunc;
        return options;
    };

    // The judges: the reference and the opaque-only frame, on the soft backend.
    auto reference = transparency::createTechnique(transparency::TechniqueKind::Reference, soft, withDepth({}));
    FrameTargets referenceTargets(soft, {o.width, o.height, 1, Format::RGBA8_SRGB, kDepthFunc});
    FrameTargets opaqueTargets(soft, {o.width, o.height, 1, Format::RGBA8_SRGB, kDepthFunc});
    FrameDrawer softDrawer(soft, softScene.library());

    std::vector<Subject> subjects;
    for (const BenchSubject& s : o.subjects) {
        if (!s.kind) continue;  // opaque-only: the judge of which pixels are foliage
        for (std::size_t b = 0; b < backends.size(); ++b) {
            BenchRow* row = nullptr;
            for (BenchRow& r : rows)
                if (r.scene == scene && r.technique == s.name && r.backend == backends[b].name && r.ran) row = &r;
            if (!row) continue;  // skipped in the comparison run: the note says why
            Subject subject;
            subject.row = row;
            subject.backend = b;
            try {
                Backend& backend = *backends[b].backend;
                subject.technique = transparency::createTechnique(*s.kind, backend, withDepth(s.options));
                subject.targets = std::make_unique<FrameTargets>(
                    backend, FrameTargetsDesc{o.width, o.height, subject.technique->opaqueSamples(), Format::RGBA8_SRGB,
                                              kDepthFunc});
                subject.drawer = std::make_unique<FrameDrawer>(backend, backends[b].scene->library());
            } catch (const std::exception& e) {
                row->note += std::string(row->note.empty() ? "" : "; ") + "no temporal measure: " + e.what();
                continue;
            }
            subjects.push_back(std::move(subject));
        }
    }

    // History first, on the pan's first view.
    std::vector<std::unique_ptr<ViewUpload>> first;
    first.reserve(backends.size());
    for (const TemporalBackend& b : backends)
        first.push_back(std::make_unique<ViewUpload>(*b.backend, *b.scene, b.scene->panCamera(aspect, 0)));
    for (Subject& s : subjects)
        if (s.technique->needsHistory())
            for (std::uint64_t i = 0; i < kHistoryFrames; ++i)
                s.drawer->draw(*s.targets, s.technique.get(), *first[s.backend], i, i == 0);
    first.clear();

    for (int k = 0; k < o.temporalFrames; ++k) {
        std::printf("[ssam-bench] %-6s temporal frame %d/%d\n", scene.c_str(), k + 1, o.temporalFrames);
        std::fflush(stdout);
        std::vector<std::unique_ptr<ViewUpload>> views;
        views.reserve(backends.size());
        for (const TemporalBackend& b : backends)
            views.push_back(std::make_unique<ViewUpload>(*b.backend, *b.scene, b.scene->panCamera(aspect, k)));
        const Image ref = draw(soft, softDrawer, referenceTargets, reference.get(), *views.front(), 0);
        const Image opaque = draw(soft, softDrawer, opaqueTargets, nullptr, *views.front(), 0);
        // Foliage pixels: where the reference differs from the opaque-only frame.
        std::size_t foliageCount = 0;
        const std::vector<char> foliage = foliagePixels(ref, opaque, foliageCount);
        if (foliageCount == 0) continue;  // nothing to judge in this frame
        for (Subject& s : subjects) {
            const std::uint64_t index = (s.technique->needsHistory() ? kHistoryFrames : 0) + std::uint64_t(k);
            const Image image =
                draw(*backends[s.backend].backend, *s.drawer, *s.targets, s.technique.get(), *views[s.backend], index);
            const FoliageError error = foliageError(ref, image, foliage, foliageCount);
            s.flip.push_back(error.flip);
            s.rmse.push_back(error.rmse);
        }
    }
    for (Subject& s : subjects) {
        s.row->temporalFrames = int(s.flip.size());
        summarize(s.flip, s.row->temporalFlip, s.row->temporalFlipWorst);
        summarize(s.rmse, s.row->temporalRmse, s.row->temporalRmseWorst);
    }
}

}  // namespace bench
