// SPDX-License-Identifier: MIT
#pragma once
// Registry: owns the entities and one Pool per component type.
//
// Contracts
// - Entities are index + generation handles (entity.hpp). destroy() bumps the slot's
//   generation, so every old handle is stale: alive() is false, has()/tryGet() say
//   "absent", and get/add/remove/destroy throw engine::Error naming the handle. A slot
//   whose generation would wrap is retired instead of reused.
// - Mutators throw engine::Error on misuse (stale handle, duplicate add, missing get)
//   with a message that names the entity and the component type; queries never throw.
// - Structural changes during a view's iteration are refused with engine::Error (see
//   view.hpp for exactly which); record them in a CommandBuffer instead.
// - References returned by add/get stay valid until the next add or remove of the
//   same component type (pools are dense arrays).
// - Not thread-safe: one thread at a time uses a registry and its command buffers.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/core/ecs/component_type.hpp"
#include "engine/core/ecs/entity.hpp"
#include "engine/core/ecs/pool.hpp"
#include "engine/core/ecs/sparse_set.hpp"
#include "engine/core/ecs/view.hpp"
#include "engine/core/error.hpp"

namespace engine::ecs {

class CommandBuffer;

class Registry {
public:
    Registry() = default;
    ~Registry();
    // Views and command buffers point into the registry: it stays where it was made.
    Registry(const Registry&) = delete;
    Registry& operator=(const Registry&) = delete;

    // A new live entity with no components. Reuses a free slot (with its next
    // generation) when there is one. Throws when the index space is exhausted.
    Entity create();
    // Removes all of e's components and makes every handle to it stale.
    void destroy(Entity e);
    bool alive(Entity e) const noexcept { return live_.contains(e); }
    std::size_t size() const noexcept { return live_.size(); }
    // Slots taken out of service because their generation would have wrapped.
    std::size_t retiredSlots() const noexcept { return retiredSlots_; }

    // Adds a T built from `args`; throws if e already has one.
    template <class T, class... Args>
    T& add(Entity e, Args&&... args) {
        Pool<T>& pool = assure<T>();
        requireAlive(e, "add", pool.name());
        if (pool.contains(e)) throwFor(e, "add", pool.name(), "it already has one");
        refuseIfLocked(pool, e, "add");
        return pool.emplace(e, std::forward<Args>(args)...);
    }
    // Adds a T, or assigns T(args...) to the existing one (not a structural change then).
    template <class T, class... Args>
    T& addOrReplace(Entity e, Args&&... args) {
        Pool<T>& pool = assure<T>();
        requireAlive(e, "add or replace", pool.name());
        if (const std::size_t position = pool.find(e); position != SparseSet::npos)
            return pool.componentAt(position) = T(std::forward<Args>(args)...);
        refuseIfLocked(pool, e, "add");
        return pool.emplace(e, std::forward<Args>(args)...);
    }
    // Removes e's T; false if it had none.
    template <class T>
    bool remove(Entity e) {
        Pool<T>* pool = poolIfAny<T>();
        requireAlive(e, "remove", componentTypeName<T>());
        if (!pool || !pool->contains(e)) return false;
        refuseIfLocked(*pool, e, "remove");
        return pool->erase(e);
    }

    template <class T>
    bool has(Entity e) const noexcept {
        const Pool<T>* pool = poolIfAny<T>();
        return pool && pool->contains(e);  // the pool compares generations: stale -> false
    }
    // e's T; throws if e is stale or has none.
    template <class T>
    T& get(Entity e) {
        Pool<T>* pool = poolIfAny<T>();
        const std::size_t position = pool ? pool->find(e) : SparseSet::npos;
        if (position == SparseSet::npos) [[unlikely]] {
            requireAlive(e, "get", componentTypeName<T>());
            throwFor(e, "get", componentTypeName<T>(), "it has none");
        }
        return pool->componentAt(position);
    }
    template <class T>
    const T& get(Entity e) const {
        return const_cast<Registry*>(this)->get<T>(e);  // same lookup; the result is re-constified
    }
    // e's T, or nullptr if e is stale or has none.
    template <class T>
    T* tryGet(Entity e) noexcept {
        Pool<T>* pool = poolIfAny<T>();
        const std::size_t position = pool ? pool->find(e) : SparseSet::npos;
        return position == SparseSet::npos ? nullptr : &pool->componentAt(position);
    }
    // How many entities have a T.
    template <class T>
    std::size_t count() const noexcept {
        const Pool<T>* pool = poolIfAny<T>();
        return pool ? pool->size() : 0;
    }

    // Entities having every T in Ts (const T gives read-only access); view<>() is
    // every live entity. See view.hpp for the iteration contract.
    template <class... Ts>
    View<Ts...> view() {
        return View<Ts...>(live_, assure<std::remove_const_t<Ts>>()...);
    }

private:
    friend class CommandBuffer;

    // CommandBuffer::create() support: a reserved handle owns its slot but is not
    // alive until committed; released reservations bump the generation like destroy().
    Entity reserve();
    void commitReserved(Entity e);
    void releaseReserved(Entity e);
    bool reserved(Entity e) const noexcept;

    template <class T>
    Pool<T>& assure() {
        static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "component types are plain object types");
        const ComponentTypeId id = componentTypeId<T>();
        if (id >= pools_.size()) pools_.resize(id + 1);
        if (!pools_[id]) pools_[id] = std::make_unique<Pool<T>>();
        return static_cast<Pool<T>&>(*pools_[id]);
    }
    template <class T>
    Pool<T>* poolIfAny() const noexcept {
        const ComponentTypeId id = componentTypeId<T>();
        return id < pools_.size() ? static_cast<Pool<T>*>(pools_[id].get()) : nullptr;
    }

    Entity allocateSlot();
    void freeSlot(Entity e);  // bumps the generation, or retires the slot
    // Throws explaining why e is not alive (null, never issued, stale, retired, reserved).
    void requireAlive(Entity e, std::string_view action, std::string_view component) const;
    void refuseIfLocked(const SparseSet& set, Entity e, std::string_view action) const;
    [[noreturn]] static void throwFor(Entity e, std::string_view action, std::string_view component,
                                      std::string_view why);

    struct Slot {
        enum class State : std::uint8_t { Free, Reserved, Live, Retired };
        std::uint32_t generation = 0;  // of the handle it holds, or will issue next when Free
        State state = State::Free;
    };

    SparseSet live_{"live entities"};
    std::vector<Slot> slots_;                        // by entity index
    std::vector<std::uint32_t> freeSlots_;           // LIFO: a recently freed slot is still in cache
    std::vector<std::unique_ptr<SparseSet>> pools_;  // by ComponentTypeId; null = never used here
    std::size_t retiredSlots_ = 0;
};

}  // namespace engine::ecs
