// SPDX-License-Identifier: MIT
// modules/lightshafts: what the sun-visibility query saves when the sun is hidden and costs
// when it is not, on the soft backend at 1280x720 (one frame's light-shaft work: the probe
// pass and the shaft pass, or the shaft pass alone with the probe off).
//   build/bin/bench_lightshafts --benchmark_min_time=0.5 --benchmark_repetitions=3
// Args: sun hidden (a canopy's depth over the whole glow) or seen; probe on or off.
#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/render/projection.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/render/vertex.hpp"
#include "lightshafts/light_shaft_feature.hpp"
#include "run_feature.hpp"

namespace {

using namespace engine;
using namespace engine::render;

constexpr int kWidth = 1280, kHeight = 720;

void shaftsFrame(benchmark::State& state) {
    const bool sunHidden = state.range(0) != 0, probe = state.range(1) != 0;
    auto backend = soft::createSoftBackend({0, 64, false});
    scene::MeshLibrary library(*backend);
    const scene::DrawLists lists;
    const TextureHandle color =
        backend->createTexture(renderTargetDesc("colour", kWidth, kHeight, Format::RGBA8_UNORM));
    const TextureHandle depth = backend->createTexture(renderTargetDesc("depth", kWidth, kHeight, Format::D32F));

    // Reverse-Z as the racer: sky is the clear value 0; the canopy is a quad at depth 0.5
    // over the middle 70% of the frame (the sun's glow, 0.3 of the height, fits inside).
    PipelineDesc canopyPipeline;
    canopyPipeline.name = "canopy";
    canopyPipeline.depth = DepthState::testAndWrite(CompareFunc::Greater);
    const PipelineHandle canopy = backend->createPipeline(canopyPipeline);
    std::vector<Vertex> quad(6);
    const glm::vec2 corners[6] = {{-0.7f, -0.7f}, {0.7f, -0.7f}, {0.7f, 0.7f},
                                  {-0.7f, -0.7f}, {0.7f, 0.7f},  {-0.7f, 0.7f}};
    for (int i = 0; i < 6; ++i) quad[i].position = {corners[i], 0.5f};
    const auto bytes = std::as_bytes(std::span(quad));
    const BufferHandle quadBuffer = backend->createBuffer({"canopy quad", BufferKind::Vertex, bytes.size()}, bytes);
    PassDesc scene;
    scene.name = "scene";
    scene.color[0] = {color, LoadOp::Clear, {0.5f, 0.6f, 0.8f, 1.0f}};
    scene.depth = {depth, LoadOp::Clear, 0.0f};
    backend->beginPass(scene);
    if (sunHidden) {
        DrawDesc d;
        d.pipeline = canopy;
        d.vertices = quadBuffer;
        d.count = 6;
        backend->draw(d);
    }
    backend->endPass();

    lightshafts::LightShaftOptions options;
    options.skipWhenSunHidden = probe;
    lightshafts::LightShaftFeature shafts(*backend, options);
    const glm::mat4 projection = perspectiveReverseZ(1.0f, float(kWidth) / kHeight, 0.1f, 30000.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), glm::vec3(0, 0, 1), glm::vec3(0, 1, 0));
    DirectionalLight sun;
    sun.towardLight = {0.0f, 0.0f, 1.0f};  // straight ahead: the frame's centre
    const scene::FeatureFrame frame{*backend,
                                    library,
                                    lists,
                                    color,
                                    depth,
                                    kWidth,
                                    kHeight,
                                    view,
                                    projection,
                                    projection * view,
                                    glm::vec3(0.0f),
                                    sun,
                                    0.0f,
                                    CompareFunc::Greater};
    backend->takeTimings();
    bool skipped = false;
    for (auto _ : state) {
        test_support::runFeatures({&shafts}, frame);
        for (const PassTiming& t : backend->takeTimings())
            if (t.pass == "light shafts") skipped = t.skipped;
    }
    state.counters["shaft pass skipped"] = skipped ? 1.0 : 0.0;
    backend->destroy(quadBuffer);
    backend->destroy(canopy);
    backend->destroy(color);
    backend->destroy(depth);
}

BENCHMARK(shaftsFrame)
    ->ArgNames({"sunHidden", "probe"})
    ->Args({1, 1})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({0, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
