// SPDX-License-Identifier: MIT
// Entity handles: bit layout, slot reuse with a new generation, stale-handle
// detection, and retirement of a slot whose generation would wrap.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "engine/core/ecs/registry.hpp"
#include "engine/core/error.hpp"

namespace {

using engine::Error;
using engine::ecs::Entity;
using engine::ecs::Registry;

struct Health {
    int points = 0;
};

TEST(EcsEntity, PacksIndexAndGeneration) {
    const Entity e = Entity::fromParts(123456, 789);
    EXPECT_EQ(e.index(), 123456u);
    EXPECT_EQ(e.generation(), 789u);
    EXPECT_EQ(Entity::kIndexBits + Entity::kGenerationBits, 32u);
    EXPECT_NE(e, Entity::fromParts(123456, 790));
    EXPECT_TRUE(Entity{}.isNull());
    EXPECT_EQ(Entity{}, Entity::null());
    std::ostringstream text;
    text << Entity::fromParts(12, 3);
    EXPECT_EQ(text.str(), "entity 12 (gen 3)");
}

TEST(EcsEntity, NullIsNeverAlive) {
    Registry registry;
    registry.create();
    EXPECT_FALSE(registry.alive(Entity::null()));
    EXPECT_THROW(registry.destroy(Entity::null()), Error);
}

TEST(EcsEntity, FreshEntitiesAreDistinctAndAlive) {
    Registry registry;
    std::set<std::uint32_t> bits;
    for (int i = 0; i < 100; ++i) {
        const Entity e = registry.create();
        EXPECT_TRUE(registry.alive(e));
        bits.insert(e.bits());
    }
    EXPECT_EQ(bits.size(), 100u);
    EXPECT_EQ(registry.size(), 100u);
}

TEST(EcsEntity, DestroyedSlotIsReusedWithNextGeneration) {
    Registry registry;
    const Entity first = registry.create();
    registry.destroy(first);
    const Entity second = registry.create();
    EXPECT_EQ(second.index(), first.index());
    EXPECT_EQ(second.generation(), first.generation() + 1);
    EXPECT_NE(second, first);
    EXPECT_FALSE(registry.alive(first));
    EXPECT_TRUE(registry.alive(second));
}

TEST(EcsEntity, StaleHandleNeverAliasesTheNewOccupant) {
    Registry registry;
    const Entity old = registry.create();
    registry.add<Health>(old, 10);
    registry.destroy(old);
    const Entity occupant = registry.create();
    registry.add<Health>(occupant, 99);
    ASSERT_EQ(occupant.index(), old.index());

    EXPECT_FALSE(registry.alive(old));
    EXPECT_FALSE(registry.has<Health>(old));
    EXPECT_EQ(registry.tryGet<Health>(old), nullptr);
    EXPECT_THROW(registry.get<Health>(old), Error);
    EXPECT_THROW(registry.add<Health>(old, 1), Error);
    EXPECT_THROW(registry.remove<Health>(old), Error);
    EXPECT_THROW(registry.destroy(old), Error);
    // The failed calls left the occupant untouched.
    EXPECT_TRUE(registry.alive(occupant));
    EXPECT_EQ(registry.get<Health>(occupant).points, 99);
}

TEST(EcsEntity, StaleGetSaysWhy) {
    Registry registry;
    const Entity old = registry.create();
    registry.add<Health>(old);
    registry.destroy(old);
    registry.create();
    try {
        registry.get<Health>(old);
        FAIL() << "get on a stale handle must throw";
    } catch (const Error& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("stale"), std::string::npos) << what;
        EXPECT_NE(what.find("Health"), std::string::npos) << what;
        EXPECT_NE(what.find("entity 0 (gen 0)"), std::string::npos) << what;
    }
}

TEST(EcsEntity, HandleFromAnotherRegistryOrTheFutureIsNotAlive) {
    Registry registry;
    const Entity e = registry.create();
    EXPECT_FALSE(registry.alive(Entity::fromParts(e.index() + 5, 0)));
    EXPECT_FALSE(registry.alive(Entity::fromParts(e.index(), e.generation() + 1)));
    EXPECT_THROW(registry.destroy(Entity::fromParts(e.index(), e.generation() + 1)), Error);
    EXPECT_TRUE(registry.alive(e));
}

TEST(EcsEntity, SlotIsRetiredWhenItsGenerationWouldWrap) {
    Registry registry;
    Entity e = registry.create();
    const std::uint32_t slot = e.index();
    Entity firstHandle = e;
    for (std::uint32_t generation = 0; generation < Entity::kMaxGeneration; ++generation) {
        ASSERT_EQ(e.index(), slot);
        ASSERT_EQ(e.generation(), generation);
        registry.destroy(e);
        e = registry.create();
    }
    ASSERT_EQ(e.index(), slot);
    ASSERT_EQ(e.generation(), Entity::kMaxGeneration);
    EXPECT_EQ(registry.retiredSlots(), 0u);
    registry.destroy(e);
    EXPECT_EQ(registry.retiredSlots(), 1u);

    // A wrap would hand out generation 0 again and revive firstHandle; retirement
    // moves to a fresh slot instead.
    const Entity next = registry.create();
    EXPECT_NE(next.index(), slot);
    EXPECT_FALSE(registry.alive(firstHandle));
    EXPECT_FALSE(registry.alive(e));
    EXPECT_THROW(registry.destroy(e), Error);
}

}  // namespace
