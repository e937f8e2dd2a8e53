// SPDX-License-Identifier: MIT
#pragma once
// View<Ts...>: the entities that have every component in Ts, obtained from
// Registry::view<Ts...>(). View<> (no components) is every live entity.
//
//   for (auto [e, pos, vel] : registry.view<Position, const Velocity>()) pos += vel;
//   registry.view<Position, Velocity>().each([](Entity e, Position& p, Velocity& v) {...});
//   registry.view<Position>().each([](Position& p) {...});   // the Entity may be left out
//
// Cost: the smallest pool is walked and each other pool is probed once per entity
// (O(1), sequential when the pools received their members in the same order). A
// one-component view is a straight loop over the pool's dense arrays.
//
// Contract while iterating (an each() call, or a live iterator such as a range-for's):
// the sets being walked are locked, so adding or removing a component of a type in Ts,
// or destroying an entity that has one (or creating/destroying any entity under View<>),
// throws engine::Error instead of corrupting the loop. Use a CommandBuffer for those.
// Component values may be modified freely, and components of other types may be added
// and removed. A View itself holds no lock and may be kept and iterated again.
// Iteration order is unspecified.
#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "engine/core/ecs/entity.hpp"
#include "engine/core/ecs/iteration_lock.hpp"
#include "engine/core/ecs/pool.hpp"
#include "engine/core/ecs/sparse_set.hpp"

namespace engine::ecs {

namespace detail {
template <class... Ts>
constexpr bool allDistinct() {
    if constexpr (sizeof...(Ts) < 2) {
        return true;
    } else {
        return []<class First, class... Rest>(std::type_identity<First>, std::type_identity<Rest>...) {
            return (!std::is_same_v<std::remove_cv_t<First>, std::remove_cv_t<Rest>> && ...) && allDistinct<Rest...>();
        }(std::type_identity<Ts>{}...);
    }
}
}  // namespace detail

template <class... Ts>
class View {
    static_assert(detail::allDistinct<Ts...>(), "View<Ts...>: each component type may appear only once");
    static_assert((!std::is_reference_v<Ts> && ...), "View<Ts...>: name component types, not references");

    static constexpr std::size_t kCount = sizeof...(Ts);
    static constexpr std::size_t kLockCount = kCount == 0 ? 1 : kCount;
    using Lock = IterationLock<kLockCount>;
    using Pools = std::tuple<Pool<std::remove_const_t<Ts>>*...>;

public:
    using value_type = std::tuple<Entity, Ts&...>;

    // The end of a range: iterators know their own end, so this carries nothing.
    struct Sentinel {};

    class Iterator {
    public:
        using value_type = View::value_type;
        using reference = value_type;
        using difference_type = std::ptrdiff_t;

        Iterator() = default;

        value_type operator*() const noexcept {
            const Entity e = entities_[position_];
            if constexpr (kCount == 0) {
                return value_type{e};
            } else if constexpr (kCount == 1) {
                return value_type{e, components_[position_]};
            } else {
                return [&]<std::size_t... I>(std::index_sequence<I...>) {
                    return value_type{e, std::get<I>(pools_)->componentAt(positions_[I])...};
                }
                (std::index_sequence_for<Ts...>{});
            }
        }
        Iterator& operator++() noexcept {
            ++position_;
            skipNonMembers();
            return *this;
        }
        void operator++(int) noexcept { ++*this; }
        friend bool operator==(const Iterator& it, Sentinel) noexcept { return it.position_ == it.end_; }

    private:
        friend class View;
        // The component type of a one-component view (int, unused, for View<>).
        using FirstComponent = std::remove_const_t<std::tuple_element_t<0, std::tuple<Ts..., int>>>;

        Iterator(const View& view, const SparseSet& driver) noexcept
            : lock_(view.lockedSets()), entities_(driver.entityData()), end_(driver.size()), pools_(view.pools_) {
            if constexpr (kCount == 1) components_ = std::get<0>(pools_)->componentData();
            skipNonMembers();
        }
        void skipNonMembers() noexcept {
            if constexpr (kCount >= 2) {
                while (position_ != end_ && !matches(position_)) ++position_;
            }
        }
        bool matches(std::size_t position) noexcept {
            return View::matchAt(pools_, entities_[position], position, positions_);
        }

