// SPDX-License-Identifier: MIT
// Scheduler: phases run in their fixed order, systems in registration order, and the
// shared CommandBuffer is flushed between phases.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/core/ecs/scheduler.hpp"
#include "engine/core/error.hpp"

namespace {

using engine::Error;
using engine::ecs::CommandBuffer;
using engine::ecs::Entity;
using engine::ecs::Registry;
using engine::ecs::Scheduler;
namespace phase = engine::ecs::phase;

struct Spawned {
    int frame = 0;
};

TEST(EcsScheduler, DefaultPhaseOrder) {
    const Scheduler scheduler;
    EXPECT_EQ(scheduler.phases(),
              (std::vector<std::string>{"input", "simulation", "deformation", "camera", "extraction"}));
}

TEST(EcsScheduler, RunsPhasesInOrderThenSystemsInRegistrationOrder) {
    Scheduler scheduler;
    std::vector<std::string> ran;
    auto log = [&ran](std::string name) { return [&ran, name](Registry&, CommandBuffer&) { ran.push_back(name); }; };
    // Registered out of phase order on purpose.
    scheduler.add(phase::extraction, "extract", log("extract"));
    scheduler.add(phase::camera, "follow", log("follow"));
    scheduler.add(phase::simulation, "physics", log("physics"));
    scheduler.add(phase::input, "keyboard", log("keyboard"));
    scheduler.add(phase::simulation, "ai", log("ai"));
    scheduler.add(phase::deformation, "skin", log("skin"));
    scheduler.add(phase::input, "gamepad", log("gamepad"));

    Registry registry;
    scheduler.run(registry);
    EXPECT_EQ(ran, (std::vector<std::string>{"keyboard", "gamepad", "physics", "ai", "skin", "follow", "extract"}));
    EXPECT_EQ(scheduler.systems(phase::simulation), (std::vector<std::string>{"physics", "ai"}));

    ran.clear();
    scheduler.run(registry);
    EXPECT_EQ(ran.size(), 7u);
    EXPECT_EQ(ran.front(), "keyboard");
}

TEST(EcsScheduler, CustomPhases) {
    Scheduler scheduler({"late", "early"});
    std::string order;
    scheduler.add("early", "e", [&](Registry&, CommandBuffer&) { order += 'e'; });
    scheduler.add("late", "l", [&](Registry&, CommandBuffer&) { order += 'l'; });
    Registry registry;
    scheduler.run(registry);
    EXPECT_EQ(order, "le");
}

TEST(EcsScheduler, CommandsAreFlushedBetweenPhases) {
    Scheduler scheduler;
    Registry registry;
    std::size_t seenInSameSimulationPhase = 99;
    std::size_t seenInCamera = 99;
    scheduler.add(phase::simulation, "spawn", [](Registry&, CommandBuffer& commands) {
        const Entity e = commands.create();
        commands.add<Spawned>(e, 1);
    });
    scheduler.add(phase::simulation, "count-same-phase",
                  [&](Registry& r, CommandBuffer&) { seenInSameSimulationPhase = r.count<Spawned>(); });
    scheduler.add(phase::camera, "count-later-phase",
                  [&](Registry& r, CommandBuffer&) { seenInCamera = r.count<Spawned>(); });
    scheduler.add(phase::extraction, "despawn", [](Registry& r, CommandBuffer& commands) {
        for (auto [e, spawned] : r.view<Spawned>()) commands.destroy(e);
    });
    scheduler.run(registry);
    EXPECT_EQ(seenInSameSimulationPhase, 0u);
    EXPECT_EQ(seenInCamera, 1u);
    EXPECT_EQ(registry.size(), 0u);  // the last phase was flushed too
}

TEST(EcsScheduler, RegistrationMistakesThrow) {
    Scheduler scheduler;
    auto noop = [](Registry&, CommandBuffer&) {};
    EXPECT_THROW(scheduler.add("physics", "x", noop), Error);  // unknown phase
    scheduler.add(phase::input, "poll", noop);
    EXPECT_THROW(scheduler.add(phase::camera, "poll", noop), Error);  // duplicate name
    EXPECT_THROW(scheduler.add(phase::camera, "", noop), Error);
    EXPECT_THROW(scheduler.add(phase::camera, "empty", engine::ecs::System{}), Error);
    EXPECT_THROW(Scheduler({"a", "a"}), Error);
    EXPECT_THROW(Scheduler(std::vector<std::string>{}), Error);
    EXPECT_THROW(scheduler.systems("nope"), Error);
}

TEST(EcsScheduler, SystemErrorsNameTheSystem) {
    Scheduler scheduler;
    scheduler.add(phase::camera, "broken-camera",
                  [](Registry& r, CommandBuffer&) { r.destroy(Entity::fromParts(42, 0)); });
    Registry registry;
    try {
        scheduler.run(registry);
        FAIL() << "the system's error must propagate";
    } catch (const Error& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("broken-camera"), std::string::npos) << what;
        EXPECT_NE(what.find("camera"), std::string::npos) << what;
    }
}

}  // namespace
