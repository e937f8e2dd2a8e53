// SPDX-License-Identifier: MIT
// Views over 0..3 components visit exactly the entities that have all of them,
// with each entity's own components, through both range-for and each().
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <ranges>
#include <set>
#include <vector>

#include "engine/core/ecs/registry.hpp"

namespace {

using engine::ecs::Entity;
using engine::ecs::Registry;

struct A {
    std::uint32_t owner = 0;
};
struct B {
    std::uint32_t owner = 0;
};
struct C {
    std::uint32_t owner = 0;
};

// 60 entities: A on multiples of 2, B on multiples of 3, C on multiples of 5;
// entities 10 (has A and C) and 30 (has all) are destroyed again. Components
// record their owner's index so a view that pairs the wrong data is caught.
class EcsView : public ::testing::Test {
protected:
    void SetUp() override {
        for (std::uint32_t i = 0; i < 60; ++i) entities.push_back(registry.create());
        // Added in different orders per type, so the pools' dense arrays do not line up.
        for (std::uint32_t i = 0; i < 60; i += 2) registry.add<A>(entities[i], entities[i].index());
        for (std::uint32_t i = 60; i-- > 0;)
            if (i % 3 == 0) registry.add<B>(entities[i], entities[i].index());
        for (std::uint32_t i : {55u, 5u, 0u, 45u, 10u, 25u, 30u, 15u, 50u, 20u, 35u, 40u})
            registry.add<C>(entities[i], entities[i].index());
        registry.destroy(entities[10]);
        registry.destroy(entities[30]);
    }

    std::set<Entity> expected(bool a, bool b, bool c) const {
        std::set<Entity> result;
        for (std::uint32_t i = 0; i < 60; ++i) {
            if (i == 10 || i == 30) continue;
            if ((!a || i % 2 == 0) && (!b || i % 3 == 0) && (!c || i % 5 == 0)) result.insert(entities[i]);
        }
        return result;
    }

    Registry registry;
    std::vector<Entity> entities;
};

TEST_F(EcsView, ZeroComponentsIsEveryLiveEntity) {
    std::set<Entity> seen;
    for (auto [e] : registry.view<>()) EXPECT_TRUE(seen.insert(e).second);
    EXPECT_EQ(seen, expected(false, false, false));
    EXPECT_EQ(seen.size(), 58u);

    std::set<Entity> seenByEach;
    registry.view<>().each([&](Entity e) { seenByEach.insert(e); });
    EXPECT_EQ(seenByEach, seen);
}

TEST_F(EcsView, OneComponent) {
    std::set<Entity> seen;
    for (auto [e, a] : registry.view<A>()) {
        EXPECT_EQ(a.owner, e.index());
        EXPECT_TRUE(seen.insert(e).second);
    }
    EXPECT_EQ(seen, expected(true, false, false));

    std::set<Entity> seenByEach;
    registry.view<A>().each([&](Entity e, A& a) {
        EXPECT_EQ(a.owner, e.index());
        seenByEach.insert(e);
    });
    EXPECT_EQ(seenByEach, seen);

    int withoutEntity = 0;
    registry.view<A>().each([&](A&) { ++withoutEntity; });
    EXPECT_EQ(withoutEntity, static_cast<int>(seen.size()));
}

TEST_F(EcsView, TwoComponents) {
    std::set<Entity> seen;
    for (auto [e, a, b] : registry.view<A, B>()) {
        EXPECT_EQ(a.owner, e.index());
        EXPECT_EQ(b.owner, e.index());
        EXPECT_TRUE(seen.insert(e).second);
    }
    EXPECT_EQ(seen, expected(true, true, false));
    EXPECT_EQ(seen.size(), 9u);  // 0, 6, 12, ..., 54 without the destroyed 30

    std::set<Entity> seenByEach;
    registry.view<B, A>().each([&](Entity e, B& b, A& a) {
        EXPECT_EQ(a.owner, e.index());
        EXPECT_EQ(b.owner, e.index());
        seenByEach.insert(e);
    });
    EXPECT_EQ(seenByEach, seen);
}

TEST_F(EcsView, ThreeComponents) {
    std::set<Entity> seen;
    for (auto [e, a, b, c] : registry.view<A, B, C>()) {
        EXPECT_EQ(a.owner, e.index());
        EXPECT_EQ(b.owner, e.index());
        EXPECT_EQ(c.owner, e.index());
        EXPECT_TRUE(seen.insert(e).second);
    }
    EXPECT_EQ(seen, expected(true, true, true));
    EXPECT_EQ(seen.size(), 1u);  // 0; 30 was destroyed

    std::set<Entity> seenByEach;
    registry.view<C, A, B>().each([&](Entity e, C&, A&, B&) { seenByEach.insert(e); });
    EXPECT_EQ(seenByEach, seen);
}

TEST_F(EcsView, WalksTheSmallestPool) {
    // C has 10 members left, A 28, B 19.
    EXPECT_EQ((registry.view<A, B, C>().sizeHint()), registry.count<C>());
    EXPECT_EQ((registry.view<A, B>().sizeHint()), registry.count<B>());
    EXPECT_EQ(registry.count<C>(), 10u);
}

TEST_F(EcsView, ContainsAgreesWithIteration) {
    const auto view = registry.view<A, C>();
    const std::set<Entity> members = expected(true, false, true);
    for (std::uint32_t i = 0; i < 60; ++i) EXPECT_EQ(view.contains(entities[i]), members.count(entities[i]) == 1) << i;
}

TEST_F(EcsView, WritesThroughTheViewAreVisible) {
    for (auto [e, a, b] : registry.view<A, B>()) {
        a.owner += 1000;
        b.owner += 2000;
    }
    registry.view<A>().each([](A& a) { a.owner += 1; });
    EXPECT_EQ(registry.get<A>(entities[6]).owner, entities[6].index() + 1001);
    EXPECT_EQ(registry.get<B>(entities[6]).owner, entities[6].index() + 2000);
    EXPECT_EQ(registry.get<A>(entities[2]).owner, entities[2].index() + 1);
    EXPECT_EQ(registry.get<B>(entities[3]).owner, entities[3].index());
}

TEST_F(EcsView, ConstComponentsAreReadOnly) {
    std::uint32_t sum = 0;
    for (auto [e, a, b] : registry.view<const A, B>()) {
        static_assert(std::is_same_v<decltype(a), const A&>);
        sum += a.owner;
        b.owner = 7;
    }
    EXPECT_GT(sum, 0u);
    EXPECT_EQ(registry.get<B>(entities[6]).owner, 7u);
}

// Views are C++20 ranges, so <ranges> and <algorithm> work on them.
static_assert(std::input_iterator<engine::ecs::View<A, B>::Iterator>);
static_assert(std::ranges::input_range<engine::ecs::View<A>>);
static_assert(std::ranges::input_range<engine::ecs::View<>>);

TEST_F(EcsView, WorksWithRangesAlgorithms) {
    auto view = registry.view<A, B>();
    EXPECT_EQ(std::ranges::distance(view), 9);
    EXPECT_EQ(std::ranges::count_if(view, [](auto item) { return std::get<0>(item).index() % 4 == 0; }), 5);
}

TEST(EcsViewEmpty, ComponentNobodyHasYieldsNothing) {
    Registry registry;
    registry.create();
    int visits = 0;
    for (auto [e, a] : registry.view<A>()) {
        (void)e;
        (void)a;
        ++visits;
    }
    registry.view<A, B>().each([&](A&, B&) { ++visits; });
    EXPECT_EQ(visits, 0);
}

}  // namespace