        Lock lock_;
        const Entity* entities_ = nullptr;  // the driver's dense entities
        std::size_t position_ = 0;
        std::size_t end_ = 0;
        Pools pools_{};
        FirstComponent* components_ = nullptr;         // kCount == 1: the driver's components
        std::array<std::size_t, kCount> positions_{};  // kCount >= 2: the current entity in each pool
    };

    // Built by Registry::view(); `liveEntities` is walked when Ts is empty.
    explicit View(SparseSet& liveEntities, Pool<std::remove_const_t<Ts>>&... pools) noexcept
        : liveEntities_(&liveEntities), pools_(&pools...) {}

    Iterator begin() const noexcept { return Iterator(*this, driver()); }
    Sentinel end() const noexcept { return {}; }

    // Calls fn(Entity, Ts&...) or fn(Ts&...) for every match.
    template <class Fn>
    void each(Fn&& fn) const {
        constexpr bool withEntity = std::is_invocable_v<Fn&, Entity, Ts&...>;
        static_assert(withEntity || std::is_invocable_v<Fn&, Ts&...>,
                      "View::each: the callback must take (Entity, Ts&...) or (Ts&...)");
        const Lock lock(lockedSets());
        const SparseSet& walked = driver();
        const Entity* entities = walked.entityData();
        const std::size_t count = walked.size();  // fixed: the lock forbids inserts and erases
        if constexpr (kCount == 0) {
            for (std::size_t i = 0; i < count; ++i) {
                if constexpr (withEntity) fn(entities[i]);
                else fn();
            }
        } else if constexpr (kCount == 1) {
            auto* components = std::get<0>(pools_)->componentData();
            for (std::size_t i = 0; i < count; ++i) {
                if constexpr (withEntity) fn(entities[i], components[i]);
                else fn(components[i]);
            }
        } else {
            std::array<std::size_t, kCount> positions{};
            for (std::size_t i = 0; i < count; ++i) {
                const Entity e = entities[i];
                if (!matchAt(pools_, e, i, positions)) continue;
                [&]<std::size_t... I>(std::index_sequence<I...>) {
                    if constexpr (withEntity) fn(e, std::get<I>(pools_)->componentAt(positions[I])...);
                    else fn(std::get<I>(pools_)->componentAt(positions[I])...);
                }
                (std::index_sequence_for<Ts...>{});
            }
        }
    }

    bool contains(Entity e) const noexcept {
        if constexpr (kCount == 0) return liveEntities_->contains(e);
        else return std::apply([e](auto*... pool) { return (pool->contains(e) && ...); }, pools_);
    }
    // An upper bound on the number of matches: the size of the set that would be walked.
    std::size_t sizeHint() const noexcept { return driver().size(); }

private:
    // The set iteration walks: the smallest pool, chosen when iteration starts.
    const SparseSet& driver() const noexcept {
        if constexpr (kCount == 0) {
            return *liveEntities_;
        } else {
            const SparseSet* smallest = std::get<0>(pools_);
            std::apply([&](auto*... pool) { ((smallest = pool->size() < smallest->size() ? pool : smallest), ...); },
                       pools_);
            return *smallest;
        }
    }
    std::array<SparseSet*, kLockCount> lockedSets() const noexcept {
        if constexpr (kCount == 0) return {liveEntities_};
        else return std::apply([](auto*... pool) { return std::array<SparseSet*, kCount>{pool...}; }, pools_);
    }
    // True if every pool holds `e` (found at `position` of the walked set); records where.
    static bool matchAt(const Pools& pools, Entity e, std::size_t position,
                        std::array<std::size_t, kCount>& positions) noexcept {
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return (((positions[I] = std::get<I>(pools)->find(e, position)) != SparseSet::npos) && ...);
        }
        (std::index_sequence_for<Ts...>{});
    }

    SparseSet* liveEntities_;
    Pools pools_;
};

}  // namespace engine::ecs
