// SPDX-License-Identifier: MIT
// ECS iteration cost per entity against a plain std::vector<struct> loop doing the
// same work, over 1M entities with 1, 2 and 3 components (every entity has all of
// them). "time/entity" is the per-entity cost; compare EcsN_* with PlainN.
//   Ecs*_Each       view.each(lambda): the intended hot path
//   Ecs*_RangeFor   for (auto [e, ...] : view)
//   Ecs2_Each_Shuffled  Velocity added in random order, so the pools' dense arrays
//                       do not line up and every entity costs a sparse lookup
// Every loop's length is a runtime value (entityCount()), as in real code: with a
// compile-time 1'000'000 GCC -O2 vectorizes the plain loop only because it can
// prove the count is a multiple of the vector width, which no ECS, and no engine
// loop over a dynamic set, can offer.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <random>
#include <vector>

#include "engine/core/ecs/registry.hpp"

namespace {

using engine::ecs::Entity;
using engine::ecs::Registry;

constexpr std::size_t kEntities = 1'000'000;

std::size_t entityCount() {
    std::size_t count = kEntities;
    benchmark::DoNotOptimize(count);  // opaque to the optimizer
    return count;
}
constexpr float kDt = 1.0f / 60.0f;

struct Position {
    float x = 0, y = 0, z = 0;
};
struct Velocity {
    float x = 1, y = 2, z = 3;
};
struct Acceleration {
    float x = 0.5f, y = -9.8f, z = 0.25f;
};

// The work, shared by ECS and plain loops so only the data access differs.
inline void drift(Position& p) {
    p.x += 1.0f * kDt;
    p.y += 2.0f * kDt;
    p.z += 3.0f * kDt;
}
inline void integrate(Position& p, const Velocity& v) {
    p.x += v.x * kDt;
    p.y += v.y * kDt;
    p.z += v.z * kDt;
}
inline void integrate(Position& p, Velocity& v, const Acceleration& a) {
    v.x += a.x * kDt;
    v.y += a.y * kDt;
    v.z += a.z * kDt;
    integrate(p, v);
}

void report(benchmark::State& state) {
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kEntities));
    state.counters["time/entity"] = benchmark::Counter(
        static_cast<double>(kEntities), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Times `pass` (one pass over every entity) and reports the rate per entity.
template <typename Pass>
void measure(benchmark::State& state, Pass&& pass) {
    for (auto _ : state) {
        pass();
        benchmark::ClobberMemory();
    }
    report(state);
}

template <class... Components>
void populate(Registry& registry) {
    for (std::size_t i = 0, n = entityCount(); i < n; ++i) {
        const Entity e = registry.create();
        (registry.add<Components>(e), ...);
    }
}

// --- plain loops -------------------------------------------------------------

void Plain1(benchmark::State& state) {
    struct Body {
        Position p;
    };
    std::vector<Body> bodies(entityCount());
    measure(state, [&] {
        for (Body& b : bodies) drift(b.p);
    });
}

void Plain2(benchmark::State& state) {
    struct Body {
        Position p;
        Velocity v;
    };
    std::vector<Body> bodies(entityCount());
    measure(state, [&] {
        for (Body& b : bodies) integrate(b.p, b.v);
    });
}

void Plain3(benchmark::State& state) {
    struct Body {
        Position p;
        Velocity v;
        Acceleration a;
    };
    std::vector<Body> bodies(entityCount());
    measure(state, [&] {
        for (Body& b : bodies) integrate(b.p, b.v, b.a);
    });
}

// --- ECS ---------------------------------------------------------------------

void Ecs1_Each(benchmark::State& state) {
    Registry registry;
    populate<Position>(registry);
    auto view = registry.view<Position>();
    measure(state, [&] { view.each([](Position& p) { drift(p); }); });
}

void Ecs1_RangeFor(benchmark::State& state) {
    Registry registry;
    populate<Position>(registry);
    auto view = registry.view<Position>();
    measure(state, [&] {
        for (auto [e, p] : view) drift(p);
    });
}

void Ecs2_Each(benchmark::State& state) {
    Registry registry;
    populate<Position, Velocity>(registry);
    auto view = registry.view<Position, const Velocity>();
    measure(state, [&] { view.each([](Position& p, const Velocity& v) { integrate(p, v); }); });
}

void Ecs2_RangeFor(benchmark::State& state) {
    Registry registry;
    populate<Position, Velocity>(registry);
    auto view = registry.view<Position, const Velocity>();
    measure(state, [&] {
        for (auto [e, p, v] : view) integrate(p, v);
    });
}

void Ecs2_Each_Shuffled(benchmark::State& state) {
    Registry registry;
    std::vector<Entity> entities(entityCount());
    for (Entity& e : entities) {
        e = registry.create();
        registry.add<Position>(e);
    }
    std::shuffle(entities.begin(), entities.end(), std::mt19937(42));
    for (Entity e : entities) registry.add<Velocity>(e);
    auto view = registry.view<Position, const Velocity>();
    measure(state, [&] { view.each([](Position& p, const Velocity& v) { integrate(p, v); }); });
}

void Ecs3_Each(benchmark::State& state) {
    Registry registry;
    populate<Position, Velocity, Acceleration>(registry);
    auto view = registry.view<Position, Velocity, const Acceleration>();
    measure(state, [&] { view.each([](Position& p, Velocity& v, const Acceleration& a) { integrate(p, v, a); }); });
}

void Ecs3_RangeFor(benchmark::State& state) {
    Registry registry;
    populate<Position, Velocity, Acceleration>(registry);
    auto view = registry.view<Position, Velocity, const Acceleration>();
    measure(state, [&] {
        for (auto [e, p, v, a] : view) integrate(p, v, a);
    });
}

}  // namespace

BENCHMARK(Plain1)->Unit(benchmark::kMillisecond);
BENCHMARK(Ecs1_Each)->Unit(benchmark::kMillisecond);
BENCHMARK(Ecs1_RangeFor)->Unit(benchmark::kMillisecond);
BENCHMARK(Plain2)->Unit(benchmark::kMillisecond);
BENCHMARK(Ecs2_Each)->Unit(benchmark::kMillisecond);
BENCHMARK(Ecs2_RangeFor)->Unit(benchmark::kMillisecond);
BENCHMARK(Ecs2_Each_Shuffled)->Unit(benchmark::kMillisecond);
BENCHMARK(Plain3)->Unit(benchmark::kMillisecond);
BENCHMARK(Ecs3_Each)->Unit(benchmark::kMillisecond);
BENCHMARK(Ecs3_RangeFor)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
