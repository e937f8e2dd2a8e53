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
using namespace engine::ecs;

struct Value {
    int v = 0;
};
struct Tag {};

// A registry and a command buffer recording for it.
class EcsCommandBuffer : public ::testing::Test {
protected:
    Registry registry;
    CommandBuffer commands{registry};
};

TEST_F(EcsCommandBuffer, NothingHappensBeforeFlush) {
    const Entity e = registry.create();
    commands.add<Value>(e, 1);
    commands.destroy(e);
    EXPECT_EQ(commands.size(), 2u);
    EXPECT_TRUE(registry.alive(e));
    EXPECT_FALSE(registry.has<Value>(e));
}

TEST_F(EcsCommandBuffer, SameEntityCommandsApplyInRecordingOrder) {
    const Entity added = registry.create();
    const Entity removed = registry.create();
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

TEST_F(EcsCommandBuffer, DestroyOrderDecidesWhatSurvives) {
    const Entity first = registry.create();
    const Entity second = registry.create();
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

TEST_F(EcsCommandBuffer, CreatedHandleIsUsableBeforeFlushAndAliveAfter) {
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

TEST_F(EcsCommandBuffer, CreatesKeepRecordingOrderAndDistinctSlots) {
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

TEST_F(EcsCommandBuffer, RecordingForAStaleHandleThrowsImmediately) {
    const Entity e = registry.create();
    registry.destroy(e);
    EXPECT_THROW(commands.add<Value>(e, 1), Error);
    EXPECT_THROW(commands.remove<Value>(e), Error);
    EXPECT_THROW(commands.destroy(e), Error);
    EXPECT_THROW(commands.destroy(Entity::null()), Error);
    EXPECT_TRUE(commands.empty());
}

TEST_F(EcsCommandBuffer, DiscardedCreatesAreReleasedAndStale) {
    Entity pending;
    {
        CommandBuffer discarded(registry);
        pending = discarded.create();
        discarded.add<Value>(pending, 1);
    }  // destroyed without a flush
    EXPECT_FALSE(registry.alive(pending));
    const Entity next = registry.create();
    EXPECT_EQ(next.index(), pending.index());  // the slot came back...
    EXPECT_NE(next, pending);                  // ...with a new generation
    EXPECT_THROW(commands.add<Value>(pending, 1), Error);

    const Entity cleared = commands.create();
    commands.clear();
    EXPECT_TRUE(commands.empty());
    commands.flush();
    EXPECT_FALSE(registry.alive(cleared));
    EXPECT_EQ(registry.size(), 1u);
}

TEST_F(EcsCommandBuffer, FailedFlushDiscardsTheRestAndEmptiesTheBuffer) {
    const Entity e = registry.create();
    registry.add<Value>(e, 1);
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
