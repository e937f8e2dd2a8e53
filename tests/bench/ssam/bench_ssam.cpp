// SPDX-License-Identifier: MIT
// "Skip verified by benchmark": what SSAM costs a frame on the soft backend at 1280x720 when no
// foliage is in view (nothing: no pass runs, no target is allocated) and when it is.
//   OpaqueOnly        the opaque pass alone: clear + 8 overlapping opaque quads (Flat, depth)
//   SsamNoFoliage     the same, then SSAM's passes in a frame graph with 24 foliage batches all
//                     outside the view volume (behind the camera or off to the side)
//   SsamWithFoliage   the same, with the 24 batches in view: crossing vertex-coloured cards of
//                     alpha 0.15-0.85 covering about 40% of the screen, 3 passes
// The argument is SoftOptions::threads (1 and 2). Wall-clock time (UseRealTime): the work runs
// on TBB workers. Compare the three at the same thread count from one run.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "engine/render/frame_targets.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/render/frame_graph/transient_texture_pool.hpp"
#include "quad_scene.hpp"
#include "run_ssam.hpp"

namespace {

using namespace engine::render;
using ssam::testing::Quad;
using ssam::testing::QuadBatches;

constexpr int kWidth = 1280, kHeight = 720;

enum class Case { OpaqueOnly, SsamNoFoliage, SsamWithFoliage };

std::vector<Quad> opaqueQuads() {
    std::vector<Quad> quads{{-1, -1, 1, 1, 0.95f, {0.2f, 0.4f, 0.6f, 1}}};  // far background
    for (int i = 0; i < 7; ++i) {
        const float x = -1.0f + 0.25f * float(i);
        quads.push_back({x, -1.0f, x + 0.6f, 0.2f, 0.6f + 0.04f * float(i), {0.3f, 0.25f, 0.2f, 1}});
    }
    return quads;
}

std::vector<Quad> foliageQuads(bool inView) {
    std::vector<Quad> quads;
    for (int i = 0; i < 24; ++i) {
        const float x = -0.9f + 0.07f * float(i), y = -0.6f + 0.03f * float(i % 5);
        const float alpha = 0.15f + 0.7f * float(i % 6) / 5.0f;
        Quad q{x, y, x + 0.35f, y + 0.7f, 0.3f + 0.01f * float(i), {0.2f, 0.6f, 0.15f, alpha}};
        if (!inView) {
            if (i % 2) q.depth = -0.5f;       // behind the camera
            else q.x0 += 3.0f, q.x1 += 3.0f;  // off to the right
        }
        quads.push_back(q);
    }
    return quads;
}

void frame(benchmark::State& state, Case c) {
    auto backend = soft::createSoftBackend({static_cast<int>(state.range(0))});
    engine::render::FrameTargets opaque(*backend, {kWidth, kHeight, 1, Format::RGBA8_SRGB, CompareFunc::Less});
    ssam::ScreenSpaceAlphaMask ssam(*backend);
    PipelineDesc p;
    p.name = "opaque flat";
    p.depth = DepthState::testAndWrite();
    const PipelineHandle pipeline = backend->createPipeline(p);
    QuadBatches scene(*backend, opaqueQuads());
    QuadBatches foliage(*backend, foliageQuads(c == Case::SsamWithFoliage));
    const ssam::FoliageView view{glm::mat4(1.0f), DirectionalLight{}, foliage.batches};
    TransientTexturePool pool(*backend);  // kept across frames, as the racer's
    int passesRun = 0;
    for (auto _ : state) {
        backend->beginPass(opaque.passDesc({0.5f, 0.6f, 0.8f, 1.0f}));
        scene.drawFlat(pipeline);
        backend->endPass();
        if (c != Case::OpaqueOnly)
            passesRun =
                test_support::runSsam(ssam, {opaque.color(), opaque.depth()}, view, false, &pool).report.passesRun;
        benchmark::DoNotOptimize(soft::softDriver(*backend).stats().passes);
    }
    (void)backend->readback(opaque.color());  // the frames are finished
    state.counters["ssam_passes"] = passesRun;
    state.counters["frames/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    backend->destroy(pipeline);
}

void BM_OpaqueOnly(benchmark::State& state) { frame(state, Case::OpaqueOnly); }
void BM_SsamNoFoliage(benchmark::State& state) { frame(state, Case::SsamNoFoliage); }
void BM_SsamWithFoliage(benchmark::State& state) { frame(state, Case::SsamWithFoliage); }

BENCHMARK(BM_OpaqueOnly)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SsamNoFoliage)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SsamWithFoliage)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
