// SPDX-License-Identifier: MIT
#pragma once
// IterationLock: holds a structural lock on the sets a view walks, for as long as an
// iterator (or an each() call) is alive. Copies lock again, so a range-for, which
// keeps its begin iterator until the loop ends, locks exactly for the loop's duration,
// and break / return / exceptions unlock through the destructor.
#include <array>
#include <cstddef>
#include <utility>

#include "engine/core/ecs/sparse_set.hpp"

namespace engine::ecs {

template <std::size_t N>
class IterationLock {
public:
    IterationLock() noexcept = default;  // holds nothing
    explicit IterationLock(const std::array<SparseSet*, N>& sets) noexcept : sets_(sets) { acquire(); }
    IterationLock(const IterationLock& other) noexcept : sets_(other.sets_) { acquire(); }
    IterationLock(IterationLock&& other) noexcept : sets_(std::exchange(other.sets_, {})) {}
    IterationLock& operator=(IterationLock other) noexcept {
        std::swap(sets_, other.sets_);
        return *this;
    }
    ~IterationLock() { release(); }

private:
    void acquire() noexcept {
        for (SparseSet* set : sets_)
            if (set) set->lock();
    }
    void release() noexcept {
        for (SparseSet* set : sets_)
            if (set) set->unlock();
    }

    std::array<SparseSet*, N> sets_{};
};

}  // namespace engine::ecs
