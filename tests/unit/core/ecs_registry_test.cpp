// SPDX-License-Identifier: MIT
// Registry component storage: add/get/remove contracts, swap-and-pop bookkeeping,
// destroy of an entity holding many component types.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "engine/core/ecs/registry.hpp"
#include "engine/core/error.hpp"

namespace {

using engine::Error;
using engine::ecs::Entity;
using engine::ecs::Registry;

template <int N>
struct Tagged {
    int value = N;
};
struct Name {
    std::string text;
};

TEST(EcsRegistry, AddGetRemove) {
    Registry registry;
    const Entity e = registry.create();
    EXPECT_FALSE(registry.has<Name>(e));
    registry.add<Name>(e, "crate");
    EXPECT_TRUE(registry.has<Name>(e));
    EXPECT_EQ(registry.get<Name>(e).text, "crate");
    registry.get<Name>(e).text = "barrel";
    EXPECT_EQ(registry.tryGet<Name>(e)->text, "barrel");
    EXPECT_TRUE(registry.remove<Name>(e));
    EXPECT_FALSE(registry.has<Name>(e));
    EXPECT_FALSE(registry.remove<Name>(e));
    EXPECT_EQ(registry.tryGet<Name>(e), nullptr);
}

TEST(EcsRegistry, MisuseThrowsWithClearMessage) {
    Registry registry;
    const Entity e = registry.create();
    registry.add<Name>(e, "a");
    try {
        registry.add<Name>(e, "b");
        FAIL() << "duplicate add must throw";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("already has"), std::string::npos) << error.what();
    }
    EXPECT_EQ(registry.get<Name>(e).text, "a");
    try {
        registry.get<Tagged<1>>(e);
        FAIL() << "get of a missing component must throw";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("Tagged<1>"), std::string::npos) << error.what();
    }
}

TEST(EcsRegistry, AddOrReplaceAssignsExisting) {
    Registry registry;
    const Entity e = registry.create();
    registry.addOrReplace<Name>(e, "first");
    registry.addOrReplace<Name>(e, "second");
    EXPECT_EQ(registry.get<Name>(e).text, "second");
    EXPECT_EQ(registry.count<Name>(), 1u);
}

TEST(EcsRegistry, RemovingFromTheMiddleKeepsOtherValues) {
    Registry registry;
    std::vector<Entity> entities;
    for (int i = 0; i < 10; ++i) {
        entities.push_back(registry.create());
        registry.add<Tagged<0>>(entities.back(), i);
    }
    registry.remove<Tagged<0>>(entities[0]);
    registry.remove<Tagged<0>>(entities[4]);
    registry.destroy(entities[7]);
    EXPECT_EQ(registry.count<Tagged<0>>(), 7u);
    for (int i = 0; i < 10; ++i) {
        if (i == 0 || i == 4 || i == 7) {
            EXPECT_FALSE(registry.has<Tagged<0>>(entities[i])) << i;
        } else {
            EXPECT_EQ(registry.get<Tagged<0>>(entities[i]).value, i) << i;
        }
    }
}

TEST(EcsRegistry, MoveOnlyComponentsWork) {
    Registry registry;
    const Entity a = registry.create();
    const Entity b = registry.create();
    registry.add<std::unique_ptr<int>>(a, std::make_unique<int>(1));
    registry.add<std::unique_ptr<int>>(b, std::make_unique<int>(2));
    registry.remove<std::unique_ptr<int>>(a);
    EXPECT_EQ(*registry.get<std::unique_ptr<int>>(b), 2);
}

TEST(EcsRegistry, DestroyRemovesAllEightComponentTypes) {
    Registry registry;
    const Entity keep = registry.create();
    const Entity doomed = registry.create();
    auto addAll = [&](Entity e, int base) {
        registry.add<Tagged<0>>(e, base + 0);
        registry.add<Tagged<1>>(e, base + 1);
        registry.add<Tagged<2>>(e, base + 2);
        registry.add<Tagged<3>>(e, base + 3);
        registry.add<Tagged<4>>(e, base + 4);
        registry.add<Tagged<5>>(e, base + 5);
        registry.add<Tagged<6>>(e, base + 6);
        registry.add<Name>(e, std::to_string(base));
    };
    // doomed is first in every pool, so destroying it moves keep's components.
    addAll(doomed, 100);
    addAll(keep, 200);

    registry.destroy(doomed);

    EXPECT_FALSE(registry.alive(doomed));
    EXPECT_EQ(registry.size(), 1u);
    EXPECT_FALSE(registry.has<Tagged<0>>(doomed));
    EXPECT_FALSE(registry.has<Tagged<6>>(doomed));
    EXPECT_FALSE(registry.has<Name>(doomed));
    EXPECT_EQ(registry.count<Tagged<0>>(), 1u);
    EXPECT_EQ(registry.count<Tagged<1>>(), 1u);
    EXPECT_EQ(registry.count<Tagged<2>>(), 1u);
    EXPECT_EQ(registry.count<Tagged<3>>(), 1u);
    EXPECT_EQ(registry.count<Tagged<4>>(), 1u);
    EXPECT_EQ(registry.count<Tagged<5>>(), 1u);
    EXPECT_EQ(registry.count<Tagged<6>>(), 1u);
    EXPECT_EQ(registry.count<Name>(), 1u);
    EXPECT_EQ(registry.get<Tagged<0>>(keep).value, 200);
    EXPECT_EQ(registry.get<Tagged<3>>(keep).value, 203);
    EXPECT_EQ(registry.get<Tagged<6>>(keep).value, 206);
    EXPECT_EQ(registry.get<Name>(keep).text, "200");

    // The reused slot starts empty.
    const Entity reborn = registry.create();
    EXPECT_EQ(reborn.index(), doomed.index());
    EXPECT_FALSE(registry.has<Tagged<0>>(reborn));
    EXPECT_FALSE(registry.has<Name>(reborn));
}

TEST(EcsRegistry, SparseIndicesFarApart) {
    Registry registry;
    std::vector<Entity> entities;
    for (int i = 0; i < 10000; ++i) entities.push_back(registry.create());
    registry.add<Tagged<0>>(entities[3], 3);
    registry.add<Tagged<0>>(entities[9999], 9999);
    EXPECT_EQ(registry.get<Tagged<0>>(entities[9999]).value, 9999);
    EXPECT_FALSE(registry.has<Tagged<0>>(entities[5000]));
    EXPECT_EQ(registry.count<Tagged<0>>(), 2u);
}

}  // namespace
