// SPDX-License-Identifier: MIT
// modules/wind: deformed vertices per second, for 1 and 2 oneTBB threads.
//   build/bin/bench_wind --benchmark_counters_tabular=true
// 64 or 1024 content trees (tree_broadleaf.glb, 188 vertices each), all within the active radius, swaying and pushed
// by a collider; the counter `vertices/s` is deformed vertices per second of wall time,
// including the buffer uploads to the soft backend.
#include <benchmark/benchmark.h>

#include <filesystem>

#include <tbb/task_arena.h>

#include "engine/assets/gltf.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "wind/wind_system.hpp"

namespace {

using namespace engine;

void deformForest(benchmark::State& state) {
    const int threads = int(state.range(0)), plants = int(state.range(1));
    auto backend = render::soft::createSoftBackend({threads, 64, false});
    scene::MeshLibrary library(*backend);
    ecs::Registry registry;
    const scene::ModelId tree =
        library.add(assets::loadGltf(std::filesystem::path(SSAM_SOURCE_DIR) / "content/models/tree_broadleaf.glb"));
    for (int i = 0; i < plants; ++i) {
        const ecs::Entity e = registry.create();
        registry.add<scene::Transform>(e, scene::Transform{{float(i % 32) * 4.0f, 0.0f, float(i / 32) * 4.0f}});
        registry.add<scene::Renderable>(e, scene::Renderable{tree});
    }
    const ecs::Entity car = registry.create();
    registry.add<scene::Transform>(car);
    registry.add<scene::Collider>(car, scene::Collider{2.5f});
    wind::Wind storm;
    storm.activeRadius = 1000.0f;
    registry.add<wind::Wind>(registry.create(), storm);
    wind::WindSystem system(library);
    system.attach(registry);
    tbb::task_arena arena(threads);
    float time = 0.0f;
    std::size_t vertices = 0;
    for (auto _ : state) {
        registry.get<scene::Transform>(car).position = {std::fmod(time * 10.0f, 128.0f), 1.0f, 6.0f};
        system.setFrame({time, 1.0f / 60.0f, {14.0f, 5.0f, -20.0f}, glm::mat4(1.0f), false});
        arena.execute([&] { system.update(registry); });
        vertices += system.stats().verticesDeformed;
        time += 1.0f / 60.0f;
    }
    state.counters["vertices/s"] = benchmark::Counter(double(vertices), benchmark::Counter::kIsRate);
    state.counters["vertices/frame"] = double(system.stats().verticesDeformed);
}
BENCHMARK(deformForest)
    ->ArgsProduct({{1, 2}, {64, 1024}})
    ->ArgNames({"threads", "plants"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
