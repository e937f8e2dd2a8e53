// SPDX-License-Identifier: MIT
#pragma once
// SparseSet: the set of entities that own something, as two arrays.
//   dense:  the member entities, packed, in no particular order (iteration walks this)
//   sparse: entity index -> position in dense, in 4096-entry pages allocated on first
//           use, so a set holding a few entities with huge indices stays small.
// contains/find/insert/erase are O(1); erase swaps the last member into the hole.
//
// Every component Pool is a SparseSet; the Registry also keeps one for its live
// entities. Views lock the sets they walk (see IterationLock): while locked,
// insert/erase throw engine::Error, because they would move members under the
// iterator and leave the references it handed out dangling.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "engine/core/ecs/entity.hpp"

namespace engine::ecs {

class SparseSet {
public:
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);

    // `name` is used in error messages and must outlive the set (a literal or a
    // componentTypeName()).
    explicit SparseSet(std::string_view name) noexcept : name_(name) {}
    virtual ~SparseSet() = default;
    SparseSet(const SparseSet&) = delete;
    SparseSet& operator=(const SparseSet&) = delete;

    std::string_view name() const noexcept { return name_; }
    std::size_t size() const noexcept { return dense_.size(); }
    bool empty() const noexcept { return dense_.empty(); }
    std::span<const Entity> entities() const noexcept { return dense_; }
    const Entity* entityData() const noexcept { return dense_.data(); }

    // Dense position of `e`, or npos. The whole handle is compared, so a stale handle
    // whose index now belongs to someone else is not found.
    std::size_t find(Entity e) const noexcept {
        const std::uint32_t index = e.index();
        const std::size_t page = index >> kPageBits;
        if (page >= pages_.size() || !pages_[page]) return npos;
        const std::uint32_t position = pages_[page][index & kPageMask];
        if (position == kAbsent || dense_[position] != e) return npos;
        return position;
    }
    // As find(e), trying position `hint` first: when several sets received their
    // members in the same order their dense arrays line up, and a multi-component
    // view then walks them all sequentially instead of hopping through the pages.
    std::size_t find(Entity e, std::size_t hint) const noexcept {
        if (hint < dense_.size() && dense_[hint] == e) return hint;
        return find(e);
    }
    bool contains(Entity e) const noexcept { return find(e) != npos; }

    // Appends `e`, which must not be a member; returns its dense position.
    // Throws engine::Error while locked.
    std::size_t insert(Entity e);
    // Removes `e`; false if it was not a member. Throws engine::Error while locked.
    bool erase(Entity e);

    // Structural lock, counted so nested and copied iterators compose.
    bool locked() const noexcept { return lockCount_ != 0; }
    void lock() noexcept { ++lockCount_; }
    void unlock() noexcept { --lockCount_; }

protected:
    // Pools mirror the dense array: erase() calls this before it moves the last
    // member into `position`, so the pool can do the same with its components.
    virtual void eraseComponentAt(std::size_t /*position*/) {}

private:
    static constexpr unsigned kPageBits = 12;
    static constexpr std::size_t kPageSize = std::size_t{1} << kPageBits;
    static constexpr std::uint32_t kPageMask = kPageSize - 1;
    static constexpr std::uint32_t kAbsent = ~std::uint32_t{0};

    std::uint32_t& sparseEntry(std::uint32_t index);  // allocates the page on demand
    [[noreturn]] void throwLocked(std::string_view action, Entity e) const;

    std::string_view name_;
    std::vector<Entity> dense_;
    std::vector<std::unique_ptr<std::uint32_t[]>> pages_;
    std::uint32_t lockCount_ = 0;
};

}  // namespace engine::ecs
