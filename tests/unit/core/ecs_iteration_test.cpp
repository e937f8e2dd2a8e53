// SPDX-License-Identifier: MIT
// Structural changes while a view iterates: direct ones on the viewed pools are
// refused with engine::Error (and change nothing); others are allowed; deferred ones
// through a CommandBuffer are applied at flush.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/core/ecs/command_buffer.hpp"
#include "engine/core/ecs/registry.hpp"
#include "engine/core/error.hpp"

namespace {

using engine::Error;
using namespace engine::ecs;

struct Position {
    float x = 0;
};
struct Velocity {
    float x = 0;
};
struct Marked {};

class EcsIteration : public ::testing::Test {
protected:
    void SetUp() override {
        for (int i = 0; i < 8; ++i) {
            const Entity e = registry.create();
            registry.add<Position>(e, static_cast<float>(i));
            if (i % 2 == 0) registry.add<Velocity>(e, 1.0f);
            entities.push_back(e);
        }
        spare = registry.create();  // no components
    }
    Registry registry;
    std::vector<Entity> entities;
    Entity spare;
};

TEST_F(EcsIteration, DirectAddOfViewedComponentThrowsAndChangesNothing) {
    int visits = 0;
    for ([[maybe_unused]] auto [e, position] : registry.view<Position>()) {
        ++visits;
        try {
            registry.add<Position>(spare, 5.0f);
            ADD_FAILURE() << "add to a pool under iteration must throw";
        } catch (const Error& error) {
            EXPECT_NE(std::string(error.what()).find("CommandBuffer"), std::string::npos) << error.what();
            EXPECT_NE(std::string(error.what()).find("Position"), std::string::npos) << error.what();
        }
    }
    EXPECT_EQ(visits, 8);
    EXPECT_FALSE(registry.has<Position>(spare));
    EXPECT_EQ(registry.count<Position>(), 8u);
    // The loop is over: the lock is gone.
    registry.add<Position>(spare, 5.0f);
    EXPECT_TRUE(registry.has<Position>(spare));
}

TEST_F(EcsIteration, DirectRemoveAndDestroyOfViewedComponentThrow) {
    int visits = 0;
    registry.view<Position, Velocity>().each([&](Entity e, Position&, Velocity&) {
        ++visits;
        EXPECT_THROW(registry.remove<Velocity>(e), Error);
        EXPECT_THROW(registry.remove<Position>(e), Error);
        EXPECT_THROW(registry.destroy(e), Error);
        EXPECT_THROW(registry.destroy(entities[1]), Error);  // has Position, which is locked
    });
    EXPECT_EQ(visits, 4);
    EXPECT_EQ(registry.count<Position>(), 8u);
    EXPECT_EQ(registry.count<Velocity>(), 4u);
    for (Entity e : entities) EXPECT_TRUE(registry.alive(e));
}

TEST_F(EcsIteration, DirectChangesOutsideTheViewedPoolsAreAllowed) {
    std::vector<Entity> created;
    for (auto [e, velocity] : registry.view<Velocity>()) {
        registry.add<Marked>(e);               // another pool
        registry.remove<Position>(e);          // another pool
        created.push_back(registry.create());  // no viewed component
        velocity.x = 2.0f;
    }
    registry.destroy(spare);  // no viewed component
    EXPECT_EQ(registry.count<Marked>(), 4u);
    EXPECT_EQ(registry.count<Position>(), 4u);
    EXPECT_EQ(created.size(), 4u);
    for (Entity e : created) EXPECT_TRUE(registry.alive(e));
    EXPECT_EQ(registry.get<Velocity>(entities[0]).x, 2.0f);
}

TEST_F(EcsIteration, AllEntitiesViewRefusesCreateAndDestroy) {
    for (auto [e] : registry.view<>()) {
        EXPECT_THROW(registry.create(), Error);
        EXPECT_THROW(registry.destroy(spare), Error);
        registry.addOrReplace<Marked>(e);  // components are fine
    }
    EXPECT_EQ(registry.size(), 9u);
    EXPECT_EQ(registry.count<Marked>(), 9u);
    registry.destroy(spare);
    EXPECT_EQ(registry.size(), 8u);
}

TEST_F(EcsIteration, LockIsReleasedOnBreakAndOnException) {
    for (auto [e, p] : registry.view<Position>()) {
        (void)e;
        (void)p;
        break;
    }
    EXPECT_NO_THROW(registry.add<Position>(spare));
    EXPECT_THROW(registry.view<Velocity>().each([](Velocity&) { throw std::runtime_error("system failed"); }),
                 std::runtime_error);
    EXPECT_NO_THROW(registry.remove<Velocity>(entities[0]));
}

TEST_F(EcsIteration, KeptViewDoesNotLockBetweenLoops) {
    auto view = registry.view<Position>();
    int first = 0;
    for ([[maybe_unused]] auto [e, p] : view) ++first;
    registry.add<Position>(spare);  // not iterating now
    int second = 0;
    view.each([&](Position&) { ++second; });
    EXPECT_EQ(first, 8);
    EXPECT_EQ(second, 9);
}

TEST_F(EcsIteration, DeferredChangesApplyAtFlush) {
    CommandBuffer commands(registry);
    std::set<Entity> visited;
    for (auto [e, position] : registry.view<Position>()) {
        visited.insert(e);
        if (position.x < 4) {
            commands.destroy(e);
        } else {
            commands.remove<Position>(e);
            commands.add<Marked>(e);
        }
        const Entity child = commands.create();
        commands.add<Position>(child, 100.0f + position.x);
    }
    // Nothing happened yet: the loop saw exactly the original members.
    EXPECT_EQ(visited, std::set<Entity>(entities.begin(), entities.end()));
    EXPECT_EQ(registry.count<Position>(), 8u);
    EXPECT_EQ(registry.size(), 9u);

    const auto stats = commands.flush();
    EXPECT_EQ(stats.applied, 8u /*destroy or remove*/ + 4u /*add Marked*/ + 16u /*create + add*/);
    EXPECT_EQ(stats.dropped, 0u);
    EXPECT_TRUE(commands.empty());

    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(registry.alive(entities[i]), i >= 4) << i;
        if (i >= 4) {
            EXPECT_FALSE(registry.has<Position>(entities[i]));
            EXPECT_TRUE(registry.has<Marked>(entities[i]));
        }
    }
    EXPECT_EQ(registry.size(), 1u + 4u + 8u);
    std::set<float> childValues;
    for (auto [e, position] : registry.view<Position>()) childValues.insert(position.x);
    EXPECT_EQ(childValues, (std::set<float>{100, 101, 102, 103, 104, 105, 106, 107}));
}

}  // namespace
