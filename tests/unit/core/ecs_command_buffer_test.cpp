// SPDX-License-Identifier: MIT
// CommandBuffer: commands apply at flush in recording order; pending creates are
// usable handles; stale targets are caught when recorded or dropped when flushed.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/core/ecs/command_buffer.hpp"
#include "engine/core/ecs/registry.hpp"
#include "engine/core/error.hpp"

namespace {

using engine::Error;
using engine::ecs::CommandBuffer;
using engine::ecs::Entity;
using engine::ecs::Registry;

struct Value {
    int v = 0;
};
struct Tag {};

TEST(EcsCommandBuffer, NothingHappensBeforeFlush) {
    Registry registry;
    const Entity e = registry.create();
    CommandBuffer commands(registry);
    commands.add<Value>(e, 1);
    commands.destroy(e);
    EXPECT_EQ(commands.size(), 2u);
    EXPECT_TRUE(registry.alive(e));
    EXPECT_FALSE(registry.has<Value>(e));
}

TEST(EcsCommandBuffer, SameEntityCommandsApplyInRecordingOrder) {
    Registry registry;
    const Entity added = registry.create();
    const Entity removed = registry.create();
    CommandBuffer commands(registry);
    commands.add<Value>(added, 1);
    commands.remove<Value>(added);
    commands.add<Value>(added, 3);
    commands.add<Value>(added, 4);  // replaces 3
    commands.add<Value>(removed, 1);
    commands.remove<Value>(removed);
    const auto stats = commands.flush();
    EXPECT_EQ(stats.applied, 6u);
    EXPECT_EQ(registry.get<Value>(added).v, 4);
    EXPECT_FALSE(registry.has<Value>(removed));
}

TEST(EcsCommandBuffer, DestroyOrderDecidesWhatSurvives) {
    Registry registry;
    const Entity first = registry.create();
    const Entity second = registry.create();
    CommandBuffer commands(registry);
    commands.add<Value>(first, 1);  // before the destroy: applied, then destroyed with it
    commands.destroy(first);
    commands.destroy(second);
    commands.add<Value>(second, 2);  // after the destroy: dropped
    commands.destroy(second);        // already gone: dropped
    const auto stats = commands.flush();
    EXPECT_EQ(stats.applied, 3u);
    EXPECT_EQ(stats.dropped, 2u);
    EXPECT_FALSE(registry.alive(first));
    EXPECT_FALSE(registry.alive(second));
    EXPECT_EQ(registry.count<Value>(), 0u);
}

TEST(EcsCommandBuffer, CreatedHandleIsUsableBeforeFlushAndAliveAfter) {
    Registry registry;
    CommandBuffer commands(registry);
    const Entity e = commands.create();
    EXPECT_FALSE(e.isNull());
    EXPECT_FALSE(registry.alive(e));
    EXPECT_THROW(registry.add<Value>(e, 1), Error);  // direct use must wait for the flush
    commands.add<Value>(e, 7);
    commands.add<Tag>(e);
    commands.flush();
    EXPECT_TRUE(registry.alive(e));
    EXPECT_EQ(registry.get<Value>(e).v, 7);
    EXPECT_TRUE(registry.has<Tag>(e));
}

TEST(EcsCommandBuffer, CreatesKeepRecordingOrderAndDistinctSlots) {
    Registry registry;
    CommandBuffer commands(registry);
    std::vector<Entity> created;
    for (int i = 0; i < 5; ++i) {
        created.push_back(commands.create());
        commands.add<Value>(created.back(), i);
    }
    const Entity direct = registry.create();  // a direct create meanwhile takes another slot
    commands.flush();
    for (int i = 0; i < 5; ++i) {
        EXPECT_NE(created[i].index(), direct.index());
        EXPECT_EQ(registry.get<Value>(created[i]).v, i);
    }
    EXPECT_EQ(registry.size(), 6u);
}

TEST(EcsCommandBuffer, RecordingForAStaleHandleThrowsImmediately) {
    Registry registry;
    const Entity e = registry.create();
    registry.destroy(e);
    CommandBuffer commands(registry);
    EXPECT_THROW(commands.add<Value>(e, 1), Error);
    EXPECT_THROW(commands.remove<Value>(e), Error);
    EXPECT_THROW(commands.destroy(e), Error);
    EXPECT_THROW(commands.destroy(Entity::null()), Error);
    EXPECT_TRUE(commands.empty());
}

TEST(EcsCommandBuffer, DiscardedCreatesAreReleasedAndStale) {
    Registry registry;
    Entity pending;
    {
        CommandBuffer commands(registry);
        pending = commands.create();
        commands.add<Value>(pending, 1);
    }  // destroyed without a flush
    EXPECT_FALSE(registry.alive(pending));
    const Entity next = registry.create();
    EXPECT_EQ(next.index(), pending.index());  // the slot came back...
    EXPECT_NE(next, pending);                  // ...with a new generation
    CommandBuffer commands(registry);
    EXPECT_THROW(commands.add<Value>(pending, 1), Error);

    const Entity cleared = commands.create();
    commands.clear();
    EXPECT_TRUE(commands.empty());
    commands.flush();
    EXPECT_FALSE(registry.alive(cleared));
    EXPECT_EQ(registry.size(), 1u);
}

TEST(EcsCommandBuffer, FailedFlushDiscardsTheRestAndEmptiesTheBuffer) {
    Registry registry;
    const Entity e = registry.create();
    registry.add<Value>(e, 1);
    CommandBuffer commands(registry);
    const Entity other = registry.create();
    commands.add<Value>(other, 2);  // refused: Value is being iterated below
    const Entity pending = commands.create();
    int visits = 0;
    registry.view<Value>().each([&](Value&) {
        ++visits;
        EXPECT_THROW(commands.flush(), Error);
    });
    EXPECT_EQ(visits, 1);
    EXPECT_TRUE(commands.empty());
    EXPECT_FALSE(registry.has<Value>(other));
    EXPECT_FALSE(registry.alive(pending));
    EXPECT_EQ(commands.flush().applied, 0u);
}

}  // namespace
