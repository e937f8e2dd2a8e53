// SPDX-License-Identifier: MIT
#pragma once
// Pool<T>: the storage of one component type. A SparseSet of owners plus a dense
// array of T kept in the same order, so components[i] belongs to entities()[i] and a
// one-component view is a plain loop over two arrays.
//
// T must be move-constructible and move-assignable (erase moves the last component
// into the hole). References to components are invalidated by any insert or erase
// in the same pool; views prevent that while they iterate by locking the pool.
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/core/ecs/component_type.hpp"
#include "engine/core/ecs/sparse_set.hpp"

namespace engine::ecs {

template <class T>
class Pool final : public SparseSet {
    static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "Pool<T>: T must be a plain object type");
    static_assert(std::is_move_constructible_v<T> && std::is_move_assignable_v<T>,
                  "ECS components must be move-constructible and move-assignable");

public:
    Pool() noexcept : SparseSet(componentTypeName<T>()) {}

    // Adds a T built from `args` for `e`, which must not be a member.
    // Aggregates work too: emplace(e, 1.f, 2.f) builds T{1.f, 2.f}.
    template <class... Args>
    T& emplace(Entity e, Args&&... args) {
        components_.emplace_back(std::forward<Args>(args)...);
        try {
            insert(e);
        } catch (...) {
            components_.pop_back();  // keep the two arrays the same length
            throw;
        }
        return components_.back();
    }

    T& componentAt(std::size_t position) noexcept { return components_[position]; }
    const T& componentAt(std::size_t position) const noexcept { return components_[position]; }
    T* componentData() noexcept { return components_.data(); }

private:
    // Hide the entity-only insert: a member without a component would desync the arrays.
    using SparseSet::insert;

    void eraseComponentAt(std::size_t position) override {
        if (position + 1 != components_.size()) components_[position] = std::move(components_.back());
        components_.pop_back();
    }

    std::vector<T> components_;
};

}  // namespace engine::ecs
