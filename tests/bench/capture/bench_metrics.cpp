// SPDX-License-Identifier: MIT
// Timings of the benchmark's image metrics on a 1280x720 RGBA pair. Arg 0: one thread,
// arg 1: oneTBB's default parallelism.
#include <benchmark/benchmark.h>

#include <tbb/global_control.h>

#include <cmath>
#include <memory>
#include <random>

#include "engine/capture/metrics.hpp"

using namespace engine::capture;

namespace {

struct Pair {
    Image reference, test;
};

const Pair& pair() {
    static const Pair p = [] {
        Pair out{Image::make(1280, 720, 4), Image::make(1280, 720, 4)};
        std::mt19937 rng(7);
        std::normal_distribution<float> noise(0.0f, 0.02f);
        for (int y = 0; y < 720; ++y)
            for (int x = 0; x < 1280; ++x)
                for (int c = 0; c < 4; ++c) {
                    const float v = c == 3 ? 1.0f : 0.5f + 0.4f * std::sin(0.01f * static_cast<float>(x * (c + 1) + y));
                    out.reference.at(x, y, c) = v;
                    out.test.at(x, y, c) = c == 3 ? v : v + noise(rng);
                }
        return out;
    }();
    return p;
}

std::unique_ptr<tbb::global_control> threads(const benchmark::State& state) {
    if (state.range(0) != 0) return nullptr;
    return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, 1);
}

template <double (*Metric)(const Image&, const Image&)>
void run(benchmark::State& state) {
    const Pair& p = pair();
    const auto control = threads(state);
    for (auto _ : state) benchmark::DoNotOptimize(Metric(p.reference, p.test));
}

double flipDefault(const Image& a, const Image& b) { return flip(a, b); }

void BM_Flicker(benchmark::State& state) {
    const Pair& p = pair();
    const std::vector<Image> frames{p.reference, p.test};
    const auto control = threads(state);
    for (auto _ : state) benchmark::DoNotOptimize(temporalFlicker(frames));
}

void BM_All(benchmark::State& state) {
    const Pair& p = pair();
    const std::vector<Image> frames{p.reference, p.test};
    const auto control = threads(state);
    for (auto _ : state) {
        benchmark::DoNotOptimize(rmseLinear(p.reference, p.test));
        benchmark::DoNotOptimize(psnrLinear(p.reference, p.test));
        benchmark::DoNotOptimize(rmseSrgb(p.reference, p.test));
        benchmark::DoNotOptimize(psnrSrgb(p.reference, p.test));
        benchmark::DoNotOptimize(ssim(p.reference, p.test));
        benchmark::DoNotOptimize(flip(p.reference, p.test));
        benchmark::DoNotOptimize(temporalFlicker(frames));
    }
}

}  // namespace

BENCHMARK(run<rmseLinear>)->Name("rmseLinear")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(run<rmseSrgb>)->Name("rmseSrgb")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(run<ssim>)->Name("ssim")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(run<flipDefault>)->Name("flip")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Flicker)->Name("temporalFlicker(2 frames)")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_All)->Name("all metrics")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
